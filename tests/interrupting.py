"""A Ctrl-C at a chosen moment of a computation, for the tests of what an interrupted run
keeps (tests that import it call :func:`interrupt_scan_at`)."""

from electrogrowth.bifurcation import curves


def interrupt_scan_at(monkeypatch, number: int) -> None:
    """The ``number``-th mode scan of a curve (or a design's sequence) from now on raises a
    KeyboardInterrupt, as a Ctrl-C during it would; the others run as usual."""
    real, calls = curves.scan_modes, []

    def scan(*args, **kwargs):
        calls.append(1)
        if len(calls) == number:
            raise KeyboardInterrupt
        return real(*args, **kwargs)

    monkeypatch.setattr(curves, "scan_modes", scan)
