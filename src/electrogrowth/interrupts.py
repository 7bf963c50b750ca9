"""Ctrl-C and SIGTERM: one exception for both, and how to recognise it when it comes wrapped.

While :func:`signals_as_interrupts` is active (the command line's ``main`` and a sweep hold
it), SIGINT and SIGTERM (a batch scheduler's time limit, ``kill``) raise :class:`Interrupted`
in the main thread, so SIGTERM too unwinds through every ``finally``: a sweep stops its
workers, a curve hands back the points it has computed, and the command exits with
128 + the signal's number (130, 143) after one line on stderr.

A signal that arrives while a compiled (numba) kernel runs surfaces as ``SystemError:
... returned a result with an exception set``, the KeyboardInterrupt as its ``__cause__``.
Code that keeps failures as data (a curve's points, a sweep's points) must not file that as
a failed point: :func:`reraise_interrupt` raises it again as the interrupt it is.
"""

from __future__ import annotations

import contextlib
import os
import signal
import sys
import threading

#: The signal received while :func:`signals_as_interrupts` is active (None: none yet); a
#: SystemError raised after it is the wrapped interrupt even where no cause is attached.
_received: int | None = None


class Interrupted(KeyboardInterrupt):
    """The computation was stopped by signal ``signum`` (SIGINT: Ctrl-C; SIGTERM).

    ``partial`` holds what was finished, where the interrupted call can hand it back (a
    curve's computed points); ``text`` replaces the default message, e.g. to say where the
    finished part was written."""

    def __init__(self, signum: int = signal.SIGINT, text: str = "", partial=None):
        self.signum = int(signum)
        self.partial = partial
        if not text:
            text = "interrupted" if signum == signal.SIGINT else f"terminated by signal {signum}"
        super().__init__(text)

    def __reduce__(self):  # pickled (a process pool's worker) with its fields
        return type(self), (self.signum, str(self), self.partial)

    @property
    def exit_status(self) -> int:
        """The shell's convention for a process ended by a signal: 128 + its number."""
        return 128 + self.signum


def _raise(signum, frame):
    global _received
    _received = signum
    raise Interrupted(signum)


@contextlib.contextmanager
def signals_as_interrupts():
    """Within the block (in the main thread; elsewhere a no-op), SIGINT and SIGTERM raise
    :class:`Interrupted`. A SIGINT that is ignored (a background job of a shell) stays
    ignored; the previous handlers come back at the end."""
    global _received
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = {}
    for sig in (signal.SIGINT, signal.SIGTERM):
        if signal.getsignal(sig) is not signal.SIG_IGN:
            previous[sig] = signal.signal(sig, _raise)
    _received = None
    hook, sys.unraisablehook = sys.unraisablehook, _redeliver(sys.unraisablehook)
    try:
        yield
    finally:
        sys.unraisablehook = hook
        for sig, handler in previous.items():
            signal.signal(sig, handler)


#: seconds before a signal caught in a finaliser is sent again (the finaliser is long gone)
REDELIVER = 0.01


def _redeliver(hook):
    """An unraisable-exception hook for the block: a signal that lands in a finaliser (a
    ``__del__``, e.g. llvmlite's while numba compiles) raises there, where Python can only
    print the exception and carry on; the signal is sent again instead, a moment later
    from another thread (sent from here it would be handled inside this hook again), so
    the code that runs next is interrupted, with one line and no traceback. Anything else
    goes to ``hook``."""

    def handle(info):
        if isinstance(info.exc_value, Interrupted):
            again = threading.Timer(REDELIVER, os.kill, (os.getpid(), info.exc_value.signum))
            again.daemon = True
            again.start()
            return
        hook(info)

    return handle


def interrupt_of(exc: BaseException) -> Interrupted | None:
    """The interrupt that ``exc`` is or wraps (its ``__cause__``/``__context__`` chain, or a
    SystemError raised after a signal arrived), as an :class:`Interrupted`; None for any
    other exception."""
    seen = set()
    link = exc
    while link is not None and id(link) not in seen:
        if isinstance(link, Interrupted):
            return link
        if isinstance(link, KeyboardInterrupt):
            return Interrupted(signal.SIGINT)
        seen.add(id(link))
        link = link.__cause__ or link.__context__
    if isinstance(exc, SystemError) and _received is not None:
        return Interrupted(_received)
    return None


def reraise_interrupt(exc: BaseException) -> None:
    """Raise the interrupt ``exc`` is or wraps (see :func:`interrupt_of`); else return."""
    stop = interrupt_of(exc)
    if stop is not None:
        raise stop from None
