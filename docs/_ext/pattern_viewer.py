"""Writes the interactive 3D pattern of the gallery's 3D example into the built site.

The page ``_static/pattern-3d.html`` (a self-contained WebGL viewer, no network; see
``electrogrowth.figures.viewer``) is computed once per HTML build, for the tube and mode of
``examples/gallery/basics/plot_05_pattern_3d.py``, which embeds it.
"""

from pathlib import Path


def _write(app, exception):
    if exception is not None or app.builder.format != "html":
        return
    from electrogrowth import Tube, critical_value, mode_shape
    from electrogrowth.figures.viewer import write_pattern_html

    tube = Tube.uniform(outer_radius=1.4, length=1.0, stretch=1.0, voltage=0.4)
    shape = mode_shape(critical_value(tube, 3, 1, "growth"), points=41)
    out = Path(app.outdir) / "_static" / "pattern-3d.html"
    write_pattern_html(shape, out, amplitude=0.08, n_theta=90, n_z=40)


def setup(app):
    app.connect("build-finished", _write)
    return {"parallel_read_safe": True}
