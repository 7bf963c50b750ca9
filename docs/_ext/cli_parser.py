"""The command-line reference page, generated from the parser at build time.

``write_reference(path)`` writes ``cli.md``: for the dispatcher and each command, exactly
what ``electrogrowth [COMMAND] --help`` prints (a literal block, so nothing in a help text
is read as markup). Called by conf.py when the build starts; the file is not in git.
"""

import argparse
import os
from pathlib import Path

from electrogrowth.cli.app import COMMANDS, PROG, build_parser

HEAD = """# Command line

Generated from the argument parser: what `{prog} --help` and `{prog} COMMAND --help`
print. Every command takes `--json` where it prints a result; bad input is one line on
stderr and exit status 2.
"""


def _help(parser: argparse.ArgumentParser) -> str:
    os.environ["COLUMNS"] = "92"  # a fixed width: the page does not depend on the terminal
    return parser.format_help().rstrip()


def write_reference(path: Path) -> None:
    top = build_parser()
    subs = next(a for a in top._actions if isinstance(a, argparse._SubParsersAction))
    parts = [HEAD.format(prog=PROG), "```text", _help(top), "```", ""]
    for name in COMMANDS:
        parts += [f"## {PROG} {name}", "", "```text", _help(subs.choices[name]), "```", ""]
    text = "\n".join(parts)
    if not path.exists() or path.read_text(encoding="utf-8") != text:
        path.write_text(text, encoding="utf-8")
