"""How many digits of a computed value to print: those its error estimate supports.

Below every stage (it imports nothing of the package): the command line's reports
(cli/report.py) and the verdict's one-line ``meaning`` (bifurcation/verdict.py) print values
by the same rule.

* :func:`supported`: the last digit shown is the decade of the estimate (1.266 for
  1.26611 +- 3.8e-3), never more than 12 significant digits, never fewer than 3;
* :func:`apart`: that, and at least the digits that tell the value from others it must not
  be read as (the control's start, the next event along the march).
"""

from __future__ import annotations

import math
from decimal import Decimal
from fractions import Fraction

MAX_DIGITS, MIN_DIGITS = 12, 3

#: the most digits :func:`apart` shows: a double's shortest round trip
ROUND_TRIP = 17


def digits(value: float, error: float | None) -> int:
    """Significant digits of ``value`` that an absolute ``error`` estimate supports.

    >>> digits(1.26611156226, 3.8e-3), digits(1.26611156226, 2e-14), digits(0.5, 0.0)
    (4, 12, 12)
    """
    if error is None or not math.isfinite(error) or error <= 0 or value == 0:
        return MAX_DIGITS
    if not math.isfinite(value):
        return MIN_DIGITS
    n = math.floor(math.log10(abs(value))) - math.floor(math.log10(error)) + 1
    return max(MIN_DIGITS, min(MAX_DIGITS, n))


def supported(value: float, error: float | None) -> str:
    """``value`` with the digits its error estimate supports.

    >>> supported(1.26611156226, 3.8e-3), supported(1.26611156226, 1e-11)
    ('1.266', '1.26611156226')
    """
    return f"{value:.{digits(value, error)}g}"


def apart(value: float, error: float | None, *others: float | None, unknown: int = 4) -> str:
    """``value`` as :func:`supported` prints it, with more digits where fewer would print it
    as one of ``others`` (None or non-finite: ignored; equal to ``value``: cannot be told
    apart). A verdict's onset 1.0002779 +- 1e-3 is not "1", the unloaded start, and two
    events 6.5e-5 apart are not both "0.7961". Without a finite ``error`` (None, or a
    criterion's inf) ``unknown`` digits: a value with no estimate claims no more.

    >>> apart(1.00027786548, 1e-3, 1.0), apart(0.79606346, 1e-6, 0.79612846)
    ('1.0003', '0.796063')
    >>> apart(1.00027786548, 5e-12, 1.0), apart(2.5e-3, None, 0.0)
    ('1.00027786548', '0.0025')
    """
    known = error is not None and math.isfinite(error)
    n = digits(value, error) if known else unknown
    if not math.isfinite(value):
        return f"{value:.{n}g}"
    for other in others:
        if other is None or not math.isfinite(other) or other == value:
            continue
        while n < ROUND_TRIP and f"{value:.{n}g}" == f"{other:.{n}g}":
            n += 1
    return f"{value:.{n}g}"


def decimal_grid(start: float, stop: float, num: int) -> list[float]:
    """``num`` equally spaced values from ``start`` to ``stop``, each the double nearest to
    the exact decimal grid point: the ends as given, and a step of 0.1 from 0 gives 0.1, 0.2
    (``np.linspace`` gives 0.09999999999999999, which a CSV then shows). The ends are read
    as their shortest decimals (``repr``), the points computed in exact fractions.

    >>> decimal_grid(0.0, 0.3, 4)
    [0.0, 0.1, 0.2, 0.3]
    """
    if num == 1:
        return [float(start)]
    a, b = (Fraction(Decimal(repr(float(v)))) for v in (start, stop))
    return [float(a + (b - a) * i / (num - 1)) for i in range(num)]
