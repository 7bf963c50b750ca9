"""The branch curvature's amplitude scales (api.initial_curvature): the scale is cut
tenfold until two agree to CURVATURE_RTOL, the larger of the two kept and their difference
reported. On a synthetic branch c(a) = c_c + c_2 a^2 + c_4 a^4 + c_6 a^6 (the FE branch
replaced): the estimate (4 D_1 - D_2) / 3 from a, 2a, 4a is c_2 - 84 c_6 a^4 exactly (the
a^4 term cancels), so which scales agree is known in advance."""

import types

import numpy as np
import pytest

pytest.importorskip("skfem")

from electrogrowth.postbuckle import api  # noqa: E402


def curvature(monkeypatch, c2, c4, c6):
    class Branch:
        def __init__(self, *args, **kwargs):
            pass

        def follow(self, start, amplitudes, direction=None):
            c = [1.0 + c2 * a**2 + c4 * a**4 + c6 * a**6 for a in amplitudes]
            return [types.SimpleNamespace(control=v) for v in c]

    monkeypatch.setattr(api, "AmplitudeBranch", Branch)
    monkeypatch.setattr(api, "with_stability", lambda section, point: point)
    monkeypatch.setattr(api, "amplitude_vector", lambda section, face: np.ones(2))
    section = types.SimpleNamespace(energy=lambda x: 0.0)
    onset = types.SimpleNamespace(value=1.0, x=np.zeros(2), mode=np.ones(2))
    return api.initial_curvature(section, None, "voltage", onset)[2]


def test_a_quadratic_branch_keeps_the_first_scale(monkeypatch):
    """c_4 cancels and c_6 = 7 leaves 6e-10 at a = 1e-3: the first two scales agree, 1e-3
    is kept."""
    got = curvature(monkeypatch, c2=7.0, c4=1e3, c6=7.0)
    assert got.amplitude == api.CURVATURE_AMPLITUDE
    assert got.value == pytest.approx(7.0, rel=1e-6)
    assert got.error < 1e-6 * 7.0


def test_a_branch_not_yet_quadratic_is_cut(monkeypatch):
    """c_2 = -500, c_6 = 1e11: the estimate is -508.4 at a = 1e-3 (1.7 % off) and
    -500.00084 at 1e-4; 1e-4 and 1e-5 agree: the 1e-4 value is kept, with their difference
    (8.4e-4 less 8.4e-8) as its error."""
    got = curvature(monkeypatch, c2=-500.0, c4=0.0, c6=1e11)
    assert got.amplitude == pytest.approx(1e-4)
    assert got.value == pytest.approx(-500.0 - 84e11 * 1e-16, rel=1e-9)
    assert got.error == pytest.approx(84e11 * (1e-16 - 1e-20), rel=1e-3)


def test_scales_that_never_agree_say_how_far_apart(monkeypatch):
    """c_6 = 1e14 with c_2 = 1: 1e-4 and 1e-5 still differ by 0.84: the last scale's value,
    with that difference as its error."""
    got = curvature(monkeypatch, c2=1.0, c4=0.0, c6=1e14)
    assert got.amplitude == pytest.approx(1e-5)
    assert got.value == pytest.approx(1.0 - 84e14 * 1e-20, rel=1e-6)
    assert got.error == pytest.approx(0.84, rel=1e-3)
    assert got.error > api.CURVATURE_RTOL * abs(got.value)
