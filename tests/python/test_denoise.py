# raylab.denoise: Open Image Denoise (PyPI pyoidn) on raylab's images. A 4-spp render of the minimal scene, denoised,
# must come closer to a 512-spp render of it than the raw 4 spp do (clamped at 1 as displayed: measured 16x closer on
# 2026-12-05, asked here for 4x); its output is finite and of the colour's size; bad input names what was wrong;
# and without pyoidn the call says how to install it. Renderer.render(denoise=True) does the same with the albedo and
# normal the renderer accumulates, and leaves the raw image readable.
import sys

import numpy as np
import pytest

import raylab


@pytest.fixture(scope="module")
def renders(source_dir):
    scene = raylab.Scene.load(str(source_dir / "assets" / "scenes" / "minimal.gltf"))
    noisy = raylab.Renderer(scene, width=96, height=54, integrator="path").render(spp=4, seed=1)
    reference = raylab.Renderer(scene, width=96, height=54, integrator="path").render(spp=512, seed=2)
    return noisy, reference


def clamped_mse(image, reference):
    return float(np.mean((np.clip(image[..., :3], 0, 1) - np.clip(reference[..., :3], 0, 1)) ** 2))


def test_a_denoised_render_is_closer_to_the_converged_one(renders):
    noisy, reference = renders
    for quality in ("fast", "high"):
        denoised = raylab.denoise(noisy, quality=quality)
        assert denoised.shape == noisy.shape[:2] + (3,) and denoised.dtype == np.float32
        assert np.isfinite(denoised).all()
        raw, better = clamped_mse(noisy, reference), clamped_mse(denoised, reference)
        assert better < raw / 4, f"{quality}: denoised {better:.2e} against raw {raw:.2e}"


def test_auxiliary_images_are_taken_and_checked(renders):
    noisy, _ = renders
    albedo = np.full(noisy.shape[:2] + (3,), 0.5, np.float32)
    normal = np.zeros(noisy.shape[:2] + (3,), np.float32)
    normal[..., 2] = 1.0
    assert np.isfinite(raylab.denoise(noisy, albedo=albedo, normal=normal)).all()
    with pytest.raises(ValueError, match="normal image needs an albedo"):
        raylab.denoise(noisy, normal=normal)
    with pytest.raises(ValueError, match="albedo has shape"):
        raylab.denoise(noisy, albedo=albedo[:-1])


def test_bad_input_names_what_was_wrong(renders):
    noisy, _ = renders
    bad = noisy.copy()
    bad[3, 5, 1] = np.nan
    with pytest.raises(ValueError, match="color is not finite at row 3, column 5"):
        raylab.denoise(bad)
    with pytest.raises(ValueError, match="shape"):
        raylab.denoise(np.zeros((0, 4, 3), np.float32))
    with pytest.raises(ValueError, match="shape"):
        raylab.denoise(np.zeros((4, 4)))
    with pytest.raises(ValueError, match="quality 'ultra'"):
        raylab.denoise(noisy, quality="ultra")
    with pytest.raises(ValueError, match="not an image of numbers"):
        raylab.denoise([["a"]])


def test_without_pyoidn_it_says_how_to_install_it(renders, monkeypatch):
    noisy, _ = renders
    monkeypatch.setitem(sys.modules, "pyoidn", None)  # import pyoidn now raises ImportError
    with pytest.raises(RuntimeError, match="pip install -r tools/requirements.txt"):
        raylab.denoise(noisy)


@pytest.fixture(scope="module")
def minimal(source_dir):
    return raylab.Scene.load(str(source_dir / "assets" / "scenes" / "minimal.gltf"))


def test_renderer_render_denoises_with_its_own_albedo_and_normal(renders, minimal):
    noisy, reference = renders
    renderer = raylab.Renderer(minimal, width=96, height=54, integrator="path")
    denoised = renderer.render(spp=4, seed=1, denoise=True)
    assert denoised.shape == (54, 96, 4) and denoised.dtype == np.float32
    assert np.isfinite(denoised).all() and (denoised[..., 3] == 1).all()
    # The raw mean stays readable, the same bits as a render without denoising.
    assert np.array_equal(renderer.image(), noisy)
    raw, better = clamped_mse(noisy, reference), clamped_mse(denoised, reference)
    assert better < raw / 4, f"denoised {better:.2e} against raw {raw:.2e}"
    albedo, normal = renderer.auxiliary()
    assert albedo.shape == normal.shape == (54, 96, 4)
    assert (albedo[..., :3] >= 0).all() and (albedo[..., :3] <= 1).all()
    # A pixel's normal, averaged over its samples, is at most unit length, unit where it sees one smooth surface, and
    # zero where it sees only the background, whose albedo is then the background colour.
    length = np.linalg.norm(normal[..., :3], axis=2)
    assert (length <= 1 + 1e-5).all()
    hit, sky = length > 0.5, length == 0
    assert hit.mean() > 0.3 and np.median(length[hit]) > 0.999
    assert sky.mean() > 0.1 and np.allclose(albedo[sky][:, :3], [0.25, 0.3, 0.4])


def test_auxiliary_needs_the_images_and_a_bad_quality_is_named(minimal):
    renderer = raylab.Renderer(minimal, width=16, height=16)
    renderer.render(spp=1)
    with pytest.raises(ValueError, match="aovs=True"):
        renderer.auxiliary()
    with pytest.raises(ValueError, match="denoise-quality is fast, balanced or high, not 'ultra'"):
        renderer.render(spp=1, denoise=True, denoise_quality="ultra")
    assert raylab.Renderer(minimal, width=16, height=8, aovs=True).render(spp=1).shape == (8, 16, 4)


def test_renderers_in_threads_denoise_independently(minimal):
    import threading
    results, errors = {}, []

    def work(key, seed):
        try:
            results[key] = raylab.Renderer(minimal, width=32, height=24).render(spp=2, seed=seed, denoise=True)
        except Exception as error:  # reported below, with the thread's own exception
            errors.append(error)

    threads = [threading.Thread(target=work, args=(k, k)) for k in range(3)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert not errors, errors
    assert all(np.isfinite(image).all() and image.shape == (24, 32, 4) for image in results.values())


def test_renderer_without_pyoidn_refuses_before_rendering(minimal, monkeypatch):
    renderer = raylab.Renderer(minimal, width=16, height=16)
    monkeypatch.setitem(sys.modules, "pyoidn", None)
    with pytest.raises(RuntimeError, match="pyoidn"):
        renderer.render(spp=2, denoise=True)
    assert renderer.samples == 0
    assert renderer.render(spp=1).shape == (16, 16, 4)  # rendering without denoise never needs it
