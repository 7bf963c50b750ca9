"""``python -m electrogrowth``: the command line of :mod:`electrogrowth.cli`."""

from ._console import main

raise SystemExit(main())
