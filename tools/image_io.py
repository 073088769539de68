"""Reading raylab's linear OpenEXR images into numpy, for the Python tools."""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import OpenEXR

from raylab_tools import ToolError


def read_exr(path: Path) -> np.ndarray:
    """The linear R, G, B channels, H x W x 3, float64."""
    with OpenEXR.File(str(path)) as file:  # the channels are released when the file closes: copy them first
        channels = file.channels()
        packed = next((name for name in ("RGBA", "RGB") if name in channels), None)
        if packed is not None:
            image = np.array(channels[packed].pixels[..., :3], dtype=np.float64)
        elif all(c in channels for c in "RGB"):
            image = np.stack([np.array(channels[c].pixels, dtype=np.float64) for c in "RGB"], axis=-1)
        else:
            raise ToolError(f"{path}: expected R, G, B channels, found {', '.join(channels) or 'none'}")
    bad = int(np.count_nonzero(~np.isfinite(image)))
    if bad:
        print(f"warning: {path} has {bad} NaN or infinite values: its errors will be NaN", file=sys.stderr)
    return image
