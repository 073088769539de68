"""The Python module off the documented path: empty arrays, threads, special files, damaged EXR files, values that
would overflow the image, NumPy scalars and paths. Each test is one class of the defects of issue 21 and fails on
the code before its fix."""
import os
import shutil
import struct
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import OpenEXR
import pytest

import raylab

BACKENDS = ["cpu", "gpu"]


@pytest.fixture(scope="module")
def minimal(source_dir) -> Path:
    return source_dir / "assets" / "scenes" / "minimal.gltf"


# Empty batches: the result is empty, of the documented shape, on both backends (the interpreter used to crash).
@pytest.mark.parametrize("backend", BACKENDS)
def test_empty_batches_give_empty_results(backend):
    empty = np.zeros((0, 3), np.float32)
    assert raylab.brdf.eval("phong", wi=empty, wo=empty, backend=backend).shape == (0, 3)
    assert raylab.brdf.eval("phong", wi=empty, wo=[0, 0, 1], backend=backend).shape == (0, 3)
    assert raylab.brdf.pdf("ward", wi=[0, 0, 1], wo=empty, backend=backend).shape == (0,)
    drawn = raylab.brdf.sample("lambert", wo=[0, 0, 1], u=empty, backend=backend)
    assert drawn["wi"].shape == (0, 3) and drawn["f"].shape == (0, 3) and drawn["pdf"].shape == (0,)
    with pytest.raises(ValueError, match="rows"):
        raylab.brdf.eval("phong", wi=empty, wo=np.zeros((2, 3), np.float32), backend=backend)


# brdf.sample takes one wo per row, and gives what one call per wo gives.
@pytest.mark.parametrize("backend", BACKENDS)
def test_sample_takes_one_outgoing_direction_per_row(backend):
    wo = np.array([[0, 0, 1], [0.6, 0, 0.8], [0.6, 0, 0.8], [0, 0.8, 0.6]], np.float32)
    u = np.random.default_rng(3).random((4, 3), dtype=np.float32) * 0.999
    together = raylab.brdf.sample("ward", {"alpha_x": 0.3}, wo=wo, u=u, backend=backend)
    for i in range(4):
        alone = raylab.brdf.sample("ward", {"alpha_x": 0.3}, wo=wo[i], u=u[i:i + 1], backend=backend)
        np.testing.assert_array_equal(together["wi"][i], alone["wi"][0])
        np.testing.assert_array_equal(together["pdf"][i], alone["pdf"][0])


# The first NumPy-returning call from two threads at once used to deadlock in NumPy's lazy initialisation. A
# fresh interpreter is needed (the module initialises once), and a timeout turns a hang into a failure.
def test_threads_whose_first_call_returns_an_array_do_not_deadlock(work):
    image = work / "tiny.exr"
    raylab.write_exr(image, np.ones((2, 3, 4), np.float32))
    script = textwrap.dedent(f"""
        import threading, raylab
        results = []
        def read(): results.append(raylab.read_exr({str(image)!r}).shape)
        def evaluate(): results.append(raylab.brdf.eval("phong", wi=[0, 0, 1], wo=[0, 0, 1], backend="cpu").shape)
        threads = [threading.Thread(target=f) for f in (read, evaluate, read, evaluate)]
        for t in threads: t.start()
        for t in threads: t.join()
        print(len(results))
    """)
    for _ in range(3):
        done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=60)
        assert done.returncode == 0 and done.stdout.strip() == "4", done.stderr


# Special files are refused by what they are, with the built-in exception that fits, never read.
def test_special_files_are_refused_by_every_reader(work):
    fifo = work / "pipe.exr"
    os.mkfifo(fifo)
    for reader in (raylab.read_exr, raylab.read_png, raylab.Scene.load):
        with pytest.raises(ValueError, match="not a regular file"):
            reader(str(fifo))
        with pytest.raises(ValueError, match="not a regular file"):
            reader("/dev/zero")
        with pytest.raises(IsADirectoryError, match="is a directory"):
            reader(work)
        with pytest.raises(FileNotFoundError, match="no such file"):
            reader(work / "missing.exr")


def _exr(path, channels, **header):
    OpenEXR.File({"compression": OpenEXR.NO_COMPRESSION, **header}, channels).write(str(path))
    return path


def _patched_windows(source: Path, target: Path, box):
    """`source` with its data and display windows replaced by `box` (x0, y0, x1, y1) and nothing else changed."""
    data = bytearray(source.read_bytes())
    for name in (b"dataWindow\0box2i\0", b"displayWindow\0box2i\0"):
        at = data.find(name) + len(name) + 4
        struct.pack_into("<4i", data, at, *box)
    target.write_bytes(bytes(data))
    return target


# A header is believed only as far as the file's content can hold it, and a file must hold every pixel it
# declares: no allocation of what a small file claims, no rows of leftover memory.
@pytest.mark.parametrize("compression", [OpenEXR.NO_COMPRESSION, OpenEXR.ZIP_COMPRESSION, OpenEXR.PIZ_COMPRESSION])
def test_damaged_exr_files_are_refused(work, compression):
    pixels = np.full((16, 32, 3), 0.5, np.float32)
    good = work / "good.exr"
    OpenEXR.File({"compression": compression}, {"RGB": pixels}).write(str(good))
    np.testing.assert_array_equal(raylab.read_exr(good)[..., :3], pixels)
    taller = _patched_windows(good, work / "taller.exr", (0, 0, 31, 215))
    huge = _patched_windows(good, work / "huge.exr", (0, 0, 16383, 16383))
    truncated = work / "truncated.exr"
    truncated.write_bytes(good.read_bytes()[:-40])
    for damaged in (taller, huge, truncated):
        with pytest.raises(RuntimeError, match="OpenEXR"):
            raylab.read_exr(damaged)


# Windows enlarged past the stored rows: OpenEXR's classes used to fill the missing rows with heap memory (-1.7e38,
# NaN, different each run), which an environment would have lit a scene with. Every chunk is decoded before the
# pixels are read; the rows held are counted where the chunk tells (uncompressed, zlib).
@pytest.mark.parametrize("layout", ["raylab", "none", "piz", "tiled"])
def test_windows_that_claim_more_rows_than_the_file_holds_are_refused(work, minimal, layout):
    pixels = np.random.default_rng(7).random((8, 16, 3), np.float32)
    stored = work / f"{layout}.exr"
    if layout == "raylab":
        raylab.write_exr(stored, pixels)
    else:
        header = {"compression": {"none": OpenEXR.NO_COMPRESSION, "piz": OpenEXR.PIZ_COMPRESSION,
                                  "tiled": OpenEXR.ZIP_COMPRESSION}[layout]}
        if layout == "tiled":
            tiles = OpenEXR.TileDescription()
            tiles.xSize = tiles.ySize = 4
            header.update(type=OpenEXR.tiledimage, tiles=tiles)
        OpenEXR.File(header, {"RGB": pixels}).write(str(stored))
    np.testing.assert_array_equal(raylab.read_exr(stored)[..., :3], pixels)
    taller = _patched_windows(stored, work / f"{layout}_taller.exr", (0, 0, 15, 15))
    held = "8" if layout == "raylab" else "[0-8]"
    with pytest.raises(RuntimeError, match=f"holds {held} of its 16 rows"):
        raylab.read_exr(taller)
    with pytest.raises(ValueError, match=f"holds {held} of its 16 rows"):
        raylab.Scene.load(minimal, env=taller)


# The chunk check decodes with OpenEXR's core library, which does not decompress DWA in 3.1: every compression the
# C++ classes read still reads (Blender's environments are DWAB).
def test_every_exr_compression_reads(work):
    pixels = np.random.default_rng(3).random((20, 24, 3), np.float32)
    for name in ("NO", "RLE", "ZIPS", "ZIP", "PIZ", "PXR24", "B44", "B44A", "DWAA", "DWAB"):
        path = work / f"{name}.exr"
        OpenEXR.File({"compression": getattr(OpenEXR, f"{name}_COMPRESSION")}, {"RGB": pixels}).write(str(path))
        np.testing.assert_allclose(raylab.read_exr(path)[..., :3], pixels, atol=0.02, err_msg=name)


def test_exr_channels_are_read_correctly_or_refused_naming_them(work):
    grey = np.full((4, 6), 0.25, np.float32)
    red, green, blue = grey * 2, grey, grey / 2
    expected = np.stack([red, green, blue], axis=-1)
    np.testing.assert_array_equal(raylab.read_exr(_exr(work / "y.exr", {"Y": grey}))[..., :3],
                                  np.stack([grey] * 3, axis=-1))
    np.testing.assert_array_equal(
        raylab.read_exr(_exr(work / "layer.exr", {"diffuse.R": red, "diffuse.G": green, "diffuse.B": blue}))[..., :3],
        expected)
    np.testing.assert_array_equal(raylab.read_exr(_exr(work / "lower.exr", {"r": red, "g": green, "b": blue}))[..., :3],
                                  expected)
    with pytest.raises(RuntimeError, match="it has A;"):
        raylab.read_exr(_exr(work / "alpha.exr", {"A": grey}))
    with pytest.raises(RuntimeError, match="several RGB layers"):
        raylab.read_exr(_exr(work / "two.exr", {"a.R": red, "a.G": red, "a.B": red, "b.R": red, "b.G": red,
                                                "b.B": red}))
    parts = [OpenEXR.Part({"compression": OpenEXR.NO_COMPRESSION}, {"RGB": expected}, name=name)
             for name in ("left", "right")]
    OpenEXR.File(parts).write(str(work / "parts.exr"))
    with pytest.raises(RuntimeError, match="2 parts \\('left', 'right'\\)"):
        raylab.read_exr(work / "parts.exr")
    # A data window inside the display window is placed in it, not stretched over it: 0 outside.
    window = raylab.read_exr(_exr(work / "window.exr", {"RGB": np.ones((8, 8, 3), np.float32)},
                                  dataWindow=((4, 4), (11, 11)), displayWindow=((0, 0), (31, 15))))
    assert window.shape == (16, 32, 4)
    assert window[4:12, 4:12].min() == 1.0 and window[:4].max() == 0.0 and window[:, 12:].max() == 0.0


# One bound on what emits light, wherever a value enters: strength x the brightest texel, a light's intensity.
def test_values_that_would_overflow_the_image_are_refused(work, minimal):
    sky = _exr(work / "sky.exr", {"RGB": np.full((8, 16, 3), 2.0, np.float32)})
    scene = raylab.Scene.load(minimal)
    scene.set_environment(sky, strength=4.0)
    with pytest.raises(ValueError, match="strength 1e\\+30 x the image's brightest texel 2"):
        scene.set_environment(strength=1e30)
    with pytest.raises(ValueError, match="over raylab's limit"):
        scene.set_environment(strength=3e38)
    assert scene.environment["strength"] == 4.0, "a refused edit changed the scene"
    with pytest.raises(ValueError, match="over raylab's limit"):
        scene.set_light("lamp", intensity=(3e38, 0, 0))
    with pytest.raises(ValueError, match="over raylab's limit"):
        raylab.Scene.load(minimal, env=sky, env_strength=1e25)
    image = raylab.Renderer(scene, width=16, height=8, integrator="path").render(spp=2)
    assert np.isfinite(image).all()
    with pytest.raises(ValueError, match="no NaN or infinity"):
        raylab.write_exr(work / "nan.exr", np.full((2, 2, 3), np.inf, np.float32))
    assert not (work / "nan.exr").exists()


def test_python_checks_what_the_command_line_checks(work, minimal):
    scene = raylab.Scene.load(minimal)
    with pytest.raises(ValueError, match="field of view"):
        scene.set_camera(fov_deg=1e-30)
    with pytest.raises(ValueError, match="rotation_deg"):
        scene.set_environment(rotation_deg=1e30)
    # Scene.load's env_rotation_deg took NaN, inf and 1e30 (a black sky, 996 of 1,024 samples dropped).
    sky = _exr(work / "sky.exr", {"RGB": np.full((8, 16, 3), 2.0, np.float32)})
    for rotation in (float("nan"), float("inf"), 1e30, -361.0):
        with pytest.raises(ValueError, match="env_rotation_deg"):
            raylab.Scene.load(minimal, env=sky, env_rotation_deg=rotation)
    assert raylab.Scene.load(minimal, env=sky, env_rotation_deg=-360.0).environment["rotation_deg"] == pytest.approx(-360.0)
    with pytest.raises(ValueError, match="exposure"):
        raylab.write_png(work / "x.png", np.zeros((2, 2, 3), np.float32), exposure=float("nan"))
    with pytest.raises(ValueError, match="must end in .png"):
        raylab.write_png(work / "x.jpg", np.zeros((2, 2, 3), np.float32))
    with pytest.raises(ValueError, match="must end in .exr"):
        raylab.write_exr(work / "x.png", np.zeros((2, 2, 3), np.float32))
    renderer = raylab.Renderer(scene, width=8, height=8)
    with pytest.raises(ValueError, match="limit of 1048576"):
        renderer.add_samples(2 ** 32)  # used to wrap to 0 and add nothing
    with pytest.raises(ValueError, match="at least 1"):
        renderer.add_samples(-1)


def test_numpy_scalars_paths_and_display_images_are_taken(work, minimal):
    scene = raylab.Scene.load(Path(minimal))
    scene.set_material("red plastic", rho_d=np.float32(0.25), m=np.float64(0.3))
    scene.set_material("ground", rho_d=np.array([0.1, 0.2, 0.3]))
    assert scene.material("red plastic")["m"] == pytest.approx(0.3)
    assert scene.material("ground")["rho_d"] == pytest.approx((0.1, 0.2, 0.3))
    with pytest.raises(ValueError, match="not a bool"):
        scene.set_material("ground", delta=True)
    image = raylab.Renderer(scene, width=np.int64(12), height=np.int32(8)).render(spp=np.int64(1))
    raylab.write_png(work / "linear.png", image)
    display = raylab.read_png(work / "linear.png")
    raylab.write_png(work / "again.png", display)  # uint8 is display-referred: written as it is
    np.testing.assert_array_equal(raylab.read_png(work / "again.png"), display)
    assert raylab.__version__.count(".") == 2
    assert raylab.limits["max_spp"] == 1 << 20


# The farm's manifests are files a user (or a crash) may leave in any state: whatever they hold, the farm decides
# "done" or "render again" and never raises. A fixed-seed fuzz over bytes and over JSON values of every shape.
def test_farm_manifests_of_any_content_never_crash_and_vouch_only_for_matching_files(work):
    import json
    import random

    from raylab.farm.jobs import MANIFEST, Job, Manifests, file_digest

    cell = work / "cell_000.exr"
    raylab.write_exr(cell, np.ones((2, 2, 4), np.float32))
    job = Job(key="k", name="cell 0", path=cell, function=print, args=(), samples=1, description="study 0")
    rng = random.Random(21)
    values = [None, True, 0, -1.5, "text", [], [1, 2], {}, {"cell_000.exr": "study 0"},
              {"cell_000.exr": {"description": "study 0"}}, {"cell_000.exr": {"description": "study 0", "sha256": 7}},
              {"cell_000.exr": {"description": "study 0", "sha256": "0" * 64}}, {"cell_000.exr": [None]}]
    contents = [json.dumps(v).encode() for v in values]
    contents += [bytes(rng.randrange(256) for _ in range(rng.randrange(64))) for _ in range(200)]
    contents += [b"\xff\xfe{", b"{" * 100000, b"[" * 100000, b'{"cell_000.exr": {"description": "study 0", "sha256": "']
    for content in contents:
        (work / MANIFEST).write_bytes(content)
        assert Manifests().is_done(job) is False, content[:80]
    # A manifest that is a FIFO or a device is reported, never read (it would hang or grow without bound).
    (work / MANIFEST).unlink()
    os.mkfifo(work / MANIFEST)
    assert Manifests().is_done(job) is False
    (work / MANIFEST).unlink()
    (work / MANIFEST).symlink_to("/dev/zero")
    assert Manifests().is_done(job) is False
    (work / MANIFEST).unlink()
    # Only the entry that names the description and this file's digest vouches for it.
    good = {"cell_000.exr": {"description": "study 0", "sha256": file_digest(cell)}}
    (work / MANIFEST).write_text(json.dumps(good))
    assert Manifests().is_done(job) is True
    cell.write_bytes(cell.read_bytes()[:-1])
    assert Manifests().is_done(job) is False


# An environment the device cannot hold is refused from its header, before it is decoded (an 8192 x 4096 image
# used to take 1.8 GiB before the device's limit refused it).
def test_an_environment_too_large_for_the_device_is_refused_before_decoding(work, minimal, raylab_binary):
    big = work / "big.exr"
    OpenEXR.File({"compression": OpenEXR.ZIP_COMPRESSION},
                 {"RGB": np.full((4096, 8192, 3), 0.5, np.float16)}).write(str(big))
    command = [str(raylab_binary), "render", str(minimal), "--env", str(big), "--width", "16", "--height", "8",
               "--spp", "1", "--out", str(work / "never.exr"), "--no-png"]
    # raylab's own peak, measured by a fresh interpreter that runs it: a child forked from this large process
    # would count the pages it shares with it until exec. Decoding would have taken over 1.5 GiB.
    measure = ("import resource, subprocess, sys; done = subprocess.run(sys.argv[1:], stderr=subprocess.PIPE, "
               "text=True); sys.stderr.write(done.stderr); "
               "print(done.returncode, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)")
    done = subprocess.run([sys.executable, "-c", measure] + command, capture_output=True, text=True, timeout=120)
    returncode, peak_kib = (int(word) for word in done.stdout.split())
    assert returncode == 1, done.stderr
    assert "8192x4096 needs 768 MiB" in done.stderr and "maxStorageBufferRange" in done.stderr
    assert peak_kib < 512 * 1024, f"{peak_kib} KiB at the peak: the image was decoded"


# A file without lights gets a headlight carried with the camera: turned to the box's far side, the face it sees
# is lit as the first view's was (a light fixed in the world left it black).
def test_a_file_without_lights_is_lit_wherever_the_camera_turns():
    box = Path("/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf")
    if not box.exists():
        pytest.skip("assimp-testmodels is not installed (tools/setup.sh installs it)")
    scene = raylab.Scene.load(box)
    assert scene.light("default")["type"] == "headlight"
    front = raylab.Renderer(scene, width=32, height=32).render(spp=1)
    camera = scene.camera
    target = np.array(camera["target"])
    behind = 2 * target - np.array(camera["position"])  # the camera turned 180 degrees about the target
    behind[1] = camera["position"][1]
    scene.set_camera(position=tuple(behind))
    back = raylab.Renderer(scene, width=32, height=32).render(spp=1)
    centre = (slice(12, 20), slice(12, 20))
    assert back[centre][..., :3].mean() > 0.5 * front[centre][..., :3].mean() > 0.05


def _resident_mib() -> float:
    return int(Path("/proc/self/statm").read_text().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 2**20


# A measured table (33 MiB) is freed when its file changes and is loaded again, and at most 8 stay in memory when
# nothing uses them: 40 reloads in Python used to take 1.37 GiB, 30 files set on one material 1.73 GiB. The newest
# version is what a material then evaluates.
def test_measured_tables_are_freed_or_replaced(work, minimal):
    for name, rho in (("a", 0.5), ("b", 0.2)):
        raylab.brdf.tabulate("lambert", {"rho_d": (rho, rho, rho)}, work / f"{name}.binary")
    scene = raylab.Scene.load(minimal)
    material = scene.materials[0]
    changing = work / "changing.binary"
    z = np.array([0.0, 0.0, 1.0])
    start = None
    for i in range(40):
        rho = 0.5 if i % 2 == 0 else 0.2
        shutil.copyfile(work / ("a.binary" if rho == 0.5 else "b.binary"), changing)
        scene.set_material(material, model="measured", file=changing)
        f = raylab.brdf.eval("measured", {"file": changing}, wi=z, wo=z)
        np.testing.assert_allclose(np.ravel(f), rho / np.pi, rtol=1e-3, err_msg=f"reload {i} read an old version")
        if i == 4:
            start = _resident_mib()
    assert _resident_mib() - start < 40, "reloads of one changed file kept their old tables"
    for i in range(16):
        distinct = work / f"copy{i}.binary"
        shutil.copyfile(work / "a.binary", distinct)
        scene.set_material(material, model="measured", file=distinct)
    assert _resident_mib() - start < 9 * 34 + 40, "tables nothing uses were kept"
    # An evicted table is read again when used.
    np.testing.assert_allclose(np.ravel(raylab.brdf.eval("measured", {"file": work / "copy0.binary"}, wi=z, wo=z)),
                               0.5 / np.pi, rtol=1e-3)


NBRDF_ARCHIVE = Path(__file__).resolve().parents[3] / "shared" / "measured" / "nbrdf" / "merl_nbrdf.zip"


def test_neural_brdf_files_are_refused_as_files_are(work):
    z = np.array([[0.0, 0.0, 1.0]])
    (work / "pipe.json").write_text("{}")
    os.mkfifo(work / "pipe.h5")
    with pytest.raises(ValueError, match="pipe.h5: is not a regular file"):
        raylab.brdf.eval("nbrdf", {"file": work / "pipe.h5"}, wi=z, wo=z)
    (work / "text.h5").write_text("not HDF5")
    (work / "text.json").write_text("{}")
    with pytest.raises(ValueError, match="text.h5"):
        raylab.brdf.eval("nbrdf", {"file": work / "text.h5"}, wi=z, wo=z)
    with pytest.raises(ValueError, match="this parameter takes a neural BRDF"):
        raylab.brdf.eval("nbrdf", {"file": work / "table.binary"}, wi=z, wo=z)


# The published networks (optional data): evaluated from threads at once, each gives what it gives alone.
def test_neural_brdfs_evaluate_the_same_from_threads(work):
    if not NBRDF_ARCHIVE.is_file():
        pytest.skip(f"{NBRDF_ARCHIVE} is absent (optional data, docs/measured.md)")
    import zipfile
    from concurrent.futures import ThreadPoolExecutor
    with zipfile.ZipFile(NBRDF_ARCHIVE) as archive:
        names = sorted(n for n in archive.namelist() if n.endswith(".h5"))[:6]
        for name in names:
            for member in (name, name[:-3] + ".json"):
                (work / Path(member).name).write_bytes(archive.read(member))
    rng = np.random.default_rng(3)
    wi = rng.normal(size=(4000, 3)) * [1, 1, 0] + [0, 0, 1.2]
    wo = rng.normal(size=(4000, 3)) * [1, 1, 0] + [0, 0, 1.2]
    wi /= np.linalg.norm(wi, axis=1, keepdims=True)
    wo /= np.linalg.norm(wo, axis=1, keepdims=True)
    files = [work / Path(n).name for n in names]
    alone = [raylab.brdf.eval("nbrdf", {"file": f}, wi=wi, wo=wo) for f in files]
    with ThreadPoolExecutor(6) as pool:
        together = list(pool.map(lambda f: raylab.brdf.eval("nbrdf", {"file": f}, wi=wi, wo=wo), files * 3))
    for i, values in enumerate(together):
        np.testing.assert_array_equal(values, alone[i % len(files)])
    assert all(np.all(np.isfinite(a)) and np.all(a >= 0) and a.max() > 0 for a in alone)
