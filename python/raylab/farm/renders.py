"""Any list of renders on a Dask cluster, and the camera path built on it: a turntable around the scene's camera
target. Each job is `raylab render` with the job's options, bit for bit: frame 0 of a turntable is the scene's own
camera, so it equals `raylab render SCENE` with the same size, samples and seed.

Scene files must be readable at the same path on every worker (a shared filesystem when workers are on other
machines); results come back to the client, which writes them."""
import hashlib
import math
import operator
import threading
from dataclasses import asdict, dataclass, field, replace
from pathlib import Path

from .. import _raylab

# The engine's render options (util/render_options.h): names, values, defaults and ranges, stated there once.
_OPTIONS = _raylab.render_options
from .jobs import FarmReport, Job, Stopwatch, farm

_device_lock = threading.Lock()  # one job at a time on the worker process's device


@dataclass(frozen=True)
class RenderJob:
    """One `raylab render`: the scene (a glTF path, or "" for the built-in scene), the EXR to write, and the
    options, named as raylab.Renderer names them. `camera` holds Scene.set_camera's keywords (position, target,
    up, fov_deg); `materials` maps material names to Scene.set_material's keywords."""
    out: str
    scene: str = ""
    width: int = 640
    height: int = 360
    spp: int = 16
    seed: int = 0
    integrator: str = _OPTIONS["integrator"]["default"]
    backend: str = _OPTIONS["backend"]["default"]
    guiding: str = _OPTIONS["guiding"]["default"]
    max_depth: int = _OPTIONS["max_depth"]["default"]
    env: str = ""
    camera: dict = field(default_factory=dict)
    materials: dict = field(default_factory=dict)
    # Also a tone-mapped PNG (clamp, exposure 0, as `raylab render --png`): at this path, or True for one beside
    # the EXR.
    png: bool | str = False

    def __post_init__(self):
        # `raylab render`'s ranges, checked where the job is made rather than on a worker after a cluster started.
        limits = _raylab.limits
        for name, low, high in (("width", 1, limits["max_image_side"]), ("height", 1, limits["max_image_side"]),
                                ("spp", 1, limits["max_spp"]), ("seed", 0, (1 << 32) - 1),
                                ("max_depth", _OPTIONS["max_depth"]["min"], _OPTIONS["max_depth"]["max"])):
            value = getattr(self, name)
            try:
                value = operator.index(value)  # int and NumPy integers; not float or bool-like strings
            except TypeError:
                value = None
            if value is None or isinstance(getattr(self, name), bool) or not low <= value <= high:
                raise ValueError(f"raylab.farm: {name} must be an integer in [{low}, {high}], "
                                 f"not {getattr(self, name)!r}")
            object.__setattr__(self, name, value)  # a plain int, so that descriptions compare equal
        for name in ("integrator", "backend", "guiding"):
            choices = _OPTIONS[name]["values"]
            if getattr(self, name) not in choices:
                raise ValueError(f"raylab.farm: {name} is {', '.join(choices)}, not {getattr(self, name)!r}")

    def description(self) -> str:
        """What decides the pixels, for the farm's manifest (the output path itself excluded)."""
        options = asdict(self)
        del options["out"], options["png"]
        return repr(sorted(options.items()))


def _scene_of(job: RenderJob, loaded=None):
    """The job's scene with its edits: loaded from its file, or `loaded` (a scene from the same file) edited."""
    scene = loaded if loaded is not None else _load(job)
    for name, edits in job.materials.items():
        scene.set_material(name, **edits)
    if job.camera:
        scene.set_camera(**job.camera)
    return scene


def _load(job: RenderJob):
    scene = _raylab.Scene.load(job.scene, env=job.env or None) if job.scene else _raylab.Scene.default()
    if job.env and not job.scene:
        scene.set_environment(job.env)
    return scene


def render_job(job: RenderJob):
    """A farm job, on a worker: the render the job describes."""
    with _device_lock:
        clock = Stopwatch()
        renderer = _raylab.Renderer(_scene_of(job), width=job.width, height=job.height, integrator=job.integrator,
                                    backend=job.backend, guiding=job.guiding, max_depth=job.max_depth)
        clock.setup_done()
        image = renderer.render(spp=job.spp, seed=job.seed)
        return image, clock.info()


def png_path(job: RenderJob) -> Path | None:
    """Where the job's PNG goes: its own path, beside the EXR (png=True), or nowhere."""
    if not job.png:
        return None
    return Path(job.out).with_suffix(".png") if job.png is True else Path(job.png)


def _png_writer(path: Path):
    return lambda image, exr: _raylab.write_png(str(path), image)


def renders(render_jobs: list[RenderJob], *, workers=None, scheduler=None, client=None, progress=True,
            label="raylab.farm renders") -> FarmReport:
    """Renders every job on a LocalCluster of `workers` processes, the scheduler at `scheduler`, or through
    `client`; a rerun skips the jobs whose EXR exists from a render with the same options."""
    if not render_jobs:
        return FarmReport()
    loaded = {}  # one load per scene file for the checks: a turntable's frames share theirs
    render_jobs = [_checked(render_jobs, index, loaded) for index in range(len(render_jobs))]
    jobs = []
    for job in render_jobs:
        out = Path(job.out)
        identity = hashlib.sha1(f"{out.resolve()}|{job.description()}".encode()).hexdigest()[:16]
        jobs.append(Job(key=f"raylab-render-{identity}", name=out.name, path=out, function=render_job, args=(job,),
                        samples=job.spp, description=job.description(),
                        png=_png_writer(png_path(job)) if job.png else None))
    if len({job.path.resolve() for job in jobs}) != len(jobs):
        raise ValueError("raylab.farm: two jobs write the same file")
    return farm(jobs, jobs[0].path.parent / "jobs.log", label, client=client, workers=workers, scheduler=scheduler,
                progress=progress)


def _checked(render_jobs: list[RenderJob], index: int, loaded: dict) -> RenderJob:
    """The job with its files as absolute paths (workers may run elsewhere), after the checks a worker would
    make, here, before any cluster starts: its scene loads and takes its edits (ValueError or FileNotFoundError
    naming the job otherwise)."""
    job = render_jobs[index]
    if Path(job.out).suffix != ".exr":
        raise ValueError(f"raylab.farm: job {index}: out '{job.out}' must end in .exr")
    absolute = replace(job, scene=str(Path(job.scene).resolve()) if job.scene else "",
                       env=str(Path(job.env).resolve()) if job.env else "")
    try:
        key = (absolute.scene, absolute.env)
        if key not in loaded:
            loaded[key] = _load(absolute)
        _scene_of(absolute, loaded[key])  # the edits, checked on the shared copy
    except (ValueError, FileNotFoundError, RuntimeError) as error:
        raise type(error)(f"raylab.farm: job {index} ({job.out}): {error}") from None
    return absolute


def _rotate(v, axis, angle):
    """v turned by `angle` radians about the unit vector `axis` (Rodrigues)."""
    c, s = math.cos(angle), math.sin(angle)
    dot = sum(a * b for a, b in zip(axis, v))
    cross = (axis[1] * v[2] - axis[2] * v[1], axis[2] * v[0] - axis[0] * v[2], axis[0] * v[1] - axis[1] * v[0])
    return tuple(v[i] * c + cross[i] * s + axis[i] * dot * (1 - c) for i in range(3))


# A turntable of 0.1 degree steps; more frames than this is a typo, not a film.
MAX_FRAMES = 3600


def turntable(scene: str, frames: int, out: str, *, target=None, **options) -> list[RenderJob]:
    """`frames` renders of `scene` as on a turntable: the camera carried round the vertical axis (+Y, glTF's up)
    through `target` by 360°/frames per frame, each frame's camera frame 0's turned rigidly (the horizon stays where
    it was). `target` (x, y, z) defaults to the centre of the scene's bounds, so the scene turns in place; frame 0
    is the scene's camera. `out` (FILE.exr) becomes FILE_000.exr, FILE_001.exr, ...; `options` are RenderJob's
    (width, height, spp, seed, ...)."""
    frames = operator.index(frames)
    if not 1 <= frames <= MAX_FRAMES:
        raise ValueError(f"raylab.farm turntable: --frames must be within 1..{MAX_FRAMES}, not {frames}")
    base = Path(out)
    if base.suffix != ".exr":
        raise ValueError(f"raylab.farm turntable: --out '{out}' must end in .exr")
    loaded = _raylab.Scene.load(scene) if scene else _raylab.Scene.default()
    camera = loaded.camera
    if target is None:
        low, high = loaded.bounds
        target = tuple(0.5 * (a + b) for a, b in zip(low, high))
    target = tuple(float(t) for t in target)
    if len(target) != 3 or not all(math.isfinite(t) for t in target):
        raise ValueError(f"raylab.farm turntable: --target must be three finite numbers x,y,z, not {target!r}")
    vertical = (0.0, 1.0, 0.0)

    def turned_point(point, angle):
        offset = tuple(p - t for p, t in zip(point, target))
        return tuple(t + o for t, o in zip(target, _rotate(offset, vertical, angle)))

    png = options.pop("png", False)
    if isinstance(png, str) and png and Path(png).suffix != ".png":
        raise ValueError(f"raylab.farm turntable: --png '{png}' must end in .png")
    jobs = []
    for frame in range(frames):
        angle = 2 * math.pi * frame / frames
        turned = {"position": turned_point(camera["position"], angle), "target": turned_point(camera["target"], angle),
                  "up": _rotate(camera["up"], vertical, angle)}
        frame_png = str(Path(png).with_name(f"{Path(png).stem}_{frame:03d}.png")) if isinstance(png, str) and png \
            else bool(png)
        jobs.append(RenderJob(out=str(base.with_name(f"{base.stem}_{frame:03d}.exr")), scene=scene,
                              camera={} if frame == 0 else turned, png=frame_png, **options))
    return jobs
