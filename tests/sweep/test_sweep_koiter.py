"""The amplitude equation in a sweep ([solve] koiter = true): the branch and the Koiter
coefficient stored at every point it covers, equal to a direct ``koiter_coefficient``
call; the reason where it does not cover the point; a failure of the expansion kept as
data; the option validated; stores written before it still read and resume."""

import dataclasses
import json
import math
import shutil
import warnings

import numpy as np
import pytest

pytest.importorskip("xarray")
pytest.importorskip("zarr")

import zarr  # noqa: E402

from electrogrowth.bifurcation import koiter as koiter_module  # noqa: E402
from electrogrowth.bifurcation.koiter import koiter_coefficient  # noqa: E402
from electrogrowth.errors import BaseStateError, ConfigError  # noqa: E402
from electrogrowth.model.layers import Layer, Tube  # noqa: E402
from electrogrowth.outcomes import Status  # noqa: E402
from electrogrowth.sweep.config import SweepConfig  # noqa: E402
from electrogrowth.sweep.file import parse_config  # noqa: E402
from electrogrowth.sweep.run import compute_sweep  # noqa: E402
from electrogrowth.sweep.schema import POINT_VARIABLES  # noqa: E402
from electrogrowth.sweep.store import open_results  # noqa: E402
from electrogrowth.sweep.unit import BRANCH_FAILED, compute_point  # noqa: E402

#: tests/bifurcation/test_koiter.py's film tube: a film [1, 1.1] (mu 1, hoop growth) inside
#: a substrate to 2 (mu 0.2); its mode (12, 0) is supercritical
FILM = """\
length = 1.0
stretch = 1.0
[[layers]]
outer_radius = 1.1
shear_modulus = 1.0
growth = [1, 1.0, 1]
[[layers]]
outer_radius = 2.0
shear_modulus = 0.2
"""
THETA = "growth[1].theta"
SWEEP = f"""\
[tube]
file = "film.toml"
[solve]
for = "{THETA}"
koiter = true
[modes]
m = [10, 14]
n = [1, 2]
[grid]
voltage = [0.0, 0.05]
"""
PAPER = """\
[solve]
for = "growth"
koiter = true
[modes]
m = [0, 3]
n = [1, 3]
extend = false
[fixed]
length = 1.0
[grid]
outer_radius = [1.5]
"""


def _film_tube() -> Tube:
    return Tube(
        [Layer(1.1, shear_modulus=1.0, growth=(1, 1.0, 1)), Layer(2.0, shear_modulus=0.2)],
        length=1.0,
        stretch=1.0,
    )


def _config(tmp_path, text=SWEEP) -> SweepConfig:
    (tmp_path / "film.toml").write_text(FILM)
    return parse_config(text, source=str(tmp_path / "s.toml"))


def test_the_store_declares_the_branch_fields():
    for name in ("branch", "koiter", "koiter_error", "branch_note"):
        assert POINT_VARIABLES[name][2], name  # a description


@pytest.mark.slow
def test_sweep_coefficient_is_the_direct_one(tmp_path):
    """Both points (Vbar = 0 and 0.05) are covered: their branches and coefficients are
    koiter_coefficient's on the same tubes; the summary counts them. ~60 s."""
    summary = compute_sweep(_config(tmp_path), tmp_path / "out.zarr", workers=1)
    ds = open_results(tmp_path / "out.zarr")
    for i, voltage in enumerate((0.0, 0.05)):
        m, n = int(ds["m"].values[i]), int(ds["n"].values[i])
        tube = dataclasses.replace(_film_tube(), voltage=voltage)
        direct = koiter_coefficient(tube, (m, n), THETA)
        assert str(ds["branch"].values[i]) == direct.branch
        assert float(ds["koiter"].values[i]) == pytest.approx(direct.coefficient, rel=1e-12)
        assert float(ds["koiter_error"].values[i]) == pytest.approx(
            direct.error_estimate, rel=1e-6
        )
        assert str(ds["branch_note"].values[i]) == ""
        assert direct.branch in str(ds["meaning"].values[i])
    assert sum(summary.verdicts["branch"].values()) == 2
    assert (int(ds["m"].values[0]), int(ds["n"].values[0])) == (12, 0)


def test_a_point_not_covered_says_why(tmp_path):
    """The paper's tube, charged, of a dielectric that is not ideal (its permittivity
    changes with the stretch): the expansion covers ideal dielectrics under a voltage only,
    so no branch, and the reason; nothing else of the point changes."""
    charged = PAPER.replace("length = 1.0", "length = 1.0\nvoltage = 0.2")
    charged += '[material]\nenergy = "(I1 - 3)/2 + I5/2 + (I1 - 3)*I5/50"\n'
    config = parse_config(charged, source=str(tmp_path / "s.toml"))
    tube = config.points((slice(0, 1),))[0]
    with_k = compute_point(tube, config.spec)
    without = compute_point(tube, SweepConfig.from_dict(_without_koiter(config)).spec)
    assert with_k.status == Status.OK and with_k.branch == "" and math.isnan(with_k.koiter)
    assert "ideal dielectric" in with_k.branch_note
    assert without.branch_note == "" and with_k.value == without.value


def test_a_failed_expansion_is_data(tmp_path, monkeypatch):
    """An expansion that raises leaves the point's status and linear result; the failure is
    in branch_note, and the summary counts it."""

    def boom(*args, **kwargs):
        raise BaseStateError("no base state at g = 9")

    monkeypatch.setattr(koiter_module, "with_branch", boom)
    config = parse_config(PAPER, source=str(tmp_path / "s.toml"))
    point = compute_point(config.points((slice(0, 1),))[0], config.spec)
    assert point.status == Status.OK and math.isfinite(point.value)
    assert point.branch_note == f"{BRANCH_FAILED}: BaseStateError: no base state at g = 9"
    summary = compute_sweep(config, tmp_path / "out.zarr", workers=1)
    assert summary.verdicts["branch"] == {"failed": 1}
    assert "branch: 1 failed" in summary.text()


def _without_koiter(config: SweepConfig) -> dict:
    d = config.to_dict()
    d["solve"].pop("koiter")
    return d


def test_koiter_option_is_validated(tmp_path):
    text = PAPER.replace("koiter = true", "koiter = 1")
    with pytest.raises(ConfigError, match=r"solve.koiter: expected true or false, got an integ"):
        parse_config(text, source=str(tmp_path / "s.toml"))


def test_koiter_refuses_a_control_it_does_not_cover(tmp_path):
    """The axial force (the stretch then an unknown of the base state) is not covered;
    a growth, the pressure, the stretch and the voltage are."""
    (tmp_path / "film.toml").write_text(FILM.replace("stretch = 1.0", "axial_force = 0.0"))
    text = SWEEP.replace(f'for = "{THETA}"', 'for = "force"').replace("voltage", "length")
    match = r"solve.koiter: the amplitude equation covers growth, pressure, stretch, voltage so"
    with pytest.raises(ConfigError, match=match):
        parse_config(text.replace("0.0, 0.05", "1.0, 2.0"), source=str(tmp_path / "s.toml"))
    stretch = PAPER.replace('for = "growth"', 'for = "stretch"\nside = "compression"')
    assert parse_config(stretch, source=str(tmp_path / "s.toml")).koiter


def test_koiter_is_stored_only_when_asked(tmp_path):
    """A sweep without it normalises as stores written before it did (so they resume);
    with it, the option round-trips through the stored JSON and counts on resume."""
    asked = parse_config(PAPER, source=str(tmp_path / "s.toml"))
    plain = parse_config(PAPER.replace("koiter = true\n", ""), source=str(tmp_path / "s.toml"))
    assert "koiter" not in json.loads(plain.to_json())["solve"]
    assert SweepConfig.from_dict(json.loads(asked.to_json())) == asked
    assert asked.spec.koiter and not plain.spec.koiter


def test_a_store_written_before_the_branch_fields_reads_and_resumes(tmp_path):
    """A store lacking the arrays added with the option (branch_note, koiter_error) is
    opened, resumed and summed up; the arrays it lacks are skipped, not invented."""
    config = parse_config(PAPER.replace("koiter = true\n", ""), source=str(tmp_path / "s.toml"))
    out = tmp_path / "old.zarr"
    compute_sweep(config, out, workers=1)
    for name in ("branch_note", "koiter_error"):
        shutil.rmtree(out / name)
    group = zarr.open_group(str(out), mode="r+")
    group["run"][...] = np.zeros_like(group["run"][...])  # as if never computed: resume
    with warnings.catch_warnings():  # "consolidated metadata is not in the v3 spec"
        warnings.simplefilter("ignore", category=UserWarning)
        zarr.consolidate_metadata(str(out))
    summary = compute_sweep(config, out, workers=1)
    ds = open_results(out)
    assert "branch_note" not in ds and "koiter_error" not in ds
    assert str(ds["status"].values[0]) == "ok" and "what comes first: 1 " in summary.text()


#: the paper's sweep on tests/bifurcation/test_koiter_resonance.py's tube: compressed, L 8.5
#: (a harmonic next to onset) and 30 (none)
RESONANT = (
    PAPER.replace('for = "growth"', 'for = "stretch"\nside = "compression"')
    .replace("length = 1.0", "outer_radius = 1.2")
    .replace("outer_radius = [1.5]", "length = [8.5, 30.0]")
)


def test_a_second_harmonic_next_to_onset_is_stored(tmp_path):
    """tests/bifurcation/test_koiter_resonance.py's tube: at L = 8.5 the first mode (1, 1)
    has its harmonic (2, 2) bifurcating 0.74 % after onset, where its coefficient has a pole;
    the store holds that harmonic's value and (m, n), those of the direct expansion. At
    L = 30 there is none: NaN and -1."""
    compute_sweep(parse_config(RESONANT, source=str(tmp_path / "s.toml")), tmp_path / "o.zarr")
    ds = open_results(tmp_path / "o.zarr")
    direct = koiter_coefficient(
        Tube.uniform(1.2, length=8.5), (1, 1), "stretch", side="compression"
    ).resonance
    assert (int(ds["m"].values[0]), int(ds["n"].values[0])) == (1, 1)
    assert float(ds["koiter_resonance_value"].values[0]) == pytest.approx(direct.value, rel=1e-12)
    assert int(ds["koiter_resonance_m"].values[0]) == direct.m == 2
    assert int(ds["koiter_resonance_n"].values[0]) == direct.n == 2
    assert math.isnan(float(ds["koiter_resonance_value"].values[1]))
    assert int(ds["koiter_resonance_m"].values[1]) == int(ds["koiter_resonance_n"].values[1]) == -1
    assert math.isfinite(float(ds["koiter"].values[1]))  # the expansion ran there
