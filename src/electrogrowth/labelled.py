"""Results as labelled arrays: ``xarray.Dataset`` with units and descriptions in attributes.

The ``to_xarray()`` methods of :class:`~electrogrowth.UniformState`,
:class:`~electrogrowth.LayeredState`, :class:`~electrogrowth.ScanResult` and
:class:`~electrogrowth.Curve` call the functions here. Every variable carries ``units`` (in
the package's units mu = eps = R_i = 1: "R_i", "mu", ...; "1" for a pure number; a control
or key by :func:`parameter`, the one table a sweep's store reads too) and
``long_name``; the dataset's attributes hold the tube, the material and what was solved
for, and contain no None (so it saves to netCDF as well as to Zarr). xarray (the ``sweep``
extra) is imported inside each function. Shared by every stage: imports no stage, reads
the results by their attributes.
"""

from __future__ import annotations

import math

import numpy as np

from .errors import MissingDependencyError

#: variable -> (units, long name); units in the package's scales mu = eps = R_i = 1
VARIABLES = {
    "R": ("R_i", "reference (undeformed) radius R"),
    "r": ("R_i", "current radius r(R)"),
    "lambda": ("1", "hoop stretch r / R"),
    "sigma_rr": ("mu", "radial Cauchy stress sigma_rr"),
    "sigma_tt": ("mu", "hoop Cauchy stress sigma_tt (theta-theta)"),
    "sigma_zz": ("mu", "axial Cauchy stress sigma_zz"),
    "p": ("mu", "Lagrange multiplier p (hydrostatic pressure)"),
    "D_r": ("sqrt(mu eps)", "radial electric displacement D_r = c / r"),
    "E_r": ("sqrt(mu / eps)", "radial electric field E_r"),
    "layer": ("1", "layer index, from the inside (0 = innermost)"),
    "m": ("1", "circumferential wavenumber m (-1: no finite mode)"),
    "n": ("1", "axial half-wavenumber n, k = n pi / (lambda_z L) (-1: no finite mode)"),
    "family": ("1", "mode family: wrinkle, prismatic (n = 0) or torsional (m = 0)"),
    "kind": ("1", "bifurcation, threshold, surface, switch or failed"),
    "surface": ("1", "1 where the critical point is the exact short-wave limit"),
    "surface_face": ("1", "where the short-wave limit wrinkles (inner, outer, interface-K)"),
    "status": ("1", "ok, inaccurate, or why a point failed"),
}
#: the unit and name of each control / tube parameter
PARAMETERS = {
    "growth": ("1", "isotropic growth factor g"),
    "stretch": ("1", "axial stretch lambda_z = l / L"),
    "voltage": (
        "1",
        "Vbar = V / (R_o - R_i) sqrt(eps / mu); V = Vbar (Rbar_o - 1) R_i sqrt(mu / eps)",
    ),
    "outer_radius": ("R_i", "undeformed outer radius Rbar_o = R_o / R_i"),
    "length": ("R_i", "undeformed length L / R_i"),
    "pressure": ("mu", "inner follower pressure P_i / mu"),
    "inner_pressure": ("mu", "inner follower pressure P_i / mu"),
    "outer_pressure": ("mu", "outer follower pressure P_o / mu"),
    "force": ("mu R_i^2", "axial end force F / (mu R_i^2)"),
}
#: the units of a layer's keys layers[K].<field>
LAYER_UNITS = {
    "outer_radius": "R_i",
    "thickness": "R_i",
    "shear_modulus": "mu",
    "permittivity": "eps",
}


def parameter(name: str) -> tuple[str, str]:
    """(units, long name) of a control or tube key, in the package's scales mu = eps = R_i =
    1 ("1": a pure number): a layer's growth ``growth[K]``, ``growth[K].theta`` is a
    growth factor, ``layers[K].thickness`` a length; one table for every record (a
    curve's, a scan's, a sweep store's values and axes)."""
    if name in PARAMETERS:
        return PARAMETERS[name]
    field = name.rsplit(".", 1)[-1]
    if name.startswith("layers[") and field in LAYER_UNITS:
        return LAYER_UNITS[field], name
    kind = name.split("[")[0].split(".")[0]
    return (PARAMETERS[kind][0] if kind in PARAMETERS else "1"), name


#: a parameter's axis in a store (a sweep's, a design map's): (description, symbol)
AXES = {
    "outer_radius": ("outer radius", "R̄ₒ = Rₒ/Rᵢ"),
    "length": ("length", "L/Rᵢ"),
    "growth": ("growth factor", "g"),
    "stretch": ("axial stretch", "λ_z"),
    "voltage": ("voltage", "V̄"),
    "pressure": ("inner pressure", "P_i"),
    "force": ("axial force", "F"),
}


def axis_label(name: str) -> tuple[str, str]:
    """(description, symbol) of a parameter; a layered tube's control or key as itself."""
    return AXES.get(name, (name, name))


def axis_attrs(name: str) -> dict:
    """The attributes of a parameter's axis in a store: long_name, symbol, units."""
    long_name, symbol = axis_label(name)
    return {"long_name": long_name, "symbol": symbol, "units": parameter(name)[0]}


def xarray():
    """The xarray module, or MissingDependencyError naming the extra."""
    try:
        import xarray
    except ImportError:
        raise MissingDependencyError(
            "to_xarray needs the optional package xarray; install it with"
            " pip install 'electrogrowth[sweep]'"
        ) from None
    return xarray


def _attrs(name: str, **extra) -> dict:
    units, long_name = VARIABLES.get(name) or parameter(str(name))
    return {"units": units, "long_name": long_name, **extra}


def clean(attrs: dict) -> dict:
    """Attributes netCDF can store: None dropped, infinities as strings, bools as ints,
    lists of numbers kept, lists of strings joined by "; "."""
    out = {}
    for key, value in attrs.items():
        if value is None:
            continue
        if isinstance(value, bool) or isinstance(value, np.bool_):
            value = int(value)
        elif isinstance(value, float) and not math.isfinite(value):
            value = str(value)
        elif isinstance(value, (tuple, list)):
            strings = any(isinstance(v, str) for v in value)
            value = "; ".join(map(str, value)) if strings else list(value)
        elif not isinstance(value, (int, float, str, np.integer, np.floating)):
            value = str(value)
        out[key] = value
    return out


def _tube_attrs(params) -> dict:
    """The tube's numbers (:meth:`Tube.record`)."""
    return params.record()


def base_state_dataset(state, points: int = 101):
    """Profiles of a uniform state (UniformState) on ``points`` radii R (dimension R)."""
    xr = xarray()
    prof = state.profiles(points)
    R = prof.pop("R")
    ds = xr.Dataset(
        {k: ("R", v, _attrs(k)) for k, v in prof.items()},
        coords={"R": ("R", R, _attrs("R"))},
    )
    ds.attrs = clean(
        {
            "title": "axisymmetric base state of a grown, stretched, charged tube",
            "units": "mu = eps = R_i = 1",
            **_tube_attrs(state.tube),
            "lambda_i": state.lambda_i,
            "lambda_o": state.lambda_o,
            "r_i": state.r_i,
            "r_o": state.r_o,
            "charge": state.charge,
            "voltage_threshold": state.voltage_threshold,
            "threshold_kind": state.threshold_kind,
            "axial_force": state.axial_force,
            "quadrature_error": state.quadrature_error,
        }
    )
    return ds


def layered_state_dataset(state, points: int = 101):
    """Profiles of a LayeredState (dimension point; an interface appears twice, once per
    side; R and layer are coordinates)."""
    xr = xarray()
    prof = state.profiles(points)
    coords = {k: ("point", prof.pop(k), _attrs(k)) for k in ("R", "layer")}
    ds = xr.Dataset({k: ("point", v, _attrs(k)) for k, v in prof.items()}, coords=coords)
    tube = state.tube
    ds.attrs = clean(
        {
            "title": "axisymmetric base state of a layered tube",
            "units": "mu = eps = R_i = 1 (mu, eps of the reference the layers are relative to)",
            "layers": len(tube.layers),
            "layer_outer_radii": [float(x) for x in tube.radii[1:]],
            "materials": [layer.material.name for layer in tube.layers],
            "voltage": tube.voltage,
            "inner_pressure": tube.inner_pressure,
            "outer_pressure": tube.outer_pressure,
            "lambda_i": state.lambda_i,
            "lambda_o": state.lambda_o,
            "stretch": state.stretch,
            "interface_radii": [float(x) for x in state.radii],
            "charge": state.charge,
            "axial_force": state.axial_force,
            "end_force": state.end_force,
            "voltage_threshold": state.voltage_threshold,
            "threshold_kind": state.threshold_kind,
        }
    )
    return ds


def scan_dataset(result):
    """A ScanResult: the critical point and the runners-up along dimension rank (0 = the
    critical point)."""
    xr = xarray()
    c = result.critical
    rows = [(c.m, c.n, str(c.family or ""), c.value)] + [
        (r.m, r.n, str(r.family or ""), r.value) for r in result.runners_up
    ]
    m, n, family, value = (list(col) for col in zip(*rows))
    name = f"{c.solve_for}_cr"
    ds = xr.Dataset(
        {
            name: ("rank", np.array(value, float), _critical_attrs(c.solve_for)),
            "m": ("rank", np.array(m, int), _attrs("m")),
            "n": ("rank", np.array(n, int), _attrs("n")),
            "family": ("rank", np.array(family, str), _attrs("family")),
        },
        coords={
            "rank": ("rank", np.arange(len(rows)), {"long_name": "0 = critical, then runners-up"})
        },
    )
    ds.attrs = clean(
        {
            "title": f"critical {c.solve_for} over the modes (m, n)",
            "units": "mu = eps = R_i = 1",
            "solve_for": c.solve_for,
            "side": c.side,
            "kind": str(c.kind),
            "error_estimate": c.error_estimate,
            "method": c.method,
            "face": c.face,
            "psi": c.psi,
            "m_range": list(result.m_range),
            "n_range": list(result.n_range),
            "surface_instability": result.surface_instability,
            "short_wave_limit": result.short_wave_limit,
            "short_wave_error": result.short_wave_error,
            **{f"tube_{k}": v for k, v in _tube_attrs(c.params).items()},
        }
    )
    return ds.assign(verdict_variables(result.verdict, c.solve_for))


#: the kinds of a verdict, along dimension rival, and their field on the Verdict
RIVAL_KINDS = (
    ("bifurcation", "wrinkle"),
    ("surface", "surface"),
    ("crease", "crease"),
    ("threshold", "threshold"),
)


def verdict_variables(v, solve_for: str) -> dict:
    """A Verdict (bifurcation/verdict.py) as variables: what comes first (``verdict``,
    ``verdict_value``, ``verdict_face``, ``meaning``), each kind's value and face along
    dimension rival (NaN and "" where that kind was not found), the slot ``branch`` (""
    not computed) and ``koiter`` (NaN)."""
    rivals = [getattr(v, key) for _, key in RIVAL_KINDS]
    units, long_name = parameter(solve_for)
    text = lambda long: {"units": "1", "long_name": long}  # noqa: E731
    return {
        "verdict": (
            (),
            str(v.kind),
            text("what comes first: " + ", ".join(k for k, _ in RIVAL_KINDS)),
        ),
        "verdict_value": (
            (),
            float(v.value),
            {"units": units, "long_name": f"{long_name} where it comes"},
        ),
        "verdict_face": ((), v.face or "", text("the face of a crease or surface instability")),
        "meaning": ((), v.meaning, text("the verdict in one line")),
        "rival_value": (
            "rival",
            np.array([np.nan if r is None else r.value for r in rivals], float),
            {"units": units, "long_name": f"{long_name} of each kind (NaN: not found)"},
        ),
        "rival_face": (
            "rival",
            np.array([(r and r.face) or "" for r in rivals], str),
            text("face"),
        ),
        "rival": (
            "rival",
            np.array([k for k, _ in RIVAL_KINDS], str),
            text("kind of instability"),
        ),
        "crease_criterion": ((), v.criterion or "", text("the crease criterion applied")),
        "branch": ((), v.branch or "", text("supercritical | subcritical | '' (not computed)")),
        "koiter": (
            (),
            np.nan if v.koiter is None else float(v.koiter),
            text("Koiter coefficient (NaN: not computed)"),
        ),
        "koiter_error": (
            (),
            np.nan if v.koiter_error is None else float(v.koiter_error),
            text("the Koiter coefficient's change from a coarser mesh (NaN: not computed)"),
        ),
        **_resonance(v.koiter_resonance, units, long_name),
    }


def _resonance(r: dict | None, units: str, long_name: str) -> dict:
    """The second harmonic bifurcating next to onset, or the mode restabilising past it,
    where the Koiter coefficient has a pole (bifurcation/koiter_resonance.py): its value and
    (m, n); NaN and -1 where none."""
    none = r is None
    return {
        "koiter_resonance_value": (
            (),
            np.nan if none else float(r["value"]),
            {
                "units": units,
                "long_name": f"{long_name} where a second harmonic bifurcates"
                " next to onset, or the mode restabilises (NaN: none)",
            },
        ),
        "koiter_resonance_m": (
            (),
            -1 if none else int(r["m"]),
            {"units": "1", "long_name": "m of that harmonic, or of the mode (-1: none)"},
        ),
        "koiter_resonance_n": (
            (),
            -1 if none else int(r["n"]),
            {"units": "1", "long_name": "n of that harmonic, or of the mode (-1: none)"},
        ),
    }


def _critical_attrs(solve_for: str) -> dict:
    units, long_name = parameter(solve_for)
    return {"units": units, "long_name": f"critical {long_name}"}


def _switch_columns(curve) -> dict:
    """The located switches' numbers along dimension switch: x, the critical value, and
    their error estimates."""
    x_attrs, v_attrs = _attrs(curve.along), _critical_attrs(curve.solve_for)
    columns = (
        ("x", x_attrs, f"{curve.along} at a mode switch"),
        ("value", v_attrs, "critical value at the switch"),
        ("x_error", x_attrs, f"error estimate of {curve.along} there"),
        ("value_error", v_attrs, "error estimate of the critical value at the switch"),
    )
    return {
        f"switch_{field}": (
            "switch",
            np.array([getattr(s, field) for s in curve.switches], float),
            {**attrs, "long_name": name},
        )
        for field, attrs, name in columns
    }


def _ends(curve) -> dict:
    """The located branch ends of a curve: x, the one-sided values, the modes either side."""
    ends = getattr(curve, "ends", ())
    return {
        "end_x": (
            "end",
            np.array([e.x for e in ends], float),
            {**_attrs(curve.along), "long_name": f"{curve.along} where a branch ends"},
        ),
        "end_value": (
            "end",
            np.array([e.value for e in ends], float),
            {**_critical_attrs(curve.solve_for), "long_name": "critical value where it ends"},
        ),
        "end_value_after": (
            "end",
            np.array([e.value_after for e in ends], float),
            {**_critical_attrs(curve.solve_for), "long_name": "critical value just after"},
        ),
        "end_x_error": (
            "end",
            np.array([e.x_error for e in ends], float),
            {**_attrs(curve.along), "long_name": f"error estimate of {curve.along} there"},
        ),
        "end_mode_before": (
            ("end", "mode"),
            np.array([e.mode_before for e in ends], int).reshape(-1, 2),
            {"units": "1", "long_name": "(m, n) of the branch that ends"},
        ),
        "end_mode_after": (
            ("end", "mode"),
            np.array([e.mode_after for e in ends], int).reshape(-1, 2),
            {"units": "1", "long_name": "(m, n) after it, (-1, -1): threshold or short waves"},
        ),
    }


def _crease_points(curve) -> dict:
    """The crease at each point of a curve (bifurcation/curve_crease.py)."""
    c = curve.crease
    value = {**_critical_attrs(curve.solve_for), "long_name": "where a face creases"}
    text = lambda what: {"units": "1", "long_name": what}  # noqa: E731
    return {
        "crease_value": ("point", np.asarray(c.value, float), value),
        "crease_face": ("point", np.asarray(c.face, str), text("the face that creases")),
        "crease_trigger": (
            "point",
            np.asarray(c.trigger, str),
            text("prismatic | axial | field: what drives the crease"),
        ),
        "crease_error": (
            "point",
            np.asarray(c.error, float),
            {**value, "long_name": "the crease value's spread over the criterion's accuracy"},
        ),
        "crease_first": (
            "point",
            np.asarray(c.first, int),
            text("1: the crease comes before the critical value (the wrinkle)"),
        ),
    }


def curve_dataset(curve):
    """A Curve along dimension point (a switch appears twice, at the same x: the end of one
    branch and the start of the next; x is the coordinate named after ``along``), its
    located switches along dimension switch and the located ends of branches (a jump of the
    critical value, or the threshold after the branch) along dimension end."""
    xr = xarray()
    name = f"{curve.solve_for}_cr"
    ds = xr.Dataset(
        {
            name: ("point", np.asarray(curve.value, float), _critical_attrs(curve.solve_for)),
            "m": ("point", np.asarray(curve.m, int), _attrs("m")),
            "n": ("point", np.asarray(curve.n, int), _attrs("n")),
            "kind": ("point", np.asarray(curve.kind, str), _attrs("kind")),
            "surface": ("point", np.asarray(curve.surface, int), _attrs("surface")),
            "surface_face": ("point", np.asarray(curve.surface_face, str), _attrs("surface_face")),
            "short_wave_limit": (
                "point",
                np.asarray(curve.short_wave_limit, float),
                {**_critical_attrs(curve.solve_for), "long_name": "exact short-wave limit"},
            ),
            "status": ("point", np.asarray(curve.status, str), _attrs("status")),
            **_crease_points(curve),
            **_switch_columns(curve),
            "switch_mode_before": (
                ("switch", "mode"),
                np.array([s.mode_before for s in curve.switches], int).reshape(-1, 2),
                {"units": "1", "long_name": "(m, n) before the switch, (-1, -1): threshold"},
            ),
            "switch_mode_after": (
                ("switch", "mode"),
                np.array([s.mode_after for s in curve.switches], int).reshape(-1, 2),
                {"units": "1", "long_name": "(m, n) after the switch, (-1, -1): threshold"},
            ),
            **_ends(curve),
        },
        coords={curve.along: ("point", np.asarray(curve.x, float), _attrs(curve.along))},
    )
    ds.attrs = clean(
        {
            "title": f"critical {curve.solve_for} along {curve.along}, mode switches located",
            "units": "mu = eps = R_i = 1",
            "solve_for": curve.solve_for,
            "along": curve.along,
            "side": curve.side,
            **{f"tube_{k}": v for k, v in _tube_attrs(curve.params).items()},
        }
    )
    return ds
