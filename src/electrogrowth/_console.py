"""The ``electrogrowth`` console script and ``python -m electrogrowth``.

Loading the command line takes a few tenths of a second (its modules, argparse), before
:func:`electrogrowth.cli.main` installs the handling of Ctrl-C: an interrupt in that window
is one line and exit status 130 here too, never Python's traceback. This module imports
nothing of the package until :func:`main` runs.
"""

from __future__ import annotations

import sys


def main() -> int:
    """Load the command line, then run it (its exit status)."""
    try:
        from .cli import main as run
    except KeyboardInterrupt:
        print("electrogrowth: interrupted", file=sys.stderr)
        return 130
    return run()
