"""The words of the energy grammar (model/energy_grammar.py) as plain names, without sympy:
the parser builds its tables from these, and the command line's ``--energy`` help and the
parser's error line list them, so what is accepted and what is announced cannot drift apart
(probe 14e D6: the help listed three of the seven functions)."""

from __future__ import annotations

INVARIANTS = ("I1", "I2", "I4", "I5", "I6")
#: as listed; the tokenizer tries the longer ones first ("**" before "*")
OPERATORS = ("+", "-", "*", "/", "**", "^", "(", ")")
#: functions of one argument, by their sympy names
FUNCTIONS = ("log", "exp", "sqrt", "tanh", "atan", "cosh", "sinh")
#: constants, by their sympy names
CONSTANTS = ("pi", "E")


def words() -> str:
    """Everything an energy text may hold, in one line.

    >>> words().startswith("numbers, I1 I2 I4 I5 I6, + - * / ** ^ ( ), log exp sqrt tanh")
    True
    """
    return (
        f"numbers, {' '.join(INVARIANTS)}, {' '.join(OPERATORS)},"
        f" {' '.join(FUNCTIONS)} of one argument, {', '.join(CONSTANTS)}"
    )
