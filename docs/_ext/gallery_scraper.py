"""A sphinx-gallery image scraper for the figures of an example.

The package draws on ``matplotlib.figure.Figure`` objects that pyplot does not manage (so
that importing it never opens a window); the default scraper sees only pyplot's figures.
This one saves both: every pyplot figure, and every Figure held by a variable of the
example that was not saved before (e.g. ``fig = render_pattern(...)``), then closes them.
"""

from matplotlib.figure import Figure

_SEEN: dict[str, set[int]] = {}


def scraper(block, block_vars, gallery_conf):
    import matplotlib.pyplot as plt
    from sphinx_gallery.scrapers import figure_rst

    seen = _SEEN.setdefault(block_vars["src_file"], set())
    figures = [plt.figure(num) for num in plt.get_fignums()]
    figures += [
        v
        for v in block_vars["example_globals"].values()
        if isinstance(v, Figure) and v not in figures and id(v) not in seen
    ]
    paths = []
    for fig, path in zip(figures, block_vars["image_path_iterator"]):
        fig.savefig(path, dpi=110)
        seen.add(id(fig))
        paths.append(path)
    plt.close("all")
    return figure_rst(paths, gallery_conf["src_dir"])
