"""The ``electrogrowth`` command line: the dispatcher (:mod:`.app`), the shared options
(:mod:`.options`) and one module per command (state, figure, critical, curve, pattern, demo,
reproduce, sweep).

The top of the ladder: may import every stage; nothing imports it.
"""

from .app import main

__all__ = ["main"]
