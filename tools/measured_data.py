"""Real measured BRDF data for the study and tests (../shared/measured, README.md there): MERL phi_d = 90 slices,
their directions and bin weights, the error metrics of `raylab brdf fit` on them, and the published per-material
fits of Ngan et al. 2005, Löw et al. 2012 and Bagher et al. 2012 with their formulas written out (numpy) and, where
raylab's own models express them exactly, the mapping onto raylab's parameters (docs/measured.md, "Published fits").

Nothing here is committed data: every reader takes a path under ../shared/measured (or the user's copy), refuses
non-regular files and bounds what it reads.
"""
from __future__ import annotations

import math
import os
import re
import sys
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parent.parent
MEASURED = REPO.parent / "shared" / "measured"

SLICE_SIDE = 90
SLICE_BYTES = SLICE_SIDE * SLICE_SIDE * 3 * 4
MAX_THETA_DEG = 80.0          # engine/fit/fit_target.h kFitMaxThetaDegrees: grazing pairs are left out
MAX_FIT_FILE_BYTES = 16 << 20  # a published fit file is a few hundred kB


def import_raylab():
    """The raylab module: the one on the path (ctest's PYTHONPATH, .venv's raylab.pth), else this tree's release
    build. PYTHONPATH is set too, so that the Dask workers a tool starts import the same module and tools/."""
    paths = [str(REPO / "tools")]
    try:
        import raylab
    except ImportError:
        paths.insert(0, str(REPO / "build" / "release" / "python"))
        sys.path.insert(0, paths[0])
        import raylab
    os.environ["PYTHONPATH"] = os.pathsep.join(
        [p for p in [*paths, os.environ.get("PYTHONPATH", "")] if p])
    return raylab


class DataError(Exception):
    """A measured or published file that cannot be used, with the file and the reason."""


def read_bounded(path: Path, limit: int) -> bytes:
    path = Path(path)
    if not path.exists():
        raise DataError(f"{path}: no such file")
    if not path.is_file():
        raise DataError(f"{path}: not a regular file")
    with open(path, "rb") as file:
        data = file.read(limit + 1)
    if len(data) > limit:
        raise DataError(f"{path}: larger than {limit} bytes")
    return data


def read_slice(path: Path) -> np.ndarray:
    """A slice as float64 (90 theta_d rows, 90 theta_h columns, RGB), with raylab's checks (fit/merl_slice.h)."""
    data = read_bounded(path, SLICE_BYTES)
    if len(data) != SLICE_BYTES:
        raise DataError(f"{path}: holds {len(data)} bytes; a phi_d = 90 slice is 90 x 90 x RGB float32, "
                        f"{SLICE_BYTES} bytes")
    values = np.frombuffer(data, dtype="<f4").reshape(SLICE_SIDE, SLICE_SIDE, 3).astype(np.float64)
    bad = ~np.isfinite(values) | (values < 0)
    if bad.any():
        row, column, channel = (int(i[0]) for i in np.nonzero(bad))
        raise DataError(f"{path}: the value at theta_d row {row}, theta_h column {column}, "
                        f"{('red', 'green', 'blue')[channel]} is {values[row, column, channel]}")
    if not (values > 0).any():
        raise DataError(f"{path}: every value is zero")
    return values


def slice_angles(bin_position: str = "centre") -> tuple[np.ndarray, np.ndarray]:
    """theta_h, theta_d (radians) of every bin (90 x 90, rows theta_d) at its start or centre."""
    offset = {"centre": 0.5, "start": 0.0}[bin_position]
    u = (np.arange(SLICE_SIDE) + offset) / SLICE_SIDE
    theta_h = u * u * 0.5 * math.pi
    theta_d = (np.arange(SLICE_SIDE) + offset) / SLICE_SIDE * 0.5 * math.pi
    return np.meshgrid(theta_h, theta_d)


def slice_directions(bin_position: str = "centre") -> tuple[np.ndarray, np.ndarray]:
    """wi, wo (90 x 90 x 3) of every bin: Rusinkiewicz's (theta_h, theta_d, phi_d = 90 degrees), phi_h = 0."""
    th, td = slice_angles(bin_position)
    wi = np.stack([np.sin(th) * np.cos(td), np.sin(td), np.cos(th) * np.cos(td)], axis=-1)
    wo = np.stack([np.sin(th) * np.cos(td), -np.sin(td), np.cos(th) * np.cos(td)], axis=-1)
    return wi, wo


def slice_weights() -> np.ndarray:
    """Each bin's exact share of dwi dwo = 4 cos theta_d sin theta_d sin theta_h dtheta_h dtheta_d (sums to 2)."""
    u = np.arange(SLICE_SIDE + 1) / SLICE_SIDE
    h_edges = u * u * 0.5 * math.pi
    d_edges = u * 0.5 * math.pi
    along_h = np.cos(h_edges[:-1]) - np.cos(h_edges[1:])
    along_d = 2.0 * (np.sin(d_edges[1:]) ** 2 - np.sin(d_edges[:-1]) ** 2)
    return np.outer(along_d, along_h)


def kept(bin_position: str = "centre") -> np.ndarray:
    """The bins a fit uses: both directions within MAX_THETA_DEG of the normal."""
    wi, wo = slice_directions(bin_position)
    limit = math.cos(math.radians(MAX_THETA_DEG))
    return (wi[..., 2] > limit) & (wo[..., 2] > limit)


def slice_errors(model: np.ndarray, target: np.ndarray, bin_position: str = "centre") -> dict:
    """`raylab brdf fit`'s errors of f values `model` against `target` (both 90 x 90 x 3) on the kept bins:
    the weighted RMS of f cos(theta_i) differences (cosine) and of log(1 + f cos(theta_i)) differences (log), each
    also relative to the target's own RMS."""
    mask = kept(bin_position)
    wi, _ = slice_directions(bin_position)
    w = slice_weights()[mask]
    w = w / w.sum()
    cos = wi[..., 2][mask][:, None]
    t, m = target[mask], np.maximum(model[mask], 0.0)
    out = {}
    for name, r, r0 in (("cos", (t - m) * cos, t * cos), ("log", np.log1p(t * cos) - np.log1p(m * cos),
                                                          np.log1p(t * cos))):
        error = math.sqrt(float((w[:, None] * r * r).sum()) / 3.0)
        scale = math.sqrt(float((w[:, None] * r0 * r0).sum()) / 3.0)
        out[f"error_{name}"] = error
        out[f"relative_{name}"] = error / scale if scale > 0 else 0.0
    return out


# ---- published fits -------------------------------------------------------------------------------------------

_LINE = re.compile(r"^\s*([A-Za-z0-9_.\-]+)\s*=\s*Aggregate\(\s*Lambertian\(\s*albedo\s*=\s*(\[[^\]]*\])\s*\)\s*,\s*"
                   r"([A-Za-z]+)\((.*)\)\s*\)\s*$")
_PARAM = re.compile(r"([A-Za-z0-9_]+)\s*=\s*(\[\[[^\]]*\]\s*,\s*\[[^\]]*\]\]|\[[^\]]*\]|[-+0-9.eE]+)")


def _value(text: str):
    text = text.strip()
    if text.startswith("[["):
        return [_value(f"[{part}]") for part in re.findall(r"\[([^\[\]]*)\]", text)]
    if text.startswith("["):
        return [float(x) for x in text.strip("[]").split(",")]
    return float(text)


def read_bbm_fits(path: Path) -> dict[str, dict]:
    """A fits_bbm/*.fit file: material -> {"family", "lambert" (RGB albedo), "params"} (bsdfbenchmark/bbm's
    `Aggregate(Lambertian(albedo=...), Model(...))` lines)."""
    fits = {}
    for number, line in enumerate(read_bounded(path, MAX_FIT_FILE_BYTES).decode().splitlines(), 1):
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        match = _LINE.match(line)
        if not match:
            raise DataError(f"{path}:{number}: not an Aggregate(Lambertian(...), Model(...)) line")
        material, lambert, family, body = match.groups()
        params = {key: _value(value) for key, value in _PARAM.findall(body)}
        fits[material] = {"family": family, "lambert": np.array(_value(lambert)), "params": params}
    return fits


def read_dj_csv(path: Path) -> dict[str, dict]:
    """A fits_djbrdf/*.csv file: material -> column -> value."""
    lines = read_bounded(path, MAX_FIT_FILE_BYTES).decode().splitlines()
    header = lines[0].split(",")
    rows = {}
    for number, line in enumerate(lines[1:], 2):
        fields = line.split(",")
        if len(fields) != len(header):
            raise DataError(f"{path}:{number}: {len(fields)} fields, the header has {len(header)}")
        row = {}
        for key, value in zip(header, fields):
            try:
                row[key] = float(value)
            except ValueError:
                row[key] = value
        rows[str(row["name"])] = row
    return rows


def _rgb(value) -> np.ndarray:
    if np.ndim(value) == 0:
        return np.full(3, float(value))
    return np.asarray(value, dtype=np.float64).reshape(3)


def _frame(wi: np.ndarray, wo: np.ndarray):
    h = wi + wo
    h = h / np.linalg.norm(h, axis=-1, keepdims=True)
    cos_i, cos_o, cos_h = wi[..., 2], wo[..., 2], h[..., 2]
    cos_d = np.clip((wi * h).sum(-1), 0.0, 1.0)
    return h, cos_i, cos_o, np.clip(cos_h, 1e-12, 1.0), cos_d


def _vgroove(cos_h, cos_i, cos_o, cos_d):
    return np.minimum(1.0, np.minimum(2 * cos_h * cos_o / cos_d, 2 * cos_h * cos_i / cos_d))


def _fresnel_dielectric(cos_d, eta):
    """Unpolarised Fresnel reflectance of a dielectric of relative index eta at cos_d (Cook & Torrance 1982)."""
    c = cos_d
    g = np.sqrt(np.maximum(eta * eta - 1.0 + c * c, 0.0))
    a = (g - c) / (g + c)
    b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0)
    return 0.5 * a * a * (1.0 + b * b)


def published_f(family: str, lambert, params: dict, wi: np.ndarray, wo: np.ndarray) -> np.ndarray:
    """f (RGB, without the cosine) of a published fit at unit directions wi, wo (..., 3), from the formula of its
    family as bsdfbenchmark/bbm and dj_brdf state it (docs/measured.md lists each)."""
    h, cos_i, cos_o, cos_h, cos_d = _frame(wi, wo)
    tan2 = np.maximum(1.0 / (cos_h * cos_h) - 1.0, 0.0)
    diffuse = _rgb(lambert) / math.pi
    x = lambda value: _rgb(value)[None, :]  # noqa: E731
    col = lambda a: a[..., None]  # noqa: E731
    shape = cos_i.shape
    cos_i, cos_o, cos_h, cos_d, tan2 = (a.reshape(-1) for a in (cos_i, cos_o, cos_h, cos_d, tan2))
    if family in ("NganWard", "NganWardDuer"):
        a = params["roughness"]
        norm = np.sqrt(cos_i * cos_o) if family == "NganWard" else cos_i * cos_o
        spec = x(params["albedo"]) * col(np.exp(-tan2 / (a * a)) / (4 * math.pi * a * a * norm))
    elif family == "NganBlinnPhong":  # bbm: the modified Phong (Lafortune 1994) about the mirror direction
        n = params["sharpness"]
        r = np.stack([-wi[..., 0], -wi[..., 1], wi[..., 2]], -1).reshape(-1, 3)
        cos_a = np.clip((r * wo.reshape(-1, 3)).sum(-1), 0.0, 1.0)
        spec = x(params["albedo"]) * col((n + 2) / (2 * math.pi) * cos_a ** n)
    elif family == "NganLafortune":  # bbm: Lafortune 1997 eq. 4, Cx = Cy, times (n+2) / (2 pi max(|Cz|, |Cxy|)^n)
        n, cxy, cz = params["sharpness"], params["Cxy"], params["Cz"]
        a, b = wi.reshape(-1, 3), wo.reshape(-1, 3)
        d = cxy * (a[:, 0] * b[:, 0] + a[:, 1] * b[:, 1]) + cz * a[:, 2] * b[:, 2]
        spec = x(params["albedo"]) * col((n + 2) / (2 * math.pi) * (np.maximum(d, 0.0) / max(abs(cz), abs(cxy))) ** n)
    elif family == "NganCookTorrance":  # Beckmann, V-groove, Schlick with F0 = "eta", divided by pi cos cos
        m, f0 = params["roughness"], params["eta"]
        d = np.exp(-tan2 / (m * m)) / (math.pi * m * m * cos_h ** 4)
        f = f0 + (1 - f0) * (1 - cos_d) ** 5
        spec = x(params["albedo"]) * col(d * f * _vgroove(cos_h, cos_i, cos_o, cos_d) / (math.pi * cos_i * cos_o))
    elif family == "NganAshikhminShirley":  # isotropic, Schlick F0 = fresnelReflectance, scaled by albedo
        n, f0 = params["sharpness"], params["fresnelReflectance"]
        f = f0 + (1 - f0) * (1 - cos_d) ** 5
        spec = x(params["albedo"]) * col((n + 1) / (8 * math.pi) * cos_h ** n * f / (cos_d * np.maximum(cos_i, cos_o)))
    elif family == "LowMicrofacetFit":  # Löw 2012 ABC: A / (1 + B (1 - cos h))^C, V-groove, Fresnel, over pi cos cos
        d = 1.0 / (1.0 + params["B"] * (1.0 - cos_h)) ** params["C"]
        g = _vgroove(cos_h, cos_i, cos_o, cos_d)
        spec = x(params["A"]) * col(_fresnel_dielectric(cos_d, params["eta"]) * d * g / (math.pi * cos_i * cos_o))
    elif family == "LowSmooth":  # Löw 2012 smooth surface (bbm): A (1 + B |wi_xy + wo_xy|^2)^-C F(cos from |wi_xy - wo_xy|)
        a, b = wi.reshape(-1, 3), wo.reshape(-1, 3)
        projected_sum = ((a[:, :2] + b[:, :2]) ** 2).sum(1)
        cos_projected = np.sqrt(np.maximum(0.0, 1.0 - 0.25 * ((a[:, :2] - b[:, :2]) ** 2).sum(1)))
        spec = x(params["A"]) * col((1.0 + params["B"] * projected_sum) ** -params["C"] *
                                    _fresnel_dielectric(cos_projected, params["eta"]))
    elif family == "BagherSGD":  # dj_brdf's statement of Bagher et al. 2012, per channel
        spec = np.zeros((cos_i.size, 3))
        theta_i, theta_o = np.arccos(np.clip(cos_i, -1, 1)), np.arccos(np.clip(cos_o, -1, 1))
        for c in range(3):
            p = {k: params[k][c] for k in ("rhoS", "alpha", "p", "f0", "f1", "kap", "lambda", "c", "k", "theta0")}
            a = p["alpha"]
            d = p["kap"] * np.exp(-a - tan2 / a) / (math.pi * (a + tan2 / a) ** p["p"] * cos_h ** 4)
            f = p["f0"] - cos_d * p["f1"] + (1 - cos_d) ** 5 * (1 - p["f0"])
            g1 = lambda t: np.clip(1 + p["lambda"] * (1 - np.exp(p["c"] * np.maximum(0.0, t - p["theta0"]) ** p["k"])),  # noqa: E731
                                   0.0, 1.0)
            spec[:, c] = p["rhoS"] * f * d * g1(theta_i) * g1(theta_o) / (math.pi * cos_i * cos_o)
    else:
        raise DataError(f"no formula for the published family {family}")
    f = diffuse[None, :] + spec
    f[~((cos_i > 0) & (cos_o > 0))] = 0.0
    return f.reshape(*shape, 3)


def bagher_params(row: dict) -> tuple[np.ndarray, dict]:
    """A merl_sgd_bagher2012_fits.csv row as (Lambert albedo, published_f's BagherSGD params)."""
    params = {key: np.array([row[f"{key}_{c}"] for c in "rgb"]) for key in
              ("rhoS", "alpha", "p", "f0", "f1", "kap", "lambda", "c", "k", "theta0")}
    lambert = np.array([row[f"rhoD_{c}"] for c in "rgb"])
    return lambert, params


def low_abc_params(row: dict) -> tuple[np.ndarray, dict]:
    """A merl_abc_low2012_fits.csv row as (Lambert albedo: kD, published_f's LowMicrofacetFit params)."""
    return (np.array([row[f"kD_{c}"] for c in "rgb"]),
            {"A": [row[f"A_{c}"] for c in "rgb"], "B": row["B"], "C": row["C"], "eta": row["ior"]})


class NotExpressible(Exception):
    """A published fit that raylab's models cannot express exactly, with the reason."""


def raylab_material(family: str, lambert, params: dict) -> tuple[str, dict]:
    """The raylab model and parameters that equal a published fit exactly (docs/measured.md, "Published fits");
    NotExpressible with the reason otherwise."""
    rho_d = [float(v) for v in _rgb(lambert)]

    def within(name, value, lo, hi):
        values = value if isinstance(value, list) else [value]
        if not all(lo <= v <= hi for v in values):
            raise NotExpressible(f"{name} = {value} is outside raylab's range [{lo}, {hi}]")
        return value

    within("the Lambert albedo", rho_d, 0.0, 1.0)
    if family in ("NganWard", "NganWardDuer"):
        a = within("roughness", params["roughness"], 0.001, 1.0)
        return ("ward" if family == "NganWard" else "ward_duer",
                {"rho_d": rho_d, "rho_s": within("albedo", params["albedo"], 0.0, 1.0), "alpha_x": a, "alpha_y": a})
    if family == "NganBlinnPhong":
        return "phong", {"rho_d": rho_d, "rho_s": within("albedo", params["albedo"], 0.0, 1.0),
                         "s": within("sharpness", params["sharpness"], 1.0, 10000.0)}
    if family == "NganCookTorrance":
        f0 = params["eta"]
        if not 0.0 <= f0 < 1.0:
            raise NotExpressible(f"F0 = {f0} is not a reflectance")
        eta = (1 + math.sqrt(f0)) / (1 - math.sqrt(f0))
        rho_s = [4.0 / math.pi * v for v in _rgb(params["albedo"])]
        return "cooktorrance", {"rho_d": rho_d, "rho_s": within("4 albedo / pi", rho_s, 0.0, 1.0),
                                "m": within("roughness", params["roughness"], 0.001, 1.0),
                                "eta": within("eta from F0", eta, 1.0, 10.0)}
    if family == "NganLafortune":
        albedo = [float(v) for v in _rgb(params["albedo"])]
        return "lafortune", {"rho_d": rho_d, "rho_s": within("albedo", albedo, 0.0, 2.0),
                             "cx": within("Cxy", params["Cxy"], -1.0, 1.0), "cy": params["Cxy"],
                             "cz": within("Cz", params["Cz"], -1.0, 1.0),
                             "n": within("sharpness", params["sharpness"], 1.0, 20000.0), "rho_s2": [0.0, 0.0, 0.0]}
    if family == "NganAshikhminShirley":
        raise NotExpressible("raylab's ashikhmin_shirley has the paper's coupled diffuse term (28/23 (1 - Rs) ...) "
                             "and no specular scale; Ngan's has a Lambert term and a scale")
    if family == "LowMicrofacetFit":
        return "abc_microfacet", {"rho_d": rho_d, "a": within("A", [float(v) for v in _rgb(params["A"])], 0.0, 1e5),
                                  "b": within("B", float(params["B"]), 1.0, 1e8),
                                  "c": within("C", float(params["C"]), 0.01, 4.0),
                                  "ior": within("eta", float(params["eta"]), 1.0, 100.0)}
    if family == "LowSmooth":
        return "abc_smooth", {"rho_d": rho_d, "a": within("A", [float(v) for v in _rgb(params["A"])], 0.0, 1e5),
                              "b": within("B", float(params["B"]), 1.0, 1e8), "c": within("C", float(params["C"]), 0.01, 4.0),
                              "ior": within("eta", float(params["eta"]), 1.0, 100.0)}
    if family == "Bagher":  # bbm's names for the same fits as dj_brdf's BagherSGD
        family, params = "BagherSGD", {"rhoS": params["albedo"], "alpha": params["alpha"], "p": params["p"],
                                       "f0": params["eta"][0], "f1": params["eta"][1], "kap": params["K"],
                                       "lambda": params["Lambda"], "c": params["c"], "k": params["k"],
                                       "theta0": params["theta0"]}
    if family == "BagherSGD":
        rgb = {key: [float(v) for v in _rgb(params[key])] for key in params}
        return "sgd", {"rho_d": rho_d, "rho_s": within("rhoS kap", [s * k for s, k in zip(rgb["rhoS"], rgb["kap"])],
                                                       0.0, 1e6),
                       "alpha": within("alpha", rgb["alpha"], 1e-6, 1.0), "p": within("p", rgb["p"], 0.0, 2.0),
                       "f0": within("f0", rgb["f0"], 0.0, 10.0), "f1": within("f1", rgb["f1"], -1.0, 10.0),
                       "lambda": within("lambda", rgb["lambda"], 0.0, 1e8), "c": within("c", rgb["c"], 0.0, 1e38),
                       "k": within("k", rgb["k"], 0.1, 1000.0), "theta0": within("theta0", rgb["theta0"], -1.0, 1.5)}
    raise NotExpressible(f"raylab has no model of the family {family} (issue: the measured-BRDF models)")


# How each published family maps onto a raylab model (bbm's ngan.h and dj_brdf's conventions), for the docs; keyed by
# the label of published_fits().
MAPPINGS = {
    "Ngan ward": "`ward`: rho_d = the Lambert albedo, rho_s = albedo, alpha_x = alpha_y = roughness",
    "Ngan ward_duer": "`ward_duer`: as Ward",
    "Ngan phong": "`phong` (bbm reads Ngan's Blinn-Phong as the modified Phong about the mirror direction): "
                  "rho_s = albedo, s = sharpness",
    "Ngan cooktorrance": "`cooktorrance`: rho_s = 4 albedo / pi (Cook's 1/(pi cos cos) against raylab's "
                         "1/(4 cos cos)), eta = (1 + sqrt F0) / (1 - sqrt F0) from Schlick's F0 (bbm's \"eta\"), m = roughness",
    "Ngan ashikhmin_shirley": "none: raylab's `ashikhmin_shirley` is the paper's whole model",
    "Ngan lafortune": "`lafortune` (one lobe, Ngan's normalisation (n+2)/(2 pi max|C|^n)): rho_s = albedo, "
                      "cx = cy = Cxy, cz = Cz, n = sharpness, rho_s2 = 0",
    "Löw smooth": "`abc_smooth` (bbm's LowSmooth form): rho_d = the Lambert albedo, a = A, b = B, c = C, ior = eta",
    "Löw ABC": "`abc_microfacet` (the fits' own form, with their 1/pi): rho_d = kD, a = A, b = B, c = C, ior = ior",
    "Bagher SGD": "`sgd` (dj_brdf's form; F clamped at 0): rho_d = rhoD, rho_s = rhoS kap, the other ten by name "
                  "(lambda = Lambda, f0 and f1 = bbm's eta pair)",
}

# The raylab model of each published family that is not Ngan's (his are keyed by that model), for the comparison of
# raylab's fit of a family with the published one.
FAMILY_MODELS = {"Löw smooth": "abc_smooth", "Löw ABC": "abc_microfacet", "Bagher SGD": "sgd"}

# The published families of the study: (label, file, reader) in the order of docs/measured.md.
NGAN_FAMILIES = {
    "ward": ("NganWard", "fits_bbm/ngan_ward.fit"),
    "ward_duer": ("NganWardDuer", "fits_bbm/ngan_wardduer.fit"),
    "phong": ("NganBlinnPhong", "fits_bbm/ngan_blinnphong.fit"),
    "cooktorrance": ("NganCookTorrance", "fits_bbm/ngan_cooktorrance.fit"),
    "ashikhmin_shirley": ("NganAshikhminShirley", "fits_bbm/ngan_ashikhminshirley.fit"),
    "lafortune": ("NganLafortune", "fits_bbm/ngan_lafortune.fit"),
}


def published_fits(measured: Path = MEASURED) -> dict[str, dict[str, tuple]]:
    """label -> material -> (family, lambert, params) of every published fit with a formula here: Ngan's five
    families that raylab has a model of (keyed by that raylab model), Löw's smooth-surface and ABC models and Bagher's
    SGD."""
    out: dict[str, dict[str, tuple]] = {}
    for model, (family, relative) in NGAN_FAMILIES.items():
        out[f"Ngan {model}"] = {m: (fit["family"], fit["lambert"], fit["params"])
                               for m, fit in read_bbm_fits(measured / relative).items()}
    out["Löw smooth"] = {m: (fit["family"], fit["lambert"], fit["params"])
                         for m, fit in read_bbm_fits(measured / "fits_bbm/low_lowsmooth_E2.fit").items()}
    out["Löw ABC"] = {m: ("LowMicrofacetFit", *low_abc_params(row))
                      for m, row in read_dj_csv(measured / "fits_djbrdf/merl_abc_low2012_fits.csv").items()}
    out["Bagher SGD"] = {m: ("BagherSGD", *bagher_params(row))
                         for m, row in read_dj_csv(measured / "fits_djbrdf/merl_sgd_bagher2012_fits.csv").items()}
    return out
