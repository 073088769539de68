"""What raylab's Python tools (tools/*.py) share: where the repository and the raylab binary are, and running
raylab with errors that say what to do.

The tools run with the project's virtual environment, which `tools/setup.sh render` (or `test`) creates:
    .venv/bin/python tools/brdf_plot.py --help
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
DEFAULT_RAYLAB = REPO / "build" / "release" / "raylab"


class ToolError(Exception):
    """A failure the user can act on; main() prints it and exits 1."""


def venv_hint(missing: str) -> str:
    return (f"the Python package '{missing}' is missing: run tools/setup.sh render (it installs the pinned "
            f"tools/requirements.txt into .venv), then run this script with .venv/bin/python")


def point_mitsuba_at_libllvm() -> None:
    """Mitsuba's LLVM backend needs libLLVM >= 16; Debian bookworm's libllvm19 (tools/setup.sh) provides it. Call
    before importing mitsuba."""
    libllvm = Path("/usr/lib/x86_64-linux-gnu/libLLVM-19.so")
    if libllvm.exists():
        os.environ.setdefault("DRJIT_LIBLLVM_PATH", str(libllvm))


def add_raylab_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--raylab", type=Path, default=DEFAULT_RAYLAB, metavar="PATH",
                        help=f"the raylab executable (default: {DEFAULT_RAYLAB.relative_to(REPO)})")


def check_raylab(path: Path) -> Path:
    if not path.is_file() or not os.access(path, os.X_OK):
        raise ToolError(f"no raylab executable at {path}: build it (cmake --preset release && cmake --build "
                        f"--preset release, or tools/setup.sh render) or pass --raylab PATH")
    return path.resolve()


def run_raylab(raylab: Path, args: list[str], what: str) -> subprocess.CompletedProcess:
    """Runs raylab; a non-zero exit raises ToolError with the command and raylab's own message."""
    command = [str(raylab), *args]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        lines = (result.stderr.strip() or result.stdout.strip()).splitlines()
        shown = lines if len(lines) <= 4 else [*lines[:3], f"... ({len(lines) - 4} more lines)", lines[-1]]
        raise ToolError(f"{what} failed (exit {result.returncode}): {' '.join(command)}\n  " + "\n  ".join(shown))
    return result


def registered_models(raylab: Path) -> list[dict]:
    """The BRDF model registry as `raylab brdf models --json` prints it: tools keep no model lists of their own."""
    return json.loads(run_raylab(raylab, ["brdf", "models", "--json"], "listing the BRDF models").stdout)


def reads_file(model: dict) -> bool:
    """A model whose data comes from a file (measured): figures give it one, or leave it out."""
    return any(param["role"] in ("file", "network") for param in model["params"])


def model_notes(model: dict) -> dict:
    """What a model's GLSL header says for the tools, parsed as the build parses it (tools/cmake/brdf_registry.py):
    `look` (the parameter list scenes show it with, or None), `figures` ([{name, params, options}]) and
    `sweep_scenes` ([{param, start, stop, log, set, statistic, trend, why}])."""
    if str(REPO / "tools" / "cmake") not in sys.path:
        sys.path.insert(0, str(REPO / "tools" / "cmake"))
    import brdf_registry  # noqa: E402 (the build's parser of the headers, standard library only)
    return brdf_registry.parse_model(model["name"], "", "", str(REPO / model["glsl"]))


def param_value(text: str) -> float | int | str | list:
    """A value of a header's parameter list as extras.raylab holds it: r/g/b a list, 60 an int, 0.3 a float, Au a
    name (a preset)."""
    if "/" in text:
        return [param_value(channel) for channel in text.split("/")]
    try:
        return int(text) if text.lstrip("-").isdigit() else float(text)
    except ValueError:
        return text


def look_material(model: dict) -> dict:
    """The extras.raylab material a scene shows `model` with: its header's `look:` line, or generic_material."""
    look = model_notes(model)["look"]
    if look is None:
        return generic_material(model)
    rgb = {param["name"] for param in model["params"] if param["type"] == "rgb"}
    material = {"model": model["name"]}
    for item in filter(None, (part.strip() for part in look.split(","))):
        name, value = (part.strip() for part in item.split("="))
        material[name] = param_value(value)
        if name in rgb and not isinstance(material[name], list):
            material[name] = [material[name]] * 3
    return material


def generic_material(model: dict) -> dict:
    """An extras.raylab material of a registered model for a figure without a hand-picked look for it: its
    defaults, with a warm diffuse colour and grey other colours."""
    material = {"model": model["name"]}
    for param in model["params"]:
        if param["type"] == "rgb":
            material[param["name"]] = [0.6, 0.35, 0.25] if param["role"] == "diffuse" else [0.5, 0.5, 0.5]
    return material


def save_figure(figure, path: Path) -> None:
    """Writes a matplotlib figure as a PNG through a temporary file and a rename: an interrupted run never leaves
    a half-written image in docs/."""
    path.parent.mkdir(parents=True, exist_ok=True)
    temporary = path.with_name(path.name + ".tmp.png")
    figure.savefig(temporary)
    temporary.replace(path)


def run_main(main) -> None:
    """Calls main(), turning ToolError into a message and exit code 1."""
    try:
        main()
    except ToolError as error:
        print(f"{Path(sys.argv[0]).name}: error: {error}", file=sys.stderr)
        sys.exit(1)
