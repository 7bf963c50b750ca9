"""A package's public names imported on first use (PEP 562).

A package face (``electrogrowth``, ``electrogrowth.bifurcation``, ``electrogrowth.model``)
lists where each of its names lives; :func:`attribute` imports that module when the name is
first read, so that importing one module of a package (``bifurcation.critical``) does not
import its siblings (the crease, the curves, the scan). ``from package import name`` and
``dir(package)`` keep working; a submodule that is not a listed name is imported by the
import system itself (``attribute`` raises AttributeError for it, as PEP 562 asks).
"""

from __future__ import annotations

import importlib


def module_of(exports: dict[str, tuple[str, ...]]) -> dict[str, str]:
    """name -> its module (relative to the package), from module -> names."""
    return {name: module for module, names in exports.items() for name in names}


def attribute(package: str, where: dict[str, str], name: str, namespace: dict) -> object:
    """The public ``name`` of ``package`` imported from its module, then kept in the
    package's ``namespace`` (its globals: read again it is a plain attribute)."""
    try:
        module = where[name]
    except KeyError:
        raise AttributeError(f"module {package!r} has no attribute {name!r}") from None
    value = getattr(importlib.import_module(module, package), name)
    namespace[name] = value
    return value
