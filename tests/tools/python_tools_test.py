"""ctest python_tools_test: runs raylab's Python tools (BRDF plot, speed against error, sampling study, image
difference) as a user would, in a tiny mode, and checks what they write. Standard library only, run by the
system python3; the tools themselves run with .venv/bin/python.

    python_tools_test.py RAYLAB SOURCE_DIR WORK_DIR
"""
import csv
import json
import math
import shutil
import subprocess
import sys
import time
from pathlib import Path

SPEED_COLUMNS = ["scene", "variant", "spp", "time_s", "per_sample_s", "cpu_per_sample_s", "run_per_sample_s",
                 "run_cpu_per_sample_s", "first_sample_s", "rmse", "relmse", "flip"]
VARIANTS = {"baseline", "schlick", "depth2", "all_features"}


class Failure(Exception):
    pass


def check(condition: bool, message: str) -> None:
    if not condition:
        raise Failure(message)


def run(command: list) -> None:
    start = time.monotonic()
    printed = " ".join(str(part) for part in command)
    result = subprocess.run([str(part) for part in command], capture_output=True, text=True)
    print(f"$ {printed}\n{result.stdout}{result.stderr}({time.monotonic() - start:.1f} s)", flush=True)
    check(result.returncode == 0, f"exit code {result.returncode}: {printed}")


def check_png(path: Path, min_bytes: int) -> None:
    check(path.is_file(), f"{path} was not written")
    data = path.read_bytes()
    check(data[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG file")
    check(min_bytes <= len(data) <= 150 * 1024, f"{path}: {len(data)} bytes, expected {min_bytes} to 150 KB")


def brdf_plot(python: Path, source: Path, raylab: Path, work: Path) -> None:
    out = work / "phong.png"
    run([python, source / "tools" / "brdf_plot.py", "--model", "phong", "--params", "rho_d=0;rho_s=1;s=50",
         "--out", out, "--raylab", raylab, "--gpu-samples", "16384"])
    check_png(out, 20 * 1024)


def speed_vs_error(python: Path, source: Path, raylab: Path, work: Path) -> None:
    out = work / "speed_vs_error"
    run([python, source / "tools" / "speed_vs_error.py", "--quick", "--fresh-reference", "--raylab", raylab,
         "--out", out])
    table = out / "speed_vs_error.csv"
    check(table.is_file(), f"{table} was not written")
    with table.open(newline="") as file:
        reader = csv.DictReader(file)
        check(reader.fieldnames == SPEED_COLUMNS, f"{table}: columns {reader.fieldnames}, expected {SPEED_COLUMNS}")
        rows = list(reader)
    check({r["variant"] for r in rows} == VARIANTS, f"{table}: variants {sorted({r['variant'] for r in rows})}")
    check(len(rows) == 2 * len(VARIANTS), f"{table}: {len(rows)} rows, expected two points per variant")
    for row in rows:
        for column in ["time_s", "per_sample_s", "cpu_per_sample_s", "first_sample_s", "rmse", "relmse", "flip"]:
            value = float(row[column])
            check(math.isfinite(value) and value > 0.0, f"{table}: {row['variant']} at {row['spp']} spp: "
                                                        f"{column} = {row[column]}, expected finite and positive")
        check(float(row["flip"]) < 1.0, f"{table}: FLIP {row['flip']} is not in (0, 1)")
    for variant in VARIANTS:
        points = sorted((r for r in rows if r["variant"] == variant), key=lambda r: int(r["spp"]))
        check(float(points[0]["time_s"]) < float(points[1]["time_s"]), f"{variant}: time does not grow with spp")
    baseline = sorted((r for r in rows if r["variant"] == "baseline"), key=lambda r: int(r["spp"]))
    for metric in ["rmse", "relmse", "flip"]:
        low, high = float(baseline[0][metric]), float(baseline[1][metric])
        check(high < low, f"baseline {metric} does not fall with spp: {low} at {baseline[0]['spp']} spp, "
                          f"{high} at {baseline[1]['spp']} spp")
    # 1 -> 16 spp: an unbiased estimator's RMSE falls about 4x; allow the reference's own noise.
    ratio = float(baseline[0]["rmse"]) / float(baseline[1]["rmse"])
    check(2.5 < ratio < 6.0, f"baseline RMSE falls {ratio:.2f}x from 1 to 16 spp, expected about 4x")
    check_png(out / "speed_vs_error_cornell_box.png", 10 * 1024)
    check((out / "summary.md").is_file(), f"{out / 'summary.md'} was not written")


def sampling_study(python: Path, source: Path, raylab: Path, work: Path) -> None:
    out = work / "sampling_study"
    run([python, source / "tools" / "sampling_study.py", "--quick", "--raylab", raylab, "--out", out])
    table = out / "sampling.csv"
    check(table.is_file(), f"{table} was not written")
    with table.open(newline="") as file:
        rows = list(csv.DictReader(file))
    check({r["strategy"] for r in rows} == {"mis", "bsdf", "light"}, f"{table}: strategies {rows[:1]}")
    check(len(rows) == 2 * 3 * 4, f"{table}: {len(rows)} rows, expected 2 models x 3 strategies x 4 spp")
    for model in {r["model"] for r in rows}:
        mis = sorted((r for r in rows if r["model"] == model and r["strategy"] == "mis"), key=lambda r: int(r["spp"]))
        first, last = float(mis[0]["relmse"]), float(mis[-1]["relmse"])
        # 1 -> 8 spp: an unbiased estimator's relMSE falls about 8x (more with Sobol points).
        check(math.isfinite(first) and last < first / 3.0, f"{model}: MIS relMSE {first} at 1 spp, {last} at 8 spp")
    check_png(out / "sampling_study.png", 10 * 1024)


def image_diff(python: Path, source: Path, raylab: Path, work: Path) -> None:
    """The viewer's two sides, rendered offscreen: a material against itself is 0 in every figure, against
    another model it is not."""
    scene = source / "assets" / "scenes" / "minimal.gltf"
    images = {}
    for name, material in (("same", "red plastic=cooktorrance:rho_d=0.6/0.1/0.1,rho_s=1,m=0.2,eta=1.5"),
                           ("ward", "red plastic=ward:alpha_x=0.3,alpha_y=0.1")):
        images[name] = work / f"diff_{name}.exr"
        run([raylab, "render", scene, "--width", "64", "--height", "48", "--spp", "2", "--no-png",
             "--out", images[name], "--material", material])
    plain = work / "diff_plain.exr"
    run([raylab, "render", scene, "--width", "64", "--height", "48", "--spp", "2", "--no-png", "--out", plain])
    for name, expect_zero in (("same", True), ("ward", False)):
        figures_path = work / f"diff_{name}.json"
        run([python, source / "tools" / "image_diff.py", plain, images[name], "--json", figures_path])
        figures = json.loads(figures_path.read_text())
        check(set(figures) == {"mean_abs", "max_abs", "rmse", "relmse", "flip"}, f"{figures_path}: {figures}")
        if expect_zero:
            check(all(value == 0.0 for value in figures.values()), f"the same material differs: {figures}")
        else:
            check(figures["mean_abs"] > 1e-3 and 0.0 < figures["flip"] < 1.0, f"two models look alike: {figures}")


def layered_cost(python: Path, source: Path, raylab: Path, work: Path) -> None:
    # Its renders compile openpbr's every-layer kernel (about 40 s cold): here its help and its refusal of bad
    # options, which need no render.
    result = subprocess.run([str(python), str(source / "tools" / "layered_cost.py"), "--help"], capture_output=True,
                            text=True)
    check(result.returncode == 0 and "showcase_layered" in result.stdout, f"layered_cost.py --help: {result.stderr}")
    result = subprocess.run([str(python), str(source / "tools" / "layered_cost.py"), "--spp", "1", "--raylab",
                             str(raylab)], capture_output=True, text=True)
    check(result.returncode == 1 and "--spp must be 2 or more" in result.stderr,
          f"layered_cost.py --spp 1: exit {result.returncode}, {result.stderr}")


def denoise_study(python: Path, source: Path, raylab: Path, work: Path) -> None:
    # The Python module this build made, through the venv's raylab.pth (tools/setup.sh).
    out = work / "denoise_study"
    run([python, source / "tools" / "denoise_study.py", "--quick", "--out", out])
    with open(out / "denoise_study.csv") as file:
        rows = list(csv.DictReader(file))
    check(len(rows) == 2, f"denoise_study.csv: {len(rows)} rows, expected 2 (1 and 4 spp)")
    for row in rows:
        raw, denoised = float(row["raw_relmse"]), float(row["denoised_relmse"])
        check(0.0 < denoised < raw, f"denoised error {denoised} is not below the raw {raw} at {row['spp']} spp")
        check(float(row["denoised_cpu_s"]) > float(row["raw_cpu_s"]) > 0.0, f"costs out of order: {row}")
    check_png(out / "denoise_cornell_box_area.png", 10 * 1024)
    check_png(out / "crops_cornell_box_area.png", 5 * 1024)


def guiding_study(python: Path, source: Path, work: Path) -> None:
    out = work / "guiding_study"
    run([python, source / "tools" / "guiding_study.py", "--quick", "--out", out])
    with open(out / "guiding_study.csv") as file:
        rows = list(csv.DictReader(file))
    check(sorted({row["mode"] for row in rows}) == ["auto", "off", "on"], f"guiding_study.csv modes: {rows}")
    for row in rows:
        check(float(row["relmse"]) > 0.0 and float(row["cpu_s"]) > 0.0, f"guiding_study.csv: {row}")
    check("| glossy_room | on |" in (out / "summary.md").read_text(), "summary.md lacks the guided row")
    check_png(out / "guiding_glossy_room.png", 10 * 1024)


def main() -> None:
    raylab, source, work = (Path(arg).resolve() for arg in sys.argv[1:4])
    python = source / ".venv" / "bin" / "python"
    if not python.exists():
        raise Failure(f"{python} is missing: run tools/setup.sh render (or test), which creates .venv with the "
                      f"pinned Python tools of tools/requirements.txt")
    check(raylab.is_file(), f"{raylab} is missing: build the raylab target")
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    brdf_plot(python, source, raylab, work)
    speed_vs_error(python, source, raylab, work)
    sampling_study(python, source, raylab, work)
    image_diff(python, source, raylab, work)
    layered_cost(python, source, raylab, work)
    denoise_study(python, source, raylab, work)
    guiding_study(python, source, work)
    print("python_tools_test: passed")


if __name__ == "__main__":
    try:
        main()
    except Failure as failure:
        print(f"python_tools_test: FAILED: {failure}")
        sys.exit(1)
