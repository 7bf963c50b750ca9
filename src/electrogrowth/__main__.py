"""``python -m electrogrowth``: the command line of :mod:`electrogrowth.cli.app`."""

from .cli import main

raise SystemExit(main())
