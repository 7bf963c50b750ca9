"""Output files written whole or not at all.

:func:`replaced` writes a file under a temporary name in the same directory and renames it
into place (``os.replace``, atomic on POSIX and Windows): two commands writing the same
output at once each leave a complete file (the last one wins), and a command stopped
mid-write (Ctrl-C, a full disk) leaves the previous file as it was, never half a file.
:func:`replaced_name` gives such a name to writers that take one (meshio's, netCDF's);
:func:`write_figure` and :func:`write_text` are the common cases.
"""

from __future__ import annotations

import contextlib
import functools
import os
import tempfile
from pathlib import Path


@contextlib.contextmanager
def replaced(path: str | Path, mode: str = "w", **open_args):
    """``open(path, mode)`` for writing, the file taking ``path``'s place only when the block
    ends without an exception; the directory is created if missing."""
    with replaced_name(path) as name, open(name, mode, **open_args) as fh:
        yield fh  # closed before the rename: the inner block ends first


@contextlib.contextmanager
def replaced_name(path: str | Path):
    """A temporary file name next to ``path`` for a writer that takes a name (meshio,
    netCDF), the file taking ``path``'s place only when the block ends without an
    exception. The name keeps the suffix, by which such writers choose their format."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.stem}.", suffix=path.suffix, dir=path.parent)
    os.close(fd)
    try:
        yield tmp
        os.chmod(tmp, 0o666 & ~_umask())
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


def write_figure(figure, path: str | Path, dpi: int = 200) -> Path:
    """A matplotlib figure saved to ``path`` in the format of its suffix (PNG, SVG, ...),
    whole or not at all."""
    path = Path(path)
    with replaced(path, "wb") as fh:
        figure.savefig(fh, dpi=dpi, format=path.suffix.lstrip(".") or "png")
    return path


def write_text(path: str | Path, text: str) -> Path:
    """``text`` written to ``path`` (UTF-8), whole or not at all."""
    with replaced(path, encoding="utf-8") as fh:
        fh.write(text)
    return Path(path)


@functools.cache
def _umask() -> int:
    """The process's umask (read by setting it: once, and put back at once)."""
    mask = os.umask(0o022)
    os.umask(mask)
    return mask
