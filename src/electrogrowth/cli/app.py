"""The ``electrogrowth`` command line (also ``python -m electrogrowth``).

Each subcommand is a pair of functions in :data:`COMMANDS`: ``configure(parser)`` adds its
options, ``run(args) -> int`` does the work. :func:`main` parses, dispatches and turns every
failure into one line ``electrogrowth: error: <message>`` on stderr with exit status 2
(1 for an unexpected internal error); no traceback reaches the user. Ctrl-C and SIGTERM
stop any command with one line (``electrogrowth: interrupted; ...``, saying what was kept)
and exit status 130 / 143 (interrupts.py). To add a subcommand,
write the two functions (a module of this package) and add an entry to :data:`COMMANDS`;
figures are registered in ``electrogrowth.figures.FIGURES``.
"""

from __future__ import annotations

import argparse
import contextlib
import importlib
import logging
import os
import re
import sys
import warnings
from collections.abc import Callable
from importlib.metadata import version
from pathlib import Path

from ..errors import BaseStateError, ElectrogrowthError, UsageError
from ..interrupts import Interrupted, interrupt_of, signals_as_interrupts
from .report import flush_notes
from .units import resolve_units


def _lazy(module: str, name: str) -> Callable:
    """``name`` of the command module ``cli/<module>.py``, imported when first called: the
    commands import the numeric stack (numba, sympy, scipy), which `--help` and `--version`
    of the dispatcher do not need."""

    def call(*args):
        return getattr(importlib.import_module(f".{module}", __package__), name)(*args)

    call.__name__ = call.__qualname__ = name
    return call


PROG = "electrogrowth"


class _Parser(argparse.ArgumentParser):
    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        # A value such as -inf, -1e5, -nan or -2mm is a (bad) number or quantity, not an
        # unknown option: let the option's type or range check name it instead of
        # "expected one argument".
        self._negative_number_matcher = _NEGATIVE_NUMBER

    def error(self, message):
        raise UsageError(message)

    def parse_known_args(self, args=None, namespace=None):
        # every parser of the command line passes here (a command's subparser too)
        words = self._values_attached(sys.argv[1:] if args is None else list(args))
        try:
            found, extras = super().parse_known_args(words, namespace)
        except UsageError as exc:  # "SWEEP.toml is required": the file was read as an option
            raise self._unknown_option(words) or exc from None
        unknown = self._unknown_option(extras)
        if unknown is not None:
            raise unknown
        return found, extras

    def _unknown_option(self, words: list[str]) -> UsageError | None:
        """The refusal of the first word (before "--") that argparse reads as an option this
        command does not have, e.g. a file ``-x.toml``; None if there is none (or this is
        the dispatcher, which hands a command's options on to its parser). Never taken as a
        file: what a command line means must not depend on which files exist (a mistyped
        option that names a file would run on it), as GNU tools refuse ``rm -x.toml``."""
        if self._subparsers is not None:
            return None
        for word in words:
            if word == "--":
                return None
            if self._reads_as_unknown_option(word):
                return UsageError(self._not_an_option(word))
        return None

    def _reads_as_unknown_option(self, word: str) -> bool:
        try:
            found = self._parse_optional(word)  # argparse's own reading of the word
        except UsageError:  # an ambiguous abbreviation: argparse names it itself
            return False
        if found is None:  # a positional (a negative number, "-", a word with a space)
            return False
        tuples = found if isinstance(found, list) else [found]  # a list from Python 3.12.7
        return all(t[0] is None for t in tuples)

    def _not_an_option(self, word: str) -> str:
        """One line naming ``word``; where it may be a file (one of that name exists, or the
        command takes a path), how to give it as one."""
        command = self.prog.split()[-1]
        text = f"{word} is not an option of {command} (see {self.prog} --help)"
        # by name: cli/options.py (path_arg) imports the model, which --help need not load
        takes_path = any(
            not a.option_strings and getattr(a.type, "__name__", "") == "path_arg"
            for a in self._actions
        )
        if os.path.lexists(word):
            return f"{text}; to give the file {word}, write ./{word} or put -- before it"
        if takes_path:
            return f"{text}; a file whose name starts with '-' is written ./{word} or after --"
        return text

    def _values_attached(self, words: list[str]) -> list[str]:
        """``--energy -10*log(1-(I1-3)/20)+I5/2`` as ``--energy=-10*log(...)+I5/2``: a word
        after an option that takes one value is that value, even if it starts with "-" (an
        energy, a path, a name), unless it is one of this parser's options or starts with
        "--". argparse would read it as an unknown option ("expected one argument"), so a
        value refused is named by the option's own check instead."""
        attached: list[str] = []
        i = 0
        while i < len(words):
            word, value = words[i], words[i + 1] if i + 1 < len(words) else ""
            if word == "--":  # the rest are positional, as given
                return attached + words[i:]
            if self._takes_one_value(word) and self._is_dashed_value(value):
                attached.append(f"{word}={value}")
                i += 2
            else:
                attached.append(word)
                i += 1
        return attached

    def _takes_one_value(self, word: str) -> bool:
        """Whether ``word`` names an option of this parser that takes exactly one value (as
        argparse reads it: exactly, or as the unique abbreviation of a long option)."""
        action = self._option_string_actions.get(word)
        if action is None and word.startswith("--") and len(word) > 2:
            found = {a for s, a in self._option_string_actions.items() if s.startswith(word)}
            action = found.pop() if len(found) == 1 else None
        return action is not None and action.nargs is None

    def _is_dashed_value(self, word: str) -> bool:
        return (
            word.startswith("-")
            and not word.startswith("--")
            and word not in self._option_string_actions
        )


_FLOATING_POINT = r"(overflow|invalid value|divide by zero|underflow) encountered"
#: a negative number, optionally with a unit (a quantity: -2mm, -3 kV, -1e5 N/m^2)
_NEGATIVE_NUMBER = re.compile(
    r"^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?(\s*[^\W\d_]\S*(\s+\S+)*)?$|^-(inf|infinity|nan)$", re.I
)


#: Subcommand name -> (one-line help, configure(parser), run(args) -> exit status).
COMMANDS: dict[str, tuple[str, Callable, Callable]] = {
    "state": (
        "solve the axisymmetric base state of a grown, stretched, charged tube",
        _lazy("state", "configure_state"),
        _lazy("state", "run_state"),
    ),
    "figure": (
        "reproduce a figure of the paper (PNG + CSV)",
        _lazy("figure", "configure_figure"),
        _lazy("figure", "run_figure"),
    ),
    "critical": (
        "critical growth factor, axial stretch or voltage for the onset of"
        " wrinkling, for one mode or scanned over modes",
        _lazy("critical", "configure_critical"),
        _lazy("critical", "run_critical"),
    ),
    "demo": (
        "the paper's headline tube (Rbar_o = 1.4, L = 1, lambda_z = 1, Vbar = 0.4):"
        " base state, critical growth and mode, curve and 3D pattern",
        _lazy("demo", "configure_demo"),
        _lazy("demo", "run_demo"),
    ),
    "pattern": (
        "mode shape of the wrinkles at onset: 3D picture, plot and CSV, VTK mesh of the wall",
        _lazy("pattern", "configure_pattern"),
        _lazy("pattern", "run_pattern"),
    ),
    "curve": (
        "critical value along a parameter, with the mode switches located",
        _lazy("curve", "configure_curve"),
        _lazy("curve", "run_curve"),
    ),
    "postbuckle": (
        "the post-buckled cross-section of a prismatic mode by finite elements (the fe extra)",
        _lazy("postbuckle", "configure_postbuckle"),
        _lazy("postbuckle", "run_postbuckle"),
    ),
    "design": (
        "which value of one design variable gives the wanted pattern, with the widest margin",
        _lazy("design", "configure_design"),
        _lazy("design", "run_design"),
    ),
    "reproduce": (
        "the paper's Figures 4-10, the 3D patterns of Figs 9B/10B and an index page",
        _lazy("reproduce", "configure_reproduce"),
        _lazy("reproduce", "run_reproduce"),
    ),
    "sweep": (
        "critical points over a grid of tubes, in parallel, into a resumable Zarr store",
        _lazy("sweep", "configure_sweep"),
        _lazy("sweep", "run_sweep"),
    ),
    "plot": (
        "phase diagram (PNG + SVG) of a sweep store",
        _lazy("sweep", "configure_plot"),
        _lazy("sweep", "run_plot"),
    ),
}


def build_parser(command: str | None = None) -> argparse.ArgumentParser:
    """The parser of every command (``command`` None), or with only ``command``'s options
    configured (the others keep their one-line help): `electrogrowth --help` then imports no
    command module. ``command = ""`` configures none."""
    parser = _Parser(
        prog=PROG,
        description="Growth, voltage and wrinkling of soft"
        " electro-elastic tubes (units mu = eps = R_i = 1).",
    )
    parser.add_argument("--version", action="version", version=f"%(prog)s {version(PROG)}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for name, (help_text, configure, run) in COMMANDS.items():
        cmd = sub.add_parser(name, help=help_text, description=help_text)
        if command is None or name == command:
            configure(cmd)
        cmd.set_defaults(run=run)
    return parser


def _command_of(argv: list[str] | None) -> str:
    """The subcommand named on the command line ("" for none: `--help`, `--version`)."""
    words = sys.argv[1:] if argv is None else argv
    return next((w for w in words if w in COMMANDS), "")


def main(argv: list[str] | None = None) -> int:
    """Run the command line; return the exit status (0 ok, 2 bad input, 1 internal error,
    130 / 143 interrupted by SIGINT (Ctrl-C) / SIGTERM)."""
    try:
        with signals_as_interrupts(), warnings.catch_warnings():
            # numpy's floating-point warnings (an overflow while a solver probes beyond a
            # threshold) are not the user's to read: a result is checked, a failure named
            warnings.filterwarnings("ignore", _FLOATING_POINT, RuntimeWarning)
            status = _dispatch(argv)
    except KeyboardInterrupt as exc:  # also while the handlers are put back
        status = _interrupted(interrupt_of(exc))
    if status > 128:
        _quiet_exit()
    return status


def _quiet_exit() -> None:
    """After an interrupt, the work a library had in flight (zarr's asyncio tasks) is
    destroyed at exit: its "Task was destroyed but it is pending!" and "coroutine ... was
    never awaited" would follow the one line."""
    logging.getLogger("asyncio").setLevel(logging.CRITICAL)
    warnings.filterwarnings("ignore", r"coroutine .* was never awaited", RuntimeWarning)


def _dispatch(argv: list[str] | None) -> int:
    """Parse and run; every failure becomes one line on stderr (no traceback)."""
    words = sys.argv[1:] if argv is None else argv
    flush_notes(keep=False)  # none left by an earlier call in this process
    if not words:  # no command: the overview on stdout and success, as `pip` does
        build_parser("").print_help()
        return 0
    try:
        try:
            args = build_parser(_command_of(argv)).parse_args(argv)
        except SystemExit as done:  # --help, --version
            return done.code if isinstance(done.code, int) else 0
        resolve_units(args)
        try:
            code = args.run(args)
            flush_notes()  # how the input was read, once it was all accepted
            return code
        except BaseStateError as exc:  # a load beyond its threshold: its file line, if any,
            # and its value and threshold in the units the user gave (kV, kPa)
            from .report import beyond_in_units
            from .tube_input import located  # the model's import only when it is needed

            raise located(beyond_in_units(exc, getattr(args, "scales", None)), args) from None
    except ElectrogrowthError as exc:  # bad input, or a failure with a remedy
        text = " ".join(str(exc).split())
        remedy = f" ({exc.remedy})" if exc.remedy else ""  # a Remedy's text: the CLI form
        print(f"{PROG}: error: {text}{remedy}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # the reader went away (e.g. `| head`): end quietly
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # no flush error
        return 0
    except OSError as exc:  # an output path that is a file, unwritable, a full disk
        if exc.filename is None:
            return _internal_error(exc)
        print(f"{PROG}: error: {_path_problem(exc)}", file=sys.stderr)
        return 2
    except KeyboardInterrupt as exc:
        return _interrupted(interrupt_of(exc))
    except Exception as exc:  # a bug: still one line, never a traceback
        stop = interrupt_of(exc)  # a signal inside a compiled kernel: a wrapped interrupt
        if stop is not None:
            return _interrupted(stop)
        return _internal_error(exc)


def _internal_error(exc: BaseException) -> int:
    print(
        f"{PROG}: internal error: {type(exc).__name__}: {' '.join(str(exc).split())}",
        file=sys.stderr,
    )
    return 1


def _path_problem(exc: OSError) -> str:
    """One line naming the path and what is wrong with it."""
    path = Path(exc.filename)
    if isinstance(exc, (FileExistsError, NotADirectoryError)):
        # the first of the path and its parents that is there but no directory (a dangling
        # link is there too: "an existing file" misnamed it, probe 8b)
        there = (p for p in (path, *path.parents) if os.path.lexists(p) and not p.is_dir())
        file = next(there, path)
        what = _what_is(file)
        tail = ", not a file" if what == "an existing file" else ""
        return f"{file} is {what}, not a directory: give --out a directory (new or existing){tail}"
    return f"cannot use {path}: {exc.strerror or exc}"


def _what_is(path: Path) -> str:
    """What a path that is no directory is, in words."""
    if path.is_symlink() and not path.exists():
        return f"a dangling symbolic link (to {os.readlink(path)}, which does not exist)"
    if path.is_file():
        return "an existing file"
    if path.is_fifo():
        return "a named pipe (FIFO)"
    if path.is_socket():
        return "a socket"
    if path.is_block_device() or path.is_char_device():
        return "a device"
    return "something other than a file"


def _interrupted(stop: Interrupted) -> int:
    """One line (what was kept, if the command said so) and 128 + the signal's number."""
    with contextlib.suppress(Exception, KeyboardInterrupt):  # a second Ctrl-C: still quiet
        print(f"{PROG}: {' '.join(str(stop).split())}", file=sys.stderr, flush=True)
    return stop.exit_status
