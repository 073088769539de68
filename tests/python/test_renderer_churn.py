"""Long-lived processes make many renderers (issue 22): creating and destroying them, with and without a Vulkan
failure injected at a creation step (raylab._fail_at_creation, the hook of vk/vk_check.h), keeps the process's
memory flat, and each injected failure is a clear Python error. tools/renderer_churn.py runs the same with 1,000
successful renderers (minutes on lavapipe; its figures are in docs/architecture.md)."""
import random

import pytest

import raylab


def resident_mib() -> float:
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * 4096 / 2**20


@pytest.fixture(scope="module")
def scene(source_dir):
    return raylab.Scene.load(str(source_dir / "assets" / "scenes" / "sweep_lambert_rho_d.gltf"))


def test_a_thousand_failed_creations_release_everything(scene):
    rng = random.Random(5)
    resident = []
    for i in range(1000):
        raylab._fail_at_creation(rng.randint(1, 40))
        try:
            with pytest.raises(RuntimeError, match="VK_ERROR_OUT_OF_DEVICE_MEMORY|out of memory"):
                raylab.Renderer(scene, width=8, height=8, integrator="slides")
        finally:
            raylab._fail_at_creation(0)
        if i in (99, 999):
            resident.append(resident_mib())
    # Leaked device memory on lavapipe is host memory: 900 leaked scenes would add tens of MiB.
    assert resident[1] - resident[0] < 2.0, f"resident memory grew from {resident[0]:.1f} to {resident[1]:.1f} MiB"
    # The hook is off again: a renderer works.
    raylab.Renderer(scene, width=8, height=8, integrator="slides").render(1)


def test_renderers_made_and_dropped_keep_memory_flat(scene):
    # A leak grows with every renderer; the process also takes one step of about 6 MiB at some point in its first
    # few dozen renderers (an allocator arena; then flat for hundreds), which may fall in either interval. So of
    # two intervals of 20 renderers at least one must stay flat: a leak of 50 KiB a renderer would fail both.
    resident = []
    for i in range(50):
        renderer = raylab.Renderer(scene, width=8, height=8, integrator="slides")
        renderer.render(1)
        del renderer
        if i in (9, 29, 49):
            resident.append(resident_mib())
    growth = min(resident[1] - resident[0], resident[2] - resident[1])
    assert growth < 1.0, f"resident memory grew in both intervals: {[round(r, 1) for r in resident]} MiB"
