"""raylab.farm against `raylab sweep`: the same contact sheet bit for bit from a LocalCluster of 2 worker processes,
also when a worker is killed while it renders (its job runs again elsewhere), and a rerun after an interruption
renders only the missing cells."""
import os
import re
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest
from distributed import Client, LocalCluster

import raylab
import raylab.farm

# Cells of about a second each on one lavapipe thread: long enough to kill a worker or interrupt the client while
# cells are rendering, short enough for CI.
CELLS = 6
STUDY = ["--model", "ward", "--param", "alpha_x", "--steps", str(CELLS), "--cell", "96", "--spp", "384",
         "--set", "rho_d=0.2/0.1/0.05", "--seed", "7"]


@pytest.fixture(scope="module")
def reference(tmp_path_factory, run_raylab):
    """The single-process sheet: `raylab sweep` itself."""
    png = tmp_path_factory.mktemp("reference") / "sheet.png"
    run_raylab("sweep", *STUDY, "--png", png)
    return png


def assert_same_sheet(png, reference):
    exr, reference_exr = png.with_suffix(".exr"), reference.with_suffix(".exr")
    farmed, single = raylab.read_exr(str(exr)), raylab.read_exr(str(reference_exr))
    assert farmed.shape == single.shape
    assert np.array_equal(farmed, single), f"EXR differs: max |difference| {np.abs(farmed - single).max()}"
    assert png.read_bytes() == reference.read_bytes(), "PNG differs"


def local_cluster():
    return LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)


def test_two_workers_make_the_same_sheet_as_raylab_sweep(work, reference):
    png = work / "sheet.png"
    report = raylab.farm.sweep([*STUDY, "--out", png], workers=2, progress=False)
    assert report.rendered == CELLS and report.skipped == 0 and report.workers == 2
    assert len(set(report.by_pid.values())) == 2, f"one worker rendered every cell: {report.by_pid}"
    assert_same_sheet(png, reference)


def test_a_worker_killed_while_it_renders_costs_only_its_job(work, reference):
    png = work / "sheet.png"
    killed = {}

    def executing(dask_worker):
        return [str(task.key) for task in dask_worker.state.executing]  # the keys of its running jobs

    def kill_a_rendering_worker(client):
        # Not the first two cells: their workers are still creating their devices. A later cell runs on a worker
        # that has rendered before, so killing it interrupts a render.
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline:
            for address, keys in client.run(executing).items():
                late = [key for key in keys if int(key.rsplit("-", 1)[1]) >= 2]
                if late:
                    pid = client.run(os.getpid, workers=[address])[address]
                    os.kill(pid, signal.SIGKILL)
                    killed.update(key=late[0], pid=pid, cell=int(late[0].rsplit("-", 1)[1]))
                    return
            time.sleep(0.02)

    with local_cluster() as cluster, Client(cluster) as client:
        killer = threading.Thread(target=kill_a_rendering_worker, args=(client,))
        killer.start()
        report = raylab.farm.sweep([*STUDY, "--out", png], client=client, progress=False)
        killer.join()
    assert killed, "no worker was seen rendering a cell"
    # The killed job was rendered again, by another process (the restarted worker or the other one).
    retried = next(name for name in report.by_pid if name.startswith(f"cell {killed['cell']} "))
    assert report.by_pid[retried] != killed["pid"], f"{retried} finished on the killed worker {killed['pid']}"
    assert report.rendered == CELLS
    assert_same_sheet(png, reference)


def farm_command(png, source_dir):
    return [sys.executable, "-m", "raylab.farm", "sweep", *STUDY, "--out", str(png), "--workers", "2"]


def test_a_rerun_after_an_interruption_renders_only_what_is_missing(work, reference, source_dir):
    png = work / "sheet.png"
    cells = png.with_suffix(".cells")
    # Ctrl-C in a terminal: SIGINT to the whole process group (the client and its workers).
    process = subprocess.Popen(farm_command(png, source_dir), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               text=True, start_new_session=True)
    deadline = time.monotonic() + 120
    while len(list(cells.glob("*/cell_*.exr"))) < 2 and process.poll() is None and time.monotonic() < deadline:
        time.sleep(0.02)
    os.killpg(process.pid, signal.SIGINT)
    out, err = process.communicate(timeout=60)
    done = len(list(cells.glob("*/cell_*.exr")))
    assert process.returncode != 0, f"the farm finished before the interruption:\n{out}{err}"
    assert 2 <= done < CELLS, f"{done} cells after the interruption\n{err}"
    assert not png.exists(), "a sheet was written by an interrupted sweep"
    assert "a rerun renders the rest" in err

    rerun = subprocess.run(farm_command(png, source_dir), capture_output=True, text=True, timeout=300)
    assert rerun.returncode == 0, rerun.stdout + rerun.stderr
    counts = re.search(r"(\d+) jobs rendered \((\d+) already done\)", rerun.stdout)
    assert counts, rerun.stdout
    assert (int(counts[1]), int(counts[2])) == (CELLS - done, done), rerun.stdout
    assert_same_sheet(png, reference)


def test_the_command_line_takes_raylab_sweeps_options_and_errors(run_raylab):
    help_text = subprocess.run([sys.executable, "-m", "raylab.farm", "sweep", "--help"], capture_output=True,
                               text=True, check=True).stdout
    assert "--workers N" in help_text and "--scheduler ADDRESS" in help_text
    assert run_raylab("sweep", "--help").stdout.strip() in help_text  # every option of raylab sweep, as it is
    bad = subprocess.run([sys.executable, "-m", "raylab.farm", "sweep", "--model", "ward", "--param", "alpha_q",
                          "--workers", "2"], capture_output=True, text=True)
    command = run_raylab("sweep", "--model", "ward", "--param", "alpha_q", check=False)
    assert bad.returncode == command.returncode == 2
    assert bad.stderr.strip() == command.stderr.strip()
    with pytest.raises(ValueError, match="not both"):
        raylab.farm.sweep(STUDY, workers=2, scheduler="tcp://127.0.0.1:1")


def test_a_turntable_frame_is_raylab_render_and_a_rerun_with_other_options_renders_again(work, run_raylab,
                                                                                         source_dir):
    scene = str(source_dir / "assets" / "scenes" / "minimal.gltf")
    options = dict(width=64, height=48, spp=4, seed=2)
    jobs = raylab.farm.turntable(scene, 4, str(work / "turn.exr"), **options)
    report = raylab.farm.renders(jobs, workers=2, progress=False)
    assert report.rendered == 4
    # Frame 0 is the scene's camera: `raylab render` with the same options.
    run_raylab("render", scene, "--width", 64, "--height", 48, "--spp", 4, "--seed", 2, "--out", work / "cli.exr",
               "--no-png")
    assert np.array_equal(raylab.read_exr(jobs[0].out), raylab.read_exr(str(work / "cli.exr")))
    # Frame 2 looks at the scene from the other side: camera and target turned by 180 degrees about the vertical
    # through the centre of the scene's bounds, so the scene turns in place.
    moved = raylab.Scene.load(scene)
    moved.set_camera(**jobs[2].camera)
    low, high = moved.bounds
    centre = (np.array(low) + np.array(high)) / 2
    original = raylab.Scene.load(scene).camera
    for point in ("position", "target"):
        turned = np.array(moved.camera[point]) - centre
        before = np.array(original[point]) - centre
        assert np.allclose(turned, [-before[0], before[1], -before[2]], atol=1e-5), point
    direct = raylab.Renderer(moved, width=64, height=48).render(spp=4, seed=2)
    assert np.array_equal(raylab.read_exr(jobs[2].out), direct)
    assert not np.array_equal(raylab.read_exr(jobs[2].out), raylab.read_exr(jobs[0].out))
    # The same study again: nothing to do. Other samples: every frame again.
    assert raylab.farm.renders(jobs, workers=1, progress=False).rendered == 0
    more = raylab.farm.turntable(scene, 4, str(work / "turn.exr"), **{**options, "spp": 5})
    assert raylab.farm.renders(more, workers=1, progress=False).rendered == 4


def test_bad_jobs_are_refused_before_any_cluster_starts(work, source_dir):
    scene = str(source_dir / "assets" / "scenes" / "minimal.gltf")
    rough = raylab.farm.RenderJob(out=str(work / "a.exr"), scene=scene,
                                  materials={"red plastic": {"model": "cooktorrance", "m": -1}})
    with pytest.raises(ValueError, match=r"job 0 \(.*a.exr\): material 'red plastic': m = -1 is outside"):
        raylab.farm.renders([rough], scheduler="tcp://127.0.0.1:1")  # nobody listens: the check comes first
    missing = raylab.farm.RenderJob(out=str(work / "b.exr"), scene=str(work / "nope.gltf"))
    with pytest.raises(FileNotFoundError, match="job 0 .*nope.gltf"):
        raylab.farm.renders([missing], scheduler="tcp://127.0.0.1:1")
    with pytest.raises(ValueError, match="must end in .exr"):
        raylab.farm.renders([raylab.farm.RenderJob(out=str(work / "c.png"))], scheduler="tcp://127.0.0.1:1")
    same = raylab.farm.RenderJob(out=str(work / "d.exr"))
    with pytest.raises(ValueError, match="same file"):
        raylab.farm.renders([same, same], scheduler="tcp://127.0.0.1:1")
    with pytest.raises(ValueError, match=r"spp must be an integer in \[1, 1048576\], not 0"):
        raylab.farm.turntable(scene, 4, str(work / "t.exr"), spp=0)
    with pytest.raises(ValueError, match=r"guiding is off, on, auto, not 'always'"):
        raylab.farm.RenderJob(out=str(work / "g.exr"), guiding="always")
    with pytest.raises(ValueError, match=r"--frames must be within 1..3600"):
        raylab.farm.turntable(scene, 0, str(work / "t.exr"))
    with pytest.raises(ValueError, match=r"--frames must be within 1..3600"):
        raylab.farm.turntable(scene, 10 ** 6, str(work / "t.exr"))
    with pytest.raises(ValueError, match=r"--workers must be within 1\.\."):
        raylab.farm.renders([raylab.farm.RenderJob(out=str(work / "e.exr"))], workers=5000)
    for option, value in (("--workers", "5000"), ("--frames", "99999"), ("--target", "1,2")):
        refused = subprocess.run([sys.executable, "-m", "raylab.farm", "turntable", option, value],
                                 capture_output=True, text=True, timeout=60)
        assert refused.returncode == 2 and option in refused.stderr, refused.stderr


def _cells(png):
    return sorted(png.with_suffix(".cells").glob("*/cell_*.exr"))


def test_damaged_replaced_or_unreadable_results_are_rendered_again(work, reference):
    """A cell truncated, replaced by another valid cell, or a manifest that is not an object: the rerun renders
    what cannot be trusted (checked against the SHA-256 the manifest records) and the sheet is still the same."""
    png = work / "sheet.png"
    raylab.farm.sweep([*STUDY, "--out", png], workers=2, progress=False)
    cells = _cells(png)
    cells[1].write_bytes(cells[1].read_bytes()[:1000])  # truncated
    cells[3].write_bytes(cells[4].read_bytes())  # a valid EXR, of another cell
    report = raylab.farm.sweep([*STUDY, "--out", png], workers=2, progress=False)
    assert (report.rendered, report.skipped) == (2, CELLS - 2)
    assert_same_sheet(png, reference)
    manifest = cells[0].parent / "raylab-farm.json"
    manifest.write_text("[1, 2, 3]\n")
    rerun = subprocess.run([sys.executable, "-m", "raylab.farm", "sweep", *STUDY, "--out", str(png), "--workers", "2",
                            "--quiet"], capture_output=True, text=True, timeout=300)
    assert rerun.returncode == 0, rerun.stderr
    assert "is not a JSON object; its jobs are rendered again" in rerun.stderr
    assert f"{CELLS} jobs rendered (0 already done)" in rerun.stdout
    assert_same_sheet(png, reference)


def test_a_scheduler_that_never_answers_is_an_error_not_a_hang(work, monkeypatch):
    """A server that accepts the connection and says nothing (not a Dask scheduler): RuntimeError within the
    farm's bound (shortened here), not a wait forever."""
    import socket

    import raylab.farm.cluster
    monkeypatch.setattr(raylab.farm.cluster, "SCHEDULER_ANSWER_S", 2)
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen(4)
    accepted = []
    stop = threading.Event()

    def accept():
        server.settimeout(0.2)
        while not stop.is_set():
            try:
                accepted.append(server.accept()[0])
            except OSError:
                pass

    thread = threading.Thread(target=accept, daemon=True)
    thread.start()
    try:
        start = time.monotonic()
        with pytest.raises(RuntimeError, match="did not answer|cannot reach"):
            raylab.farm.renders([raylab.farm.RenderJob(out=str(work / "a.exr"), width=8, height=8, spp=1)],
                                scheduler=f"tcp://127.0.0.1:{server.getsockname()[1]}", progress=False)
        assert time.monotonic() - start < 30
    finally:
        stop.set()
        thread.join()
        server.close()
