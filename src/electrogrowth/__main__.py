"""``python -m electrogrowth``: the command line of :mod:`electrogrowth.cli`."""

from .cli import main

raise SystemExit(main())
