"""``python -m electrogrowth``: the command line of :mod:`electrogrowth.cli`."""

import sys

try:
    from .cli import main
except KeyboardInterrupt:  # Ctrl-C while the command line loads (before main handles it)
    print("electrogrowth: interrupted", file=sys.stderr)
    raise SystemExit(130) from None

raise SystemExit(main())
