"""Drawing a project's figures: which there are, the longest first, over two processes where a fork is possible, and a batch worker's cache of the figures that repeat between variants."""

from __future__ import annotations

from pathlib import Path


# Figures that depend only on the planetary reducer, i.e. on design_gears' inputs other than the
# cam speed; a batch with one crank speed draws them once per worker process (see figure_cache).
REDUCER_FIGURES = ("gears_planetary", "gears_assembly")


def _reducer_key(gears, lang: str, fmt: str) -> tuple:
    return (gears.crank_rpm, gears.motor_rpm, gears.tolerance_pct, gears.forced_ratio, gears.forced_planets, lang, fmt)


GEAR_FIGURES = ("gears_planetary", "gears_assembly", "gears_mesh")


CAM_FIGURES = ("cam_motion", "cam_zone", "cam_profile", "cam_pressure_angle", "cam_profile_scaled")


ALL_FIGURES = GEAR_FIGURES + CAM_FIGURES  # sheet 4 first, as in the report


# Rough time [s] of drawing and saving each figure (PNG at 120 dpi, its SVG copy for the note),
# variant 17: only to draw the long ones first.
_COST = {"gears_planetary": (0.45, 0.2), "gears_assembly": (0.25, 0.1), "gears_mesh": (0.6, 0.35),
         "cam_motion": (0.65, 0.15), "cam_zone": (0.45, 0.2), "cam_profile": (0.3, 0.15),
         "cam_pressure_angle": (0.2, 0.1), "cam_profile_scaled": (0.1, 0.05)}


def _largest_first(names, svg) -> list:
    """The figures to draw, the longest first (so that the last ones, taken by whichever process
    is free, are short).

    >>> _largest_first(["cam_profile_scaled", "gears_assembly", "gears_mesh"], set())
    ['gears_mesh', 'gears_assembly', 'cam_profile_scaled']
    """
    def cost(n):
        png, copy = _COST.get(n, (0.4, 0.2))
        return png + (copy if n in svg else 0.0)

    return sorted(names, key=cost, reverse=True)


def _figure_task(tmp: Path, result, lang: str, fmt: str, name: str, svg):
    return lambda: _draw_and_save(tmp, result, lang, fmt, [name], svg)


def prepare_figures(svg, note: bool = False) -> None:
    """What every process that draws needs, built once before a fork: the figure modules, mathtext
    and the fonts, the SVG backend if SVG files are wanted (`svg` true, or the note's figures:
    `note`, with the note's font)."""
    from . import cam, gears  # noqa: F401  (loaded before the fork)
    from .kit import _warm_up

    _warm_up()
    if svg or note:
        from .kit import share_svg_text

        share_svg_text()
    if note:
        from .note import _fonts

        _fonts()
    calm_collector()


def calm_collector() -> None:
    """Python's cycle collector, told what lives to the end: everything loaded so far (the modules,
    matplotlib's fonts and grammar) is frozen out of its scans (`gc.freeze`, as Python's manual
    advises before a fork), and it runs after 10 000 new objects instead of 700. A figure is
    thousands of small objects in cycles; with the defaults the collector took ≈ 10 % of drawing
    time, walking the whole heap again and again (≈ 0.15 s per variant, ≈ 0.07 s after this)."""
    import gc

    gc.freeze()
    gc.set_threshold(10_000, 50, 100)


def _draw_and_save(tmp: Path, result, lang: str, fmt: str, names, svg) -> None:
    """Draw the figures `names` once and save each as `fmt`, and as SVG too if it is in `svg`."""
    from .cam import cam_figures
    from .gears import gears_figures
    from .save import save_figures

    gear = [n for n in names if n in GEAR_FIGURES]
    cam = [n for n in names if n in CAM_FIGURES]
    figs = {**(gears_figures(result.gears, lang, names=gear) if gear else {}),
            **(cam_figures(result.cam, lang, names=cam) if cam else {})}
    save_figures(tmp, figs, fmt)
    if svg:
        from .kit import share_svg_text

        share_svg_text()
    for name, fig in figs.items():
        if name in svg:
            fig.savefig(tmp / f"{name}.svg", format="svg")  # the same drawn figure, another renderer


def _mesh_key(gears, lang: str, fmt: str) -> tuple:
    return ("mesh", repr(gears.spur), gears.directions, lang, fmt)


def _from_cache(tmp: Path, result, lang: str, fmt: str, svg, cache: dict, shared=None):
    """Write the figures a batch worker drew already for another variant (the reducer's two,
    which depend only on the reducer; the spur mesh, which depends only on the spur pair and
    the senses of rotation); draw and keep them on a miss.

    `shared` (a :class:`~tmm_cli.render.figures.shared.SharedFigures`, the batch's workers' common
    folder) is asked on a miss: a drawing another worker published is taken from it; one another
    worker is drawing now is put off to the end of the row. Returns (the names written or put
    off, a function that writes the put-off ones: call it once the row's other figures are done).
    """
    written, later = set(), []

    def draw(group):
        _draw_and_save(tmp, result, lang, fmt, group, svg)
        paths = [f"{n}.{fmt}" for n in group] + [f"{n}.svg" for n in group if n in svg]
        return {p: (tmp / p).read_bytes() for p in paths}

    def write(entry):
        for p, data in entry.items():
            (tmp / p).write_bytes(data)

    for group, key in ((REDUCER_FIGURES, _reducer_key(result.gears, lang, fmt)),
                       (("gears_mesh",), _mesh_key(result.gears, lang, fmt))):
        key = (*key, tuple(sorted(n for n in group if n in svg)))
        written.update(group)
        entry = cache.pop(key, None)
        if entry is None and shared is not None:
            entry = shared.get(key)
            if entry is None and not shared.claim(key):  # another worker draws it right now
                later.append((group, key))
                continue
            if entry is None:
                entry = draw(group)
                shared.put(key, entry)
            else:
                write(entry)
        elif entry is None:
            entry = draw(group)
        else:
            write(entry)
        cache[key] = entry  # the most recently used last (the batch drops the oldest)

    def finish() -> None:
        for group, key in later:
            entry = shared.wait(key)
            if entry is None:  # the other worker failed or was stopped: draw it here
                entry = draw(group)
            else:
                write(entry)
            cache[key] = entry

    return written, finish
