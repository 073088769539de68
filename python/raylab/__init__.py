"""raylab: an interactive ray tracer built around a library of analytic BRDFs, from Python.

    import raylab
    scene = raylab.Scene.load("assets/scenes/minimal.gltf")
    scene.set_material("red plastic", model="ward", alpha_x=0.2, alpha_y=0.2)
    image = raylab.Renderer(scene, width=320, height=180).render(spp=16)   # float32 (180, 320, 4)
    raylab.write_exr("out/ward.exr", image)
    f = raylab.brdf.eval("phong", {"s": 60}, wi=[[0, 0, 1]], wo=[[0.6, 0, 0.8]])

The module wraps the engine library, not the binary: the same kernels, the same results bit for bit as the
command line with the same options. Long calls release the GIL and stop on Ctrl-C between submissions. Errors are
ValueError (bad input), FileNotFoundError or RuntimeError (no device, a failed dispatch), with the command line's
messages. raylab.farm spreads studies over a Dask cluster (docs/farm.md).
"""
from ._raylab import (Cancelled, Renderer, Scene, __version__, brdf, devices, limits, read_exr,  # noqa: F401
                      read_png, render_options, write_exr, write_png)
from ._raylab import _fail_at_creation  # noqa: F401  (a test hook: tests/python/test_renderer_churn.py)
from .denoise import denoise  # noqa: F401  (Open Image Denoise through pyoidn, imported at its first call)

__all__ = ["Cancelled", "Renderer", "Scene", "__version__", "brdf", "denoise", "devices", "limits", "read_exr", "read_png",
           "render_options",
           "write_exr", "write_png"]
