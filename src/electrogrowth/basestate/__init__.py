"""The axisymmetric base state of the grown, stretched, charged tube: the voltage curve
Vbar(lambda_i) and its threshold (:mod:`.voltage`, package-internal), the solved state with
its through-wall profiles (:mod:`.tube`).

May import ``model`` and ``errors``.
"""

from .tube import BaseState, solve_base_state, voltage_curve, voltage_threshold

__all__ = ["BaseState", "solve_base_state", "voltage_curve", "voltage_threshold"]
