"""The command line's parser for the CLI reference (sphinx-argparse renders help texts as
reStructuredText, where |U| would be a substitution: the bars are escaped here)."""

import argparse

from electrogrowth.cli.app import build_parser


def _escape(text):
    return text.replace("|", "\\|") if isinstance(text, str) else text


def parser() -> argparse.ArgumentParser:
    top = build_parser()
    todo = [top]
    while todo:
        p = todo.pop()
        p.description = _escape(p.description)
        for group in p._action_groups:
            group.description = _escape(group.description)
        for action in p._actions:
            action.help = _escape(action.help)
            if isinstance(action, argparse._SubParsersAction):
                todo.extend(action.choices.values())
    return top
