"""The Python module against the command line: the same renders bit for bit, the same BRDF values, the same
errors; and a render that another thread interrupts stops within one submission."""
import _thread
import os
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import raylab


def test_devices_lists_a_capable_device():
    devices = raylab.devices()
    assert devices, "no Vulkan device"
    assert any(d["backends"] for d in devices), devices


@pytest.mark.parametrize("backend", ["query", "pipeline"])
def test_render_equals_the_command_lines_exr_bit_for_bit(backend, source_dir, work, run_raylab):
    scene_path = source_dir / "assets" / "scenes" / "minimal.gltf"
    exr = work / "cli.exr"
    run_raylab("render", scene_path, "--width", 96, "--height", 64, "--spp", 5, "--seed", 3, "--backend", backend,
               "--out", exr, "--no-png")
    scene = raylab.Scene.load(str(scene_path))
    renderer = raylab.Renderer(scene, width=96, height=64, backend=backend)
    image = renderer.render(spp=5, seed=3)
    assert image.dtype == np.float32 and image.shape == (64, 96, 4)
    reference = raylab.read_exr(str(exr))
    assert np.array_equal(image, reference), f"max difference {np.abs(image - reference).max()}"
    assert renderer.report()["samples"] == 5
    assert renderer.report()["backend"] == backend


def test_path_integrator_with_an_environment_and_edits_equals_the_command_line(source_dir, work, run_raylab):
    scene_path = source_dir / "assets" / "scenes" / "minimal.gltf"
    env = source_dir / "assets" / "scenes" / "environments" / "courtyard.exr"
    material = "red plastic=ward:alpha_x=0.3,alpha_y=0.1"
    exr = work / "cli.exr"
    run_raylab("render", scene_path, "--env", env, "--env-strength", 0.5, "--integrator", "path", "--width", 64,
               "--height", 48, "--spp", 3, "--material", material, "--out", exr, "--no-png")
    scene = raylab.Scene.load(str(scene_path), env=str(env), env_strength=0.5)
    # The model switch carries the material's colours over, as --material does (one switchModel for both).
    scene.set_material("red plastic", model="ward", alpha_x=0.3, alpha_y=0.1)
    renderer = raylab.Renderer(scene, width=64, height=48, integrator="path")
    assert np.array_equal(renderer.render(spp=3), raylab.read_exr(str(exr)))


def test_add_samples_refines_progressively_to_the_same_image():
    scene = raylab.Scene.default()
    renderer = raylab.Renderer(scene, width=48, height=32)
    whole = renderer.render(spp=4).copy()
    renderer.render(spp=1)
    renderer.add_samples(3)
    assert renderer.samples == 4
    assert np.array_equal(renderer.image(), whole)


def _random_cases(count, seed):
    rng = np.random.default_rng(seed)
    def directions():
        v = rng.normal(size=(count, 3))
        v[:, 2] = np.abs(v[:, 2]) + 0.05
        return (v / np.linalg.norm(v, axis=1, keepdims=True)).astype(np.float32)
    return directions(), directions()


@pytest.mark.parametrize("backend", ["gpu", "cpu"])
def test_brdf_eval_equals_raylab_brdf_eval(backend, work, run_raylab):
    wi, wo = _random_cases(64, 5)
    params = "rho_d=0.2/0.3/0.4;rho_s=0.7;alpha_x=0.15;alpha_y=0.4"
    rows = ["id,model,params,wi,wo,n,t"]
    for i in range(len(wi)):
        rows.append(f"{i},ward,{params},{' '.join(f'{x:.9g}' for x in wi[i])},{' '.join(f'{x:.9g}' for x in wo[i])},"
                    "0 0 1,1 0 0")
    cases = work / "cases.csv"
    cases.write_text("\n".join(rows) + "\n")
    values = work / "values.csv"
    run_raylab("brdf", "eval", "--in", cases, "--out", values, "--backend", backend)
    expected = np.array([[float(x) for x in line.split(",")[-1].split()]
                         for line in values.read_text().splitlines()[1:]])
    f = raylab.brdf.eval("ward", params, wi=wi, wo=wo, backend=backend)
    assert f.shape == (64, 3)
    # The CSV holds 9 significant digits: float32 values exactly, doubles to 5e-9.
    np.testing.assert_allclose(f, expected, rtol=5e-9, atol=0)
    as_dict = raylab.brdf.eval("ward", {"rho_d": (0.2, 0.3, 0.4), "rho_s": 0.7, "alpha_x": 0.15, "alpha_y": 0.4},
                               wi=wi, wo=wo, backend=backend)
    assert np.array_equal(as_dict, f)


def test_pdf_and_sample_agree_between_the_device_and_the_reference():
    wo = np.array([0.3, 0.2, 0.93], dtype=np.float32)
    wo /= np.linalg.norm(wo)
    u = (np.random.default_rng(2).integers(0, 1 << 24, size=(256, 3)) / float(1 << 24)).astype(np.float32)
    gpu = raylab.brdf.sample("cooktorrance", {"m": 0.3}, wo=wo, u=u, backend="gpu")
    cpu = raylab.brdf.sample("cooktorrance", {"m": 0.3}, wo=wo, u=u, backend="cpu")
    ok = (cpu["pdf"] > 0) & (gpu["pdf"] > 0)
    assert ok.sum() > 200
    np.testing.assert_allclose(gpu["wi"][ok], cpu["wi"][ok], atol=2e-4)
    np.testing.assert_allclose(gpu["pdf"][ok], cpu["pdf"][ok], rtol=2e-3)
    # pdf() at the sampled directions is the density the sampler reported.
    pdf = raylab.brdf.pdf("cooktorrance", {"m": 0.3}, wi=gpu["wi"][ok].astype(np.float32), wo=wo)
    np.testing.assert_allclose(pdf, gpu["pdf"][ok], rtol=1e-3)


def test_albedo_matches_the_command_line(run_raylab):
    out = run_raylab("brdf", "albedo", "--model", "phong", "--params", "s=40", "--angles", "0,60").stdout
    expected = [[float(x) for x in line.split(",")[5:8]] for line in out.splitlines()[1:]]
    albedo = raylab.brdf.albedo("phong", "s=40", theta_deg=[0, 60])["albedo"]
    np.testing.assert_allclose(albedo, expected, rtol=1e-8)


def test_images_round_trip(work):
    image = np.random.default_rng(1).random((5, 7, 4), dtype=np.float32)
    raylab.write_exr(str(work / "a.exr"), image)
    assert np.array_equal(raylab.read_exr(str(work / "a.exr")), image)
    raylab.write_png(str(work / "a.png"), image[..., :3], exposure=0.0)
    png = raylab.read_png(str(work / "a.png"))
    assert png.shape == (5, 7, 3) and png.dtype == np.uint8


def test_bad_input_raises_with_the_command_lines_messages(source_dir, work):
    with pytest.raises(FileNotFoundError, match="nosuch.gltf"):
        raylab.Scene.load(str(work / "nosuch.gltf"))
    broken = work / "broken.gltf"
    broken.write_text('{"asset": {"version": "2.0"}, "scenes": [{"nodes": [7]}]}')
    with pytest.raises(ValueError, match="broken.gltf"):
        raylab.Scene.load(str(broken))
    scene = raylab.Scene.load(str(source_dir / "assets" / "scenes" / "minimal.gltf"))
    with pytest.raises(ValueError, match="'ground', 'red plastic'"):
        scene.material("nosuch")
    with pytest.raises(ValueError, match=r"m .*\[|range|outside"):
        scene.set_material("red plastic", m=-1.0)
    assert scene.material("red plastic")["m"] == pytest.approx(0.2), "a refused edit changed the material"
    with pytest.raises(ValueError, match="alpha_x"):
        scene.set_material("red plastic", model="ward", beta=2.0)
    # openpbr's layers: an out-of-range weight, a negative volume depth, NaN (a NumPy one too); none is applied.
    for bad in ({"coat_weight": 1.5}, {"transmission_depth": -1.0}, {"fuzz_weight": float("nan")},
                {"geometry_opacity": np.float32(2.0)}, {"thin_film_weight": np.nan}):
        name = next(iter(bad))
        with pytest.raises(ValueError, match=name):
            scene.set_material("red plastic", model="openpbr", **bad)
        assert scene.material("red plastic")["model"] == "cooktorrance", f"a refused {name} changed the material"
    with pytest.raises(ValueError, match="lambert, phong"):
        raylab.brdf.eval("wardish", wi=[0, 0, 1], wo=[0, 0, 1])
    with pytest.raises(ValueError, match="finite"):
        raylab.brdf.eval("phong", wi=[0, 0, float("nan")], wo=[0, 0, 1])
    with pytest.raises(ValueError, match="image size"):
        raylab.Renderer(scene, width=0, height=10)
    with pytest.raises(ValueError, match="must be finite and >= 0"):
        scene.set_light("lamp", intensity=(1.0, -1.0, 1.0))
    with pytest.raises(ValueError, match="shape"):
        raylab.write_exr(str(work / "bad.exr"), np.zeros((4, 4)))


def _slow_renderer():
    scene = raylab.Scene.default()
    return raylab.Renderer(scene, width=320, height=180, integrator="path")


def test_cancel_from_another_thread_stops_within_one_submission():
    renderer = _slow_renderer()
    renderer.render(spp=1)  # the kernel compiles at its first dispatch
    cancelled_at = []
    def cancel():
        time.sleep(1.0)
        cancelled_at.append(time.monotonic())
        renderer.cancel()
    thread = threading.Thread(target=cancel)
    thread.start()
    with pytest.raises(raylab.Cancelled, match="cancelled after"):
        renderer.render(spp=100000)
    stopped = time.monotonic() - cancelled_at[0]
    thread.join()
    # Submissions last about a quarter second; allow one, and a loaded machine's slack.
    assert stopped < 1.0, f"stopped {stopped:.2f} s after cancel()"
    assert 1 <= renderer.samples < 100000


def test_ctrl_c_raises_keyboard_interrupt_between_submissions():
    renderer = _slow_renderer()
    renderer.render(spp=1)
    timer = threading.Timer(1.0, _thread.interrupt_main)
    timer.start()
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        renderer.render(spp=100000)
    assert time.monotonic() - start < 2.5
    timer.cancel()



def test_a_device_without_what_was_asked_raises_runtime_error_with_the_command_lines_message(raylab_binary, work):
    # The device survey is made once per process: fresh processes see the ray queries hidden.
    environment = {**os.environ, "RAYLAB_HIDE_RAY_QUERIES": "1"}
    code = ("import raylab\n"
            "try:\n"
            "    raylab.Renderer(raylab.Scene.default(), width=8, height=8, backend='query')\n"
            "except RuntimeError as error:\n"
            "    print(error)\n"
            "print(raylab.Renderer(raylab.Scene.default(), width=8, height=8).report()['backend'])\n")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=environment)
    assert result.returncode == 0, result.stderr
    message, backend = result.stdout.strip().splitlines()
    command = subprocess.run([str(raylab_binary), "render", "--backend", "query", "--width", "8", "--height", "8",
                              "--out", str(work / "never.exr"), "--no-png"], capture_output=True, text=True, env=environment)
    assert command.returncode == 3
    assert "offers no ray queries" in message and message in command.stderr
    assert backend == "pipeline"  # auto takes the ray-tracing pipeline, as the command line does


# Path guiding through Python: the option as `raylab render --guiding` takes it, the guide's state in the report, and
# the same refusals (a value not among off, on, auto; the slides' integrator, which samples no continuations).
def test_guiding(source_dir):
    scene = raylab.Scene.load(str(source_dir / "assets" / "scenes" / "glossy_room.gltf"))
    renderer = raylab.Renderer(scene, width=48, height=27, guiding="on")
    image = renderer.render(spp=4, seed=np.uint32(3))
    assert np.isfinite(image).all() and image[..., :3].mean() > 0.0
    report = renderer.report()
    assert report["guiding"] == "on" and "path guiding" in report["kernel"]
    assert report["guide"]["updates"] == 3 and report["guide"]["cells"] > 0, report["guide"]
    assert raylab.Renderer(scene, width=48, height=27).report()["guiding"] == "off"
    with pytest.raises(ValueError, match="guiding.*off, on or auto"):
        raylab.Renderer(scene, width=48, height=27, guiding="always")
    minimal = raylab.Scene.load(str(source_dir / "assets" / "scenes" / "minimal.gltf"))
    with pytest.raises(ValueError, match="--guiding"):
        raylab.Renderer(minimal, width=48, height=27, integrator="slides", guiding="on")
