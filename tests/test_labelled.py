"""Labelled results (labelled.py): to_xarray with units and descriptions, saved to netCDF
and Zarr and read back; the notebook summaries; the CLI answering --help without the
numeric stack; the edge warning and the digits of the text output (cli/report.py)."""

import subprocess
import sys
import types
import warnings

import numpy as np
import pytest

from electrogrowth import Layer, ScanOptions, Tube, critical_curve, scan_modes, solve_base_state
from electrogrowth.cli.report import edge_warning, supported

xr = pytest.importorskip("xarray")

TUBE = Tube.uniform(outer_radius=1.4, voltage=0.4)
SMALL = ScanOptions(m_range=(0, 3), n_range=(1, 3), top=3, extend=False, surface=False)


def _round_trip(ds, tmp_path):
    """Save to netCDF (scipy engine, no extra package) and to Zarr; read both back."""
    ds.to_netcdf(tmp_path / "a.nc", engine="scipy")
    with warnings.catch_warnings():  # zarr 3: fixed-width strings have no v3 spec yet
        warnings.simplefilter("ignore")
        ds.to_zarr(tmp_path / "a.zarr", mode="w")
        back_zarr = xr.open_zarr(tmp_path / "a.zarr").load()
    back_nc = xr.open_dataset(tmp_path / "a.nc", engine="scipy").load()
    return back_nc, back_zarr


def test_base_state_dataset(tmp_path):
    state = solve_base_state(TUBE)
    ds = state.to_xarray(21)
    assert ds.sizes == {"R": 21}
    assert ds["sigma_rr"].attrs["units"] == "mu" and ds["R"].attrs["units"] == "R_i"
    assert ds.attrs["lambda_i"] == state.lambda_i and ds.attrs["voltage"] == 0.4
    prof = state.profiles(21)
    np.testing.assert_array_equal(ds["sigma_tt"].values, prof["sigma_tt"])
    for back in _round_trip(ds, tmp_path):
        np.testing.assert_allclose(back["sigma_zz"].values, prof["sigma_zz"], rtol=0)
        assert back["E_r"].attrs["long_name"] == "radial electric field E_r"


def test_layered_state_dataset(tmp_path):
    tube = Tube([Layer(1.2, shear_modulus=3.0), Layer(1.6)], voltage=0.2)
    ds = solve_base_state(tube).to_xarray(30)
    assert set(np.unique(ds["layer"].values)) == {0, 1}
    assert ds.attrs["layers"] == 2
    back, _ = _round_trip(ds, tmp_path)
    np.testing.assert_array_equal(back["R"].values, ds["R"].values)


def test_scan_dataset(tmp_path):
    result = scan_modes(TUBE, "growth", options=SMALL)
    ds = result.to_xarray()
    c = result.critical
    assert ds["growth_cr"].values[0] == c.value and (ds["m"][0], ds["n"][0]) == (c.m, c.n)
    assert list(ds["growth_cr"].values) == sorted(ds["growth_cr"].values)
    assert ds.attrs["m_range"] == [0, 3] and "short_wave_limit" not in ds.attrs  # None left out
    back, _ = _round_trip(ds, tmp_path)
    assert list(back["family"].values) == list(ds["family"].values)
    assert "<table>" in result._repr_html_() and "1.26611156" in result._repr_html_()


def test_curve_dataset(tmp_path):
    curve = critical_curve(TUBE, "growth", "stretch", [0.9, 1.0, 1.1], options=SMALL)
    ds = curve.to_xarray()
    np.testing.assert_array_equal(ds["stretch"].values, curve.x)
    np.testing.assert_array_equal(ds["growth_cr"].values, curve.value)
    assert ds.sizes["switch"] == len(curve.switches)
    back, _ = _round_trip(ds, tmp_path)
    np.testing.assert_array_equal(back["m"].values, curve.m)
    assert "Curve" in curve._repr_html_()


def test_help_and_version_import_no_numeric_stack():
    code = (
        "import sys\n"
        "from electrogrowth.cli.app import main\n"
        "for argv in (['--help'], ['--version']):\n"
        "    main(argv)\n"
        "heavy = {'numba', 'sympy', 'scipy', 'matplotlib'} & set(sys.modules)\n"
        "assert not heavy, heavy\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "critical" in done.stdout


def test_help_piped_into_a_closed_reader_ends_quietly():
    cmd = [sys.executable, "-m", "electrogrowth", "--help"]
    with subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE) as proc:
        proc.stdout.read(10)
        proc.stdout.close()  # like `| head -c 10`
        err = proc.stderr.read().decode()
        assert proc.wait() == 0 and err == ""


def _scan(m, n, m_range=(0, 12), n_range=(1, 30), caps=(2000, 2000), status="ok"):
    crit = types.SimpleNamespace(kind="bifurcation", m=m, n=n, status=status)
    return types.SimpleNamespace(critical=crit, m_range=m_range, n_range=n_range, caps=caps)


def test_edge_warning():
    assert edge_warning(_scan(3, 1)) == ""
    assert "m = 12 is the largest m scanned" in edge_warning(_scan(12, 1))
    assert "n = 30" in edge_warning(_scan(0, 30))
    # at the tube's cap an INACCURATE status already says it: no second warning
    at_cap = _scan(6464, 0, m_range=(0, 6464), caps=(6464, 2037), status="inaccurate")
    assert edge_warning(at_cap) == ""
    assert "m = 6464" in edge_warning(_scan(6464, 0, m_range=(0, 6464), caps=(6464, 2037)))
    threshold = types.SimpleNamespace(critical=types.SimpleNamespace(kind="threshold", m=-1, n=-1))
    assert edge_warning(threshold) == ""


def test_digits_follow_the_error_estimate():
    assert supported(1.2661115622623291, 0.0038) == "1.266"
    assert supported(1.2661115622623291, 1.4e-12) == "1.26611156226"
    assert supported(0.613948, 2e-4) == "0.6139"


def test_scan_dataset_has_the_verdict(tmp_path):
    """The verdict of a tube that creases first (docs/derivation-crease.md): what comes
    first, each kind along rival, the empty branch/koiter slot; saved and read back."""
    res = scan_modes(Tube.uniform(1.8, length=1.0), "stretch", side="compression", options=SMALL)
    ds = res.to_xarray()
    crease = 2.4 ** (-2 / 3)  # the homogeneous tube's axial crease, closed form
    assert str(ds["verdict"].values) == "crease"
    assert float(ds["verdict_value"]) == pytest.approx(crease, rel=1e-12)
    assert list(ds["rival"].values) == ["bifurcation", "surface", "crease", "threshold"]
    values = ds["rival_value"].values
    assert values[0] == res.critical.value and np.isnan(values[1]) and np.isnan(values[3])
    assert values[2] == pytest.approx(crease, rel=1e-12)
    assert str(ds["branch"].values) == "" and np.isnan(float(ds["koiter"]))
    for name in ("verdict_face", "meaning", "rival_face", "crease_criterion"):
        assert name in ds
    back, _ = _round_trip(ds, tmp_path)
    assert str(back["verdict"].values) == "crease" and "creases" in str(back["meaning"].values)
    assert "verdict" in res._repr_html_() and "creases" in res._repr_html_()


def test_verdict_variables_carry_a_harmonic_next_to_onset():
    """A verdict with its branch (bifurcation/koiter.with_branch) whose wrinkle (1, 1) has
    the harmonic (2, 2) 0.74 % after onset (L = 8.5): its value and (m, n) are variables;
    without one, NaN and -1."""
    from electrogrowth.bifurcation.koiter import with_branch
    from electrogrowth.labelled import verdict_variables

    tube = Tube.uniform(1.2, length=8.5)
    verdict, note = with_branch(
        scan_modes(tube, "stretch", side="compression", options=SMALL).verdict,
        tube,
        "stretch",
        "compression",
    )
    assert note is None
    got = verdict_variables(verdict, "stretch")
    r = verdict.koiter_resonance
    assert got["koiter_resonance_value"][1] == r["value"]
    assert (got["koiter_resonance_m"][1], got["koiter_resonance_n"][1]) == (2, 2)
    plain = verdict_variables(scan_modes(TUBE, "growth", options=SMALL).verdict, "growth")
    assert np.isnan(plain["koiter_resonance_value"][1])
    assert plain["koiter_resonance_m"][1] == plain["koiter_resonance_n"][1] == -1


@pytest.mark.parametrize(
    ("solve_for", "units"), [("pressure", "mu"), ("force", "mu R_i^2"), ("growth[1].theta", "1")]
)
def test_a_curve_of_any_control_carries_that_controls_units(solve_for, units):
    """Check round 29 (doubts): a layered tube's controls had units "1" whatever they were
    (a pressure is in mu, a force in mu R_i^2, as the command line's axes say), and so had
    its keys (a layer's shear modulus is in mu); the same table serves a sweep's store."""
    from electrogrowth.bifurcation.curve_crease import CreaseAlong
    from electrogrowth.bifurcation.curve_record import Curve

    nan = np.full(2, np.nan)
    crease = CreaseAlong(nan, ("", ""), ("", ""), nan, np.zeros(2, bool))
    curve = Curve("layers[1].shear_modulus", solve_for, None, np.array([2.0, 3.0]),
                  np.array([0.1, 0.2]), np.array([1, 1]), np.array([1, 1]),
                  np.array(["bifurcation"] * 2), ("ok", "ok"), (), TUBE, np.zeros(2, bool),
                  nan, crease=crease, surface_face=("", ""))  # fmt: skip
    ds = curve.to_xarray()
    assert ds[f"{solve_for}_cr"].attrs["units"] == units
    assert ds["layers[1].shear_modulus"].attrs["units"] == "mu"
    assert ds["switch_value"].attrs["units"] == units
