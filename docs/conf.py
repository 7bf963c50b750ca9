"""Sphinx configuration of the electrogrowth documentation (``make docs``)."""

import os
import re
import sys
from pathlib import Path

os.environ.setdefault("MPLBACKEND", "Agg")
HERE = Path(__file__).parent
sys.path.insert(0, str(HERE / "_ext"))

import electrogrowth  # noqa: E402

project = "electrogrowth"
author = "the electrogrowth developers"
copyright = "the electrogrowth developers"
release = version = electrogrowth.__version__

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.napoleon",
    "sphinx.ext.mathjax",
    "sphinx-mathjax-offline",  # MathJax from the package, not from a CDN: the site works offline
    "sphinx.ext.viewcode",
    "myst_parser",
    "sphinx_gallery.gen_gallery",
    "pattern_viewer",  # _ext/: the interactive 3D pattern of the gallery, written at build
]
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
exclude_patterns = ["_build", "_ext", "gallery/*.ipynb", "gallery/*.py", "**/*.csv"]
myst_enable_extensions = ["dollarmath", "amsmath"]
myst_heading_anchors = 3
# The theory notes are plain markdown files also read on the repository's web view: their
# links to source files (src/..., tests/...) are not pages of this site.
suppress_warnings = ["myst.xref_missing", "myst.domains", "ref.python"]


def _plain_bars(app, what, name, obj, options, lines):
    """Docstrings write |U| for a norm; reStructuredText would read a substitution."""
    lines[:] = [re.sub(r"(?<![\\`])\|(?=\S)([^|`]+?)(?<=\S)\|", r"\\|\1\\|", x) for x in lines]


def setup(app):
    app.connect("autodoc-process-docstring", _plain_bars)


# The CLI reference (cli.md) is written from the parser before the sources are read.
from cli_parser import write_reference  # noqa: E402

write_reference(HERE / "cli.md")


autodoc_member_order = "bysource"
autodoc_typehints = "description"
autodoc_default_options = {"members": True, "undoc-members": False, "show-inheritance": False}
napoleon_numpy_docstring = True
napoleon_google_docstring = False

# Option names (--inner-radius) must stay two hyphens, not an en dash.
smartquotes = False

html_theme = "furo"
html_title = f"electrogrowth {release}"
html_static_path = []

sphinx_gallery_conf = {
    "examples_dirs": str(HERE.parent / "examples" / "gallery"),
    "gallery_dirs": "gallery",
    "filename_pattern": r"plot_",
    # Subsections are the subfolders (each with its README.txt), in the order of the
    # pipeline: one tube, layered tubes, sweeps, the inverse question (design), then past
    # onset by finite elements (postbuckle).
    "subsection_order": [  # paths relative to this directory, as sphinx-gallery wants
        f"../examples/gallery/{s}" for s in ("basics", "layered", "sweeps", "design", "postbuckle")
    ],
    "within_subsection_order": "FileNameSortKey",
    "image_scrapers": ("gallery_scraper.scraper",),
    "remove_config_comments": True,
    "capture_repr": ("_repr_html_", "__repr__"),
    "download_all_examples": False,
    "show_memory": False,
    "default_thumb_file": None,
}
