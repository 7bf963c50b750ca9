"""A Problem built once gives what the keyword forms give, to the last bit; its targets and
march functions are named objects that pickle; a bad input is one ParameterError."""

import pickle

import numpy as np
import pytest

from electrogrowth import (
    Accuracy,
    ParameterError,
    Problem,
    ScanOptions,
    Tube,
    certify,
    critical_curve,
    critical_value,
    scan_modes,
    solve_base_state,
)
from electrogrowth.bifurcation.along import TubeAt, root_mode
from electrogrowth.bifurcation.surface import short_wave_limit
from electrogrowth.incremental.targets import (
    CollocationTarget,
    ImpedanceTarget,
    targets_for,
    with_family,
)

TUBE = Tube.uniform(outer_radius=1.4, length=1.0, voltage=0.2)
SMALL = ScanOptions(m_range=(0, 3), n_range=(1, 3), top=3)


def test_critical_value_of_a_problem_equals_the_keyword_form():
    problem = Problem(TUBE, "stretch", side="extension", accuracy=Accuracy(1e-10))
    assert critical_value(problem, 1, 1) == critical_value(
        TUBE, 1, 1, "stretch", side="extension", rtol=1e-10
    )


def test_scan_of_a_problem_equals_the_keyword_form():
    problem = Problem(TUBE, "growth", options=SMALL)
    scan = scan_modes(problem)
    assert scan == scan_modes(TUBE, "growth", options=SMALL)
    assert scan.critical.kind == "bifurcation"


def test_short_wave_limit_of_a_problem_equals_the_keyword_form():
    problem = Problem(TUBE, "stretch", accuracy=1e-10)  # a number is taken as the rtol
    assert problem.accuracy == Accuracy(1e-10)
    limit = short_wave_limit(problem)
    assert limit == short_wave_limit(TUBE, "stretch", rtol=1e-10)
    assert limit.side == "compression"


def test_certify_and_curve_take_a_problem():
    problem = Problem(Tube.uniform(), "stretch", options=ScanOptions((0, 2), (1, 2)))
    crit = critical_value(problem, 1, 1)
    assert certify(problem, crit) == certify(problem.tube, crit)
    curve = critical_curve(problem, "outer_radius", [1.2, 1.3])
    same = critical_curve(
        Tube.uniform(), "stretch", "outer_radius", [1.2, 1.3], options=ScanOptions((0, 2), (1, 2))
    )
    assert curve.as_dict() == same.as_dict()


def test_problem_at_and_targets():
    problem = Problem(TUBE, "voltage", accuracy=Accuracy(1e-11))
    assert problem.at(0.3) == TUBE.at("voltage", 0.3)
    assert problem.targets() == ImpedanceTarget(1e-11)
    assert problem.targets("collocation") == CollocationTarget(1e-11)
    assert problem.targets("impedance", rtol=1e-5) == targets_for("impedance", 1e-5)


@pytest.mark.parametrize("target", [ImpedanceTarget(1e-10), CollocationTarget(1e-10)])
def test_targets_pickle_and_round_trip(target):
    state = solve_base_state(TUBE)
    modes = np.array([[1.0, 1.0], [2.0, 3.0]])
    back = pickle.loads(pickle.dumps(target))
    assert back == target and type(back) is type(target)
    assert np.array_equal(back(state, modes), target(state, modes))


def test_a_signed_march_function_pickles_and_round_trips():
    mode = with_family(1, 1, "wrinkle")
    f = root_mode(TubeAt(TUBE, "stretch"), ImpedanceTarget(1e-10), mode, -1.0)
    back = pickle.loads(pickle.dumps(f))
    assert back(0.9) == f(0.9)
    problem = Problem(TUBE, "growth")
    assert pickle.loads(pickle.dumps(problem)) == problem


@pytest.mark.parametrize(
    ("kwargs", "named"),
    [
        ({"control": "bogus"}, "bogus"),
        ({"control": "stretch", "side": "sideways"}, "sideways"),
        ({"control": "growth", "accuracy": Accuracy(1e-2)}, "0.01"),
        ({"control": "growth", "accuracy": 0.0}, "0.0"),
        ({"control": "growth", "accuracy": "tight"}, "tight"),
    ],
)
def test_bad_problem_is_one_parameter_error_naming_the_value(kwargs, named):
    with pytest.raises(ParameterError, match=named) as info:
        Problem(TUBE, **kwargs)
    assert "\n" not in str(info.value)


def test_a_problem_with_its_pieces_again_is_refused():
    problem = Problem(TUBE, "growth")
    with pytest.raises(ParameterError, match="rtol given with a Problem"):
        critical_value(problem, 1, 1, rtol=1e-10)
    with pytest.raises(ParameterError, match="solve_for, options given with a Problem"):
        scan_modes(problem, "growth", options=SMALL)
    with pytest.raises(ParameterError, match="is not a Tube"):
        Problem("tube", "growth")
