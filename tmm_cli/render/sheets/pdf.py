"""The PDF of a sheet, rendered from the very ezdxf document written as DXF.

ezdxf's drawing add-on with its matplotlib backend (DRAWING.md traps): ``adjust_figure=False``
keeps the 841 × 594 mm page, lineweights are scaled by 72/25.4 (the backend reads them as
points), black lines on white paper. The axes fill the page and span exactly the sheet's
millimetres, so 1 mm of the model is 1 mm of paper (print at 100 %).
"""

from __future__ import annotations

import math
from pathlib import Path

from .paper import FONT, SHEET_H, SHEET_W, mtext_runs, run_offsets

MM_PER_INCH = 25.4


def _backend(ax):
    """ezdxf's matplotlib backend, drawing the sheet as a few collections instead of an artist per
    entity. The sheet is black on white (ColorPolicy.BLACK): what is drawn in which order cannot
    show, so every line, path and fill of one colour and weight joins one collection, added at the
    end — a sheet of ~1200 artists becomes ~10, and matplotlib's per-artist cost (clip box, graphics
    context, PDF state) goes (half the time of the PDF). Filled paths are taken as given: the
    sheet's filled paths are glyphs of a TrueType font (outer contours and holes already wound
    opposite ways), arrow heads and dots, so ezdxf's hole detection is not needed. Line ends and
    joins are those of the artists ezdxf would have made (Line2D: projecting; paths: butt, miter)."""
    from ezdxf.addons.drawing.matplotlib import MatplotlibBackend
    from ezdxf.npshapes import to_matplotlib_path
    import numpy as np
    from matplotlib.collections import PathCollection
    from matplotlib.patches import PathPatch
    from matplotlib.path import Path as MplPath

    class SheetBackend(MatplotlibBackend):
        def __init__(self, *args, **kwargs):
            super().__init__(*args, **kwargs)
            self._segments: dict = {}  # (linewidth, colour, capstyle) -> [((x0, y0), (x1, y1)), ...]
            self._strokes: dict = {}  # (linewidth, colour) -> [Path, ...]
            self._fills: dict = {}  # colour -> [Path, ...]

        def draw_line(self, start, end, properties):
            if start.isclose(end):
                self.draw_point(start, properties)  # a dot, as ezdxf draws it
                return
            key = (self.get_lineweight(properties), properties.color, "projecting")
            self._segments.setdefault(key, []).append(((start.x, start.y), (end.x, end.y)))

        def draw_solid_lines(self, lines, properties):
            key = (self.get_lineweight(properties), properties.color, "butt")
            segments = self._segments.setdefault(key, [])
            for s, e in lines:
                if s.isclose(e):
                    self.draw_point(s, properties)
                else:
                    segments.append(((s.x, s.y), (e.x, e.y)))

        def draw_path(self, path, properties):
            try:
                mpl_path = to_matplotlib_path([path])
            except ValueError:  # an empty path
                return
            self._strokes.setdefault((self.get_lineweight(properties), properties.color), []).append(mpl_path)

        def draw_filled_paths(self, paths, properties):
            try:
                mpl_path = to_matplotlib_path(paths, detect_holes=False)
            except ValueError:  # an empty path: nothing to fill
                return
            self._fills.setdefault(properties.color, []).append(mpl_path)

        def draw_filled_polygon(self, points, properties):
            xy = [(p.x, p.y) for p in points.vertices()]
            if len(xy) > 2:
                self._fills.setdefault(properties.color, []).append(MplPath(xy + [xy[0]], closed=True))

        def finalize(self):
            z = self._get_z()
            for color, paths in self._fills.items():
                self.ax.add_collection(PathCollection(paths, facecolors=color, edgecolors="none", linewidths=0,
                                                      zorder=z), autolim=False)
            for (lw, color), paths in self._strokes.items():
                self.ax.add_collection(PathCollection(paths, facecolors="none", edgecolors=color, linewidths=lw,
                                                      capstyle="butt", joinstyle="miter", zorder=z), autolim=False)
            for (lw, color, cap), segments in self._segments.items():
                # one path of MOVETO/LINETO pairs: the PDF writer's cost is per path (a LineCollection
                # of ~500 segments took a quarter of a sheet's PDF time), the picture is the same
                verts = np.asarray(segments, dtype=float).reshape(-1, 2)
                path = MplPath(verts, np.tile([MplPath.MOVETO, MplPath.LINETO], len(segments)))
                path.should_simplify = False  # every segment drawn as given
                self.ax.add_patch(PathPatch(path, fill=False, edgecolor=color, linewidth=lw, capstyle=cap, zorder=z))
            super().finalize()

    return SheetBackend(ax, adjust_figure=False)


def _frontend(ctx, backend, cfg):
    """ezdxf's Frontend, with the sheets' MTEXT (a text with stacked indices, ``paper.mtext_content``)
    laid out here: ezdxf's own MTEXT layout raises an index instead of lowering it. Each run is
    drawn like a TEXT: the base at the cap height, an index at 0.7 of it, SUB_DROP lower — the
    positions the sheet measured when it placed the label."""
    from ezdxf.addons.drawing import Frontend
    from ezdxf.math import Matrix44

    class SheetFrontend(Frontend):
        def draw_mtext_entity(self, entity, properties):
            dxf = entity.dxf
            h = dxf.char_height
            content = entity.text
            wf = 1.0
            if content.startswith("\\W"):
                head, _, content = content.partition(";")
                wf = float(head[2:])
            from ezdxf.fonts import fonts

            name = properties.font.filename if properties.font else FONT
            cache = {}

            def measure(t, hh):
                f = cache.get(hh)
                if f is None:
                    f = cache[hh] = fonts.make_font(name, hh, wf)
                return f.text_width(t)

            ins = dxf.insert
            rot = Matrix44.z_rotate(math.radians(dxf.get("rotation", 0.0)))
            runs = run_offsets(mtext_runs(content), h, measure)
            ap = dxf.get("attachment_point", 7)
            if ap in (8, 9):  # bottom centre / right: the runs shifted by (half) their length
                total = max((dx + measure(t, hh) for t, dx, dy, hh in runs), default=0.0)
                shift = total / 2 if ap == 8 else total
                runs = [(t, dx - shift, dy, hh) for t, dx, dy, hh in runs]
            for t, dx, dy, hh in runs:
                m = Matrix44.scale(wf, 1.0, 1.0) @ Matrix44.translate(dx, dy, 0) @ rot @ Matrix44.translate(ins.x, ins.y, 0)
                self.pipeline.draw_text(t, m, properties, hh, "MTEXT")

    return SheetFrontend(ctx, backend, config=cfg)


def render_config():
    """The drawing add-on's configuration of the PDF: black on white, absolute lineweights read as
    points (× 72/25.4), linetypes drawn as their dashes (the default, stated)."""
    from ezdxf.addons.drawing.config import (
        BackgroundPolicy,
        ColorPolicy,
        Configuration,
        LinePolicy,
        LineweightPolicy,
    )

    return Configuration(
        color_policy=ColorPolicy.BLACK,
        background_policy=BackgroundPolicy.WHITE,
        lineweight_policy=LineweightPolicy.ABSOLUTE,
        lineweight_scaling=72.0 / MM_PER_INCH,
        line_policy=LinePolicy.ACCURATE,
    )


def draw(doc, backend) -> None:
    """Render the model space of `doc` through `backend` as the PDF does (tests record it)."""
    from ezdxf.addons.drawing import RenderContext

    _frontend(RenderContext(doc), backend, render_config()).draw_layout(doc.modelspace(), finalize=True)


def sheet_figure(doc):
    """A matplotlib Figure of the whole sheet at true size (no pyplot)."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(SHEET_W / MM_PER_INCH, SHEET_H / MM_PER_INCH))
    ax = fig.add_axes((0.0, 0.0, 1.0, 1.0))
    ax.set_axis_off()
    ax.set_xlim(0.0, SHEET_W)
    ax.set_ylim(0.0, SHEET_H)
    ax.set_autoscale_on(False)
    # the limits are the sheet, fixed: skip matplotlib's data-limit updates, which walk every
    # Bézier segment of every text glyph (seconds per sheet, for nothing)
    ax._update_patch_limits = lambda patch: None
    ax._update_line_limits = lambda line: None
    draw(doc, _backend(ax))
    ax.set_xlim(0.0, SHEET_W)
    ax.set_ylim(0.0, SHEET_H)
    ax.set_aspect("equal", adjustable="box")
    ax.set_position((0.0, 0.0, 1.0, 1.0))
    return fig


def save_pdf(doc, path: Path) -> None:
    """Write the sheet as a vector PDF of 841 × 594 mm (zlib level 1: half the time of the
    default level for a file 15 % larger)."""
    import matplotlib

    fig = sheet_figure(doc)
    with matplotlib.rc_context({"pdf.compression": 1}):
        fig.savefig(path, format="pdf")


def save_png(doc, path: Path, dpi: int = 60) -> None:
    """A raster preview of the sheet (documentation pictures)."""
    sheet_figure(doc).savefig(path, format="png", dpi=dpi)
