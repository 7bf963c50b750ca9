"""The grammar of an energy written as text, and its parser: text in, sympy expression out.

Every energy text (``--energy``, a tube file's ``energy``, a sweep file's ``[material]
energy``, a configuration read back from a results store, ``Material(name, "text")``) is
read here and nowhere else. Nothing of the text is ever evaluated: a tokenizer and a
recursive-descent parser accept a whitelist grammar and build the expression from sympy's
own constructors (``Integer``, ``Float``, ``Add``, ``Mul``, ``Pow``, ``log``, ...; the
operators ``a + b`` etc. of sympy objects are those constructors), so the result is the
expression ``sympify`` gave for the same text, without ``sympify``, ``eval`` or ``exec``::

    energy  := sum
    sum     := product (("+" | "-") product)*
    product := unary (("*" | "/") unary)*
    unary   := ("+" | "-") unary | power
    power   := atom (("**" | "^") unary)?          right-associative, as in Python
    atom    := number | I1 | I2 | I4 | I5 | I6 | pi | E | "(" sum ")"
             | (log | exp | sqrt | tanh | atan | cosh | sinh) "(" sum ")"
    number  := digits ["." digits] [("e" | "E") ["+" | "-"] digits]  (or ".5")

ASCII only, spaces, tabs and line breaks between tokens. Limits, each refused naming it:
:data:`MAX_LENGTH` characters, :data:`MAX_DEPTH` levels of nesting, :data:`MAX_OPERATIONS`
operations, numbers that are finite doubles, powers nested at most :data:`MAX_TOWER` deep,
and no power or exponential whose size at the undeformed state (I1 = I2 = 3,
I4 = I5 = I6 = 0) exceeds e^:data:`MAX_LOG` (about 1e304) or whose exponents, multiplied
through nested powers, exceed :data:`MAX_EXPONENT` there. The last two are checked before
sympy builds the power, so ``0*9**9**9`` is refused in microseconds instead of computing a
number with 370 million digits; they also bound every exact number sympy later computes at
the undeformed state (the units check). Every failure is one MaterialError line naming the
text, the position and the problem.
"""

from __future__ import annotations

import math
import re

import sympy as sp

from ..errors import MaterialError
from . import energy_words
from .energy_sizes import as_float, log_height, log_size, undeformed_value

MAX_LENGTH = 2000
MAX_DEPTH = 50
MAX_OPERATIONS = 300
MAX_TOWER = 3
MAX_LOG = 700.0  # e^709.8 is the largest double
MAX_EXPONENT = 100.0

#: The invariants, equal to model/materials.py's symbols (sympy symbols are equal by name
#: and assumptions); the functions and constants by their names in sympy (energy_words.py).
SYMBOLS = {name: sp.Symbol(name, real=True) for name in energy_words.INVARIANTS}
FUNCTIONS = {name: getattr(sp, name) for name in energy_words.FUNCTIONS}
CONSTANTS = {name: getattr(sp, name) for name in energy_words.CONSTANTS}
ALLOWED = "allowed: " + energy_words.words()

_NUMBER = re.compile(r"(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d+)?")
_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_SPACE = " \t\r\n"
_NAMES = {*SYMBOLS, *CONSTANTS, *FUNCTIONS}
_OPERATORS = tuple(sorted(energy_words.OPERATORS, key=len, reverse=True))  # "**" before "*"
_GROWING = (sp.exp, sp.cosh, sp.sinh)  # functions that overflow a double beyond MAX_LOG


def parse_energy(text: str) -> sp.Expr:
    """The sympy expression of an energy text (the grammar above).

    Raises MaterialError (one line) naming the text, the position and the problem.

    >>> parse_energy("(I1 - 3)/2 + I5^2/4")
    I1/2 + I5**2/4 - 3/2
    >>> parse_energy("__import__('os')")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    electrogrowth.errors.MaterialError: energy "__import__('os')" at position 1: unknown name ...
    """
    if not isinstance(text, str):
        raise MaterialError(f"energy = {_short(repr(text))} is not a text")
    return _Parser(text).parse()


def shorten(text: str, limit: int = 60) -> str:
    """``text`` on one line, cut to ``limit`` characters (for an error message); only ASCII
    white space is joined, so a look-alike space stays visible in the quoted text."""
    line = re.sub(r"[ \t\r\n]+", " ", text).strip()
    return line if len(line) <= limit else line[: limit - 3] + "..."


def _short(text: str) -> str:
    return shorten(text)


class _Parser:
    """One pass over the tokens; each ``_sum``/``_product``/... returns (expression, tower
    height, exponent growth): the number of ``**`` nested in it and the product of the sizes
    of those exponents at the undeformed state."""

    def __init__(self, text: str):
        self.text = text
        self.tokens: list[tuple[str, str, int]] = []  # (kind, token, position from 1)
        self.i = 0
        self.depth = 0
        self.operations = 0
        self.values: dict = {}  # sympy node -> its value at the undeformed state (float)

    # -- errors ---------------------------------------------------------------------------

    def fail(self, problem: str, position: int | None = None):
        at = f" at position {position}" if position is not None else ""
        raise MaterialError(f"energy {_short(self.text)!r}{at}: {problem}; {ALLOWED}")

    # -- tokens -----------------------------------------------------------------------------

    def tokenize(self) -> None:
        text = self.text
        if len(text) > MAX_LENGTH:
            self.fail(f"{len(text)} characters, more than the limit {MAX_LENGTH}")
        pos = 0
        while pos < len(text):
            ch = text[pos]
            if ch in _SPACE:
                pos += 1
                continue
            if not ch.isascii():
                self.fail(f"the character {ch!r} (U+{ord(ch):04X}) is not ASCII", pos + 1)
            if ch == ",":
                self.fail("a comma: give one expression, not a list", pos + 1)
            if hit := _NUMBER.match(text, pos):
                self.tokens.append(("number", hit.group(), pos + 1))
                pos = hit.end()
                if pos < len(text) and (text[pos].isalnum() or text[pos] in "_."):
                    self.fail(f"{text[pos]!r} right after the number {hit.group()!r}", pos + 1)
                continue
            if hit := _NAME.match(text, pos):
                if hit.group() not in _NAMES:
                    self.fail(f"unknown name {_short(hit.group())!r}", pos + 1)
                self.tokens.append(("name", hit.group(), pos + 1))
                pos = hit.end()
                continue
            op = next((o for o in _OPERATORS if text.startswith(o, pos)), None)
            if op is None:
                self.fail(f"the character {ch!r}", pos + 1)
            self.tokens.append(("op", op, pos + 1))
            pos += len(op)
        if not self.tokens:
            self.fail("it is empty: write Omega in I1, I2, I4, I5, I6")
        self.tokens.append(("end", "", len(text) + 1))

    def peek(self) -> tuple[str, str, int]:
        return self.tokens[self.i]

    def take(self) -> tuple[str, str, int]:
        token = self.tokens[self.i]
        self.i += 1
        return token

    def expect(self, op: str, opened: int) -> None:
        kind, token, pos = self.take()
        if (kind, token) != ("op", op):
            where = f"the '(' at position {opened} is not closed"
            found = "the end" if kind == "end" else repr(token)
            self.fail(f"unbalanced parentheses: {where} (found {found})", pos)

    # -- grammar ----------------------------------------------------------------------------

    def parse(self) -> sp.Expr:
        self.tokenize()
        expr, _, _ = self.sum()
        kind, token, pos = self.peek()
        if kind != "end":
            problem = (
                "unbalanced parentheses: a ')' without its '('"
                if token == ")"
                else f"{token!r} where an operator or the end is expected"
            )
            self.fail(problem, pos)
        self.check_numbers(expr)
        return expr

    def enter(self, pos: int) -> None:
        self.depth += 1
        if self.depth > MAX_DEPTH:
            self.fail(f"nested deeper than the limit of {MAX_DEPTH} levels", pos)

    def count(self, pos: int) -> None:
        self.operations += 1
        if self.operations > MAX_OPERATIONS:
            self.fail(f"more than the limit of {MAX_OPERATIONS} operations", pos)

    def sum(self):
        expr, tower, growth = self.product()
        while self.peek()[:2] in (("op", "+"), ("op", "-")):
            _, op, pos = self.take()
            self.count(pos)
            right, t, g = self.product()
            expr = expr + right if op == "+" else expr - right
            tower, growth = max(tower, t), max(growth, g)
        return expr, tower, growth

    def product(self):
        expr, tower, growth = self.unary()
        while self.peek()[:2] in (("op", "*"), ("op", "/")):
            _, op, pos = self.take()
            self.count(pos)
            right, t, g = self.unary()
            if op == "/" and right == 0:
                self.fail("a division by zero", pos)
            expr = expr * right if op == "*" else expr / right
            tower, growth = max(tower, t), max(growth, g)
        return expr, tower, growth

    def unary(self):
        kind, token, pos = self.peek()
        if (kind, token) not in (("op", "+"), ("op", "-")):
            return self.power()
        self.take()
        self.count(pos)
        self.enter(pos)
        expr, tower, growth = self.unary()
        self.depth -= 1
        return (-expr if token == "-" else expr), tower, growth

    def power(self):
        base, tower, growth = self.atom()
        kind, token, pos = self.peek()
        if (kind, token) not in (("op", "**"), ("op", "^")):
            return base, tower, growth
        self.take()
        self.count(pos)
        self.enter(pos)
        exponent, t, g = self.unary()
        self.depth -= 1
        tower = max(tower, t) + 1
        if tower > MAX_TOWER:
            self.fail(f"powers nested more than {MAX_TOWER} deep (a power tower)", pos)
        self.check_power(base, exponent, pos)
        if not (base.free_symbols or exponent.free_symbols):
            return base**exponent, tower, 1.0  # one number, its size checked: a literal
        growth = max(growth, g) * self.exponent_size(exponent, pos)
        if growth > MAX_EXPONENT:
            self.fail(
                f"exponents multiplied through nested powers reach {growth:.3g} at the"
                f" undeformed state, beyond the limit {MAX_EXPONENT:g}",
                pos,
            )
        return base**exponent, tower, growth

    def atom(self):
        kind, token, pos = self.take()
        if kind == "number":
            return self.number(token, pos), 0, 1.0
        if kind == "name":
            return self.name(token, pos)
        if (kind, token) == ("op", "("):
            self.enter(pos)
            inner = self.sum()
            self.expect(")", pos)
            self.depth -= 1
            return inner
        found = "the end" if kind == "end" else repr(token)
        self.fail(f"{found} where a number, a name or '(' is expected", pos)

    def name(self, token: str, pos: int):
        if token in SYMBOLS:
            return SYMBOLS[token], 0, 1.0
        if token in CONSTANTS:
            return CONSTANTS[token], 0, 1.0
        kind, op, at = self.take()
        if (kind, op) != ("op", "("):
            self.fail(f"the function {token!r} needs its argument in parentheses", at)
        self.count(pos)
        self.enter(at)
        arg, tower, growth = self.sum()
        self.expect(")", at)
        self.depth -= 1
        function = FUNCTIONS[token]
        if function in _GROWING:
            value = self.value(arg)
            if not abs(value) <= MAX_LOG:  # also NaN
                self.fail(
                    f"{token} of {value:.3g} at the undeformed state: beyond the largest"
                    f" double 1.8e308 (need |argument| <= {MAX_LOG:g} there)",
                    pos,
                )
        return function(arg), tower, growth

    def number(self, token: str, pos: int) -> sp.Number:
        value = float(token)
        if math.isinf(value):
            self.fail(f"the number {_short(token)} is beyond the largest double 1.8e308", pos)
        if value == 0 and any(c in "123456789" for c in token.split("e")[0].split("E")[0]):
            self.fail(f"the number {_short(token)} is below the smallest double 5e-324", pos)
        # exactly what sympify made of a literal (its auto_number): Float of the text when
        # it has a point or an exponent, else Integer
        if "." in token or "e" in token or "E" in token:
            return sp.Float(token)
        return sp.Integer(int(token))

    # -- sizes at the undeformed state ----------------------------------------------------

    def value(self, expr) -> float:
        """``expr`` at the undeformed state, in floating point (inf or NaN where it is not
        finite); never evaluates sympy numbers exactly."""
        if expr in self.values:
            return self.values[expr]
        value = undeformed_value(expr, self.value)
        self.values[expr] = value
        return value

    def exponent_size(self, exponent, pos: int) -> float:
        value = self.value(exponent)
        if not math.isfinite(value):
            self.fail("an exponent that is not finite at the undeformed state", pos)
        return max(1.0, abs(value))

    def check_power(self, base, exponent, pos: int) -> None:
        """Refuse base**exponent whose size is beyond e^MAX_LOG at the undeformed state,
        or whose base's numeric factor sympy would raise to such a size exactly."""
        e = self.value(exponent)
        if not math.isfinite(e):
            self.fail("an exponent that is not finite at the undeformed state", pos)
        sizes = [log_height(base) if base.is_Rational else log_size(self.value(base))]
        if exponent.is_Number:  # sympy distributes (c x)**k into c**k x**k
            coefficient = base.as_coeff_Mul()[0]
            if coefficient.is_Rational and coefficient != 0:
                sizes.append(log_height(coefficient))
        for size in sizes:
            if size is None:
                self.fail("a power whose base is not finite at the undeformed state", pos)
            if abs(e * size) > MAX_LOG:
                self.fail(
                    f"a power of size about e^{e * size:.3g} at the undeformed state, beyond"
                    f" the range of doubles (e^-{MAX_LOG:g} to e^{MAX_LOG:g}, 1.8e308)",
                    pos,
                )

    def check_numbers(self, expr: sp.Expr) -> None:
        """Every number sympy combined into the expression is a double (the numerical code
        and lambdify read them as such)."""
        for number in expr.atoms(sp.Number):
            if number.is_Rational:
                too_big = log_height(number) > 709.0
            else:
                too_big = not math.isfinite(as_float(number))
            if too_big:
                self.fail("the numbers combine into one beyond the largest double 1.8e308")
