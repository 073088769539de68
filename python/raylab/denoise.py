"""raylab.denoise: Intel's Open Image Denoise on an image raylab rendered (issue 39, docs/python.md).

OIDN comes from the PyPI package `pyoidn` (pinned in tools/requirements.txt, installed into .venv by
tools/setup.sh), which bundles the library and its CPU device; it is imported at the first call, so that nothing
else in raylab needs it. The colour is HDR radiance (OIDN's `hdr` mode); albedo and normal, when given, are the
auxiliary images OIDN uses to keep texture and geometric detail, expected noise-free (`clean_aux`: no prefiltering,
which would cost about five times the denoise itself).
"""
import numpy as np

from ._raylab import render_options as _render_options

# Declared once in the engine (util/render_options.h, kDenoiseQualityOption).
_QUALITIES = tuple(_render_options["denoise_quality"]["values"])
_INSTALL = ("raylab.denoise needs Open Image Denoise from the PyPI package pyoidn: run tools/setup.sh, or "
            ".venv/bin/pip install -r tools/requirements.txt")


def _rgb(image, name, shape=None):
    """`image` as a C-contiguous float32 (height, width, 3) array of finite values; an RGBA image (Renderer.image(),
    Renderer.render()) loses its fourth channel."""
    try:
        array = np.asarray(image, dtype=np.float32)
    except (TypeError, ValueError) as error:
        raise ValueError(f"raylab.denoise: {name} is not an image of numbers ({error})") from None
    if array.ndim != 3 or array.shape[2] not in (3, 4) or array.shape[0] == 0 or array.shape[1] == 0:
        raise ValueError(f"raylab.denoise: {name} has shape {array.shape}; expected (height, width, 3) or "
                         "(height, width, 4), neither dimension 0")
    array = np.ascontiguousarray(array[:, :, :3])
    if shape is not None and array.shape != shape:
        raise ValueError(f"raylab.denoise: {name} has shape {array.shape[:2]}, the colour {shape[:2]}")
    if not np.isfinite(array).all():
        bad = np.argwhere(~np.isfinite(array))[0]
        raise ValueError(f"raylab.denoise: {name} is not finite at row {bad[0]}, column {bad[1]}")
    return array


def denoise(color, albedo=None, normal=None, quality=_render_options["denoise_quality"]["default"]):
    """The denoised colour, float32 (height, width, 3).

    color: radiance (height, width, 3 or 4), as Renderer.render() returns it. albedo, normal: the auxiliary images of
    the same size, noise-free (both or albedo alone, as OIDN takes them), as Renderer.auxiliary() returns them.
    quality: "fast", "balanced" (the default, as `raylab render --denoise`) or "high".
    Raises ValueError on bad input and RuntimeError when Open Image Denoise is missing or fails.
    """
    if not isinstance(quality, str) or quality not in _QUALITIES:
        raise ValueError(f"raylab.denoise: quality {quality!r} is not one of {', '.join(_QUALITIES)}")
    if normal is not None and albedo is None:
        raise ValueError("raylab.denoise: a normal image needs an albedo image too (Open Image Denoise's rule)")
    colour = _rgb(color, "color")
    aux_albedo = None if albedo is None else _rgb(albedo, "albedo", colour.shape)
    aux_normal = None if normal is None else _rgb(normal, "normal", colour.shape)
    try:
        import pyoidn
    except ImportError:
        raise RuntimeError(_INSTALL) from None
    try:
        result = pyoidn.denoise(colour, aux_albedo, aux_normal, hdr=True, clean_aux=albedo is not None,
                                quality=quality)
    except Exception as error:  # OIDN's own errors: a device it cannot create, memory
        raise RuntimeError(f"raylab.denoise: Open Image Denoise failed: {error}") from None
    result = np.asarray(result, dtype=np.float32).reshape(colour.shape)
    if not np.isfinite(result).all():
        raise RuntimeError("raylab.denoise: Open Image Denoise returned non-finite values")
    return result


def _load():
    """Imports pyoidn now (Renderer.render(denoise=True) calls it before rendering): RuntimeError saying how to
    install it when it is missing."""
    try:
        import pyoidn  # noqa: F401
    except ImportError:
        raise RuntimeError(_INSTALL) from None


def _denoised_rgba(color, albedo, normal, quality):
    """Renderer.render(denoise=True)'s result: the denoised colour with the alpha channel the raw image has."""
    rgb = denoise(color, albedo, normal, quality)
    return np.concatenate([rgb, np.ones(rgb.shape[:2] + (1,), dtype=np.float32)], axis=2)
