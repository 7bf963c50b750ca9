"""``electrogrowth curve``'s summary in words: what each branch is (a mode, the exact
short-wave limit at its face, the threshold) and where the crease criterion lies."""

import math

import numpy as np
import pytest

from electrogrowth import Tube
from electrogrowth.bifurcation.curve_crease import CreaseAlong
from electrogrowth.bifurcation.curve_record import Curve, CurvePoint, point_of, point_record
from electrogrowth.bifurcation.curves import curve_point
from electrogrowth.bifurcation.scan import ScanOptions
from electrogrowth.bifurcation.surface import short_wave_limit
from electrogrowth.cli.curve import crease_line, summary


def _curve(values, *, m=None, kind=None, surface=None, faces=None, crease=None, **kw):
    """A curve of ``stretch`` along ``outer_radius`` with the rows given (m = n = -1: no
    finite mode, the short-wave limit where ``surface``)."""
    rows = len(values)
    m = np.array(m if m is not None else [-1] * rows)
    surface = np.array(surface if surface is not None else [True] * rows, bool)
    kind = kind or ["surface" if s else "threshold" if k < 0 else "bifurcation"
                    for s, k in zip(surface, m)]  # fmt: skip
    defaults = {"solve_for": "stretch", "side": "extension"}
    return Curve(
        "outer_radius",
        kw.get("solve_for", defaults["solve_for"]),
        kw.get("side", defaults["side"]),
        np.linspace(1.2, 1.4, rows),
        np.array(values, float),
        m,
        np.where(m < 0, -1, 1),
        np.array(kind),
        ("",) * rows,
        (),
        Tube.uniform(1.2, voltage=0.4),
        surface,
        np.where(surface, values, math.nan),
        crease=crease,
        surface_face=tuple(faces or [("outer" if s else "") for s in surface]),
    )


def _field(values, face="inner", first=False):
    rows = len(values)
    return CreaseAlong(
        np.array(values, float),
        (face,) * rows,
        ("field",) * rows,
        np.full(rows, 0.007),
        np.full(rows, first, bool),
    )


def test_a_surface_branch_is_the_exact_short_wave_limit_at_its_face():
    """Check round 29, D2: `curve` called the short-wave limit (kind surface, m = n = -1)
    "threshold (axisymmetric state lost) at the mode cap". It is the exact half-space
    limit, at the outer face (as `critical` says), and a threshold after it stays one: a
    branch of its own."""
    curve = _curve([2.4668, 2.4562, 2.45], surface=[True, True, False])
    assert [mode for mode, _ in curve.branches()] == [(-1, -1), (-1, -1)]
    text = "\n".join(summary(curve))
    assert "mode cap" not in text
    assert (
        "1.2 .. 1.3: short-wave (surface) instability, the exact limit m, n -> infinity," in text
    )
    assert "at the outer face" in text
    assert "1.4 .. 1.4: threshold (axisymmetric state lost)" in text
    assert "surface) instability" not in text.split("1.4 .. 1.4")[1]


def test_the_limit_at_two_faces_is_two_branches():
    curve = _curve([2.1, 2.2], faces=["inner", "outer"])
    lines = summary(curve)
    assert any(line.endswith("at the inner face") for line in lines)
    assert any(line.endswith("at the outer face") for line in lines)


@pytest.mark.parametrize(
    ("side", "values", "crease", "when"),
    [
        ("extension", [2.4668, 2.4562], [2.3194, 2.2996], "before"),  # check round 29
        ("extension", [2.1, 2.2], [2.3194, 2.2996], "after"),
        ("compression", [0.6, 0.62], [0.7, 0.71], "before"),  # compression lowers it
        ("compression", [0.8, 0.82], [0.7, 0.71], "after"),
    ],
)
def test_the_field_criterion_is_an_early_bound_before_or_after_along_the_control(
    side, values, crease, when
):
    """Check round 29, D3: with the field criterion reached at lambda_z = 2.30 .. 2.32,
    before the short-wave instability at 2.46 (extension raises lambda_z), `curve` said "a
    face creases later". It is compared along the control's direction and worded as
    `critical` words it: the field reaches the electro-creasing field, an early bound."""
    curve = _curve(values, side=side, crease=_field(crease))
    line = crease_line(curve)
    assert "creases later" not in line
    assert "the inner face's field reaches the electro-creasing field" in line
    assert "an early bound for a crease, not ranked" in line
    assert line.endswith(f"{when} the critical value")


def test_a_mechanical_crease_after_the_critical_value_creases_later():
    crease = CreaseAlong(
        np.array([2.6, 2.7]), ("outer",) * 2, ("axial",) * 2, np.full(2, 0.01), np.zeros(2, bool)
    )
    line = crease_line(_curve([2.4668, 2.4562], crease=crease))
    assert line.endswith("a face creases later, from stretch = 2.6 .. 2.7")


def test_a_surface_points_face_is_kept_and_old_records_still_read():
    pt = CurvePoint(1.2, 2.4, (-1, -1), "surface", "", (), True, 2.4, 0.0, face="outer")
    record = point_record(pt)
    assert point_of(record) == pt
    del record["face"]  # a record written before the face was kept
    assert point_of(record).face == ""


def test_a_scanned_curve_point_carries_the_face_of_its_short_wave_limit():
    """The face comes from the scan; independently, the short-wave limit alone (no mode
    scanned) says outer at the same value (docs/derivation-surface.md section 8)."""
    tube = Tube.uniform(outer_radius=1.2, voltage=0.4)
    opts = ScanOptions(m_range=(0, 2), n_range=(1, 2))
    pt = curve_point(tube, "stretch", "outer_radius", 1.2, side="extension", options=opts)
    limit = short_wave_limit(tube, "stretch", side="extension")
    assert (pt.kind, pt.surface, pt.face) == ("surface", True, "outer")
    assert (limit.face, pt.value) == ("outer", limit.value)
