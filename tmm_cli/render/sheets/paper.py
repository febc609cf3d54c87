"""The A1 sheet itself: an ezdxf document with the ESKD frame, title block, layers and text.

Everything is drawn in sheet millimetres (the model space origin is the sheet's lower-left
corner, 1 unit = 1 mm on paper). A :class:`Field` maps a drawing's own units (real millimetres
of the mechanism) to the sheet by ``sheet = origin + scale·real``; each field records its box,
origin and scale as XDATA on its heading so that a test (or a CAD user) can read them back from
the file. Every line drawn goes into an index (:class:`~.layout.Obstacles`) and labels are placed
last, clear of lines and of each other (:mod:`.layout`).

Facts used (``/work/shared/DRAWING.md``): A1 841 × 594 (ГОСТ 2.301), frame 20/5/5/5 mm; title
block form 1 185 × 55 (ГОСТ 2.104); lines 0.7 / 0.25 mm, dash-dot axes, dashed hidden lines
(ГОСТ 2.303); text heights 2.5 … 10 mm (ГОСТ 2.304); scales of ГОСТ 2.302.

Text: one style, ``OpenGostTypeB-Regular`` (LibreCAD shows its own GOST type B stroke font for
that name; other CAD programs use the style's TrueType file ``osifont.ttf``, which tmm ships and
the PDF is drawn with). A text with an index is one MTEXT whose index is stacked (``\\S^ 0;``,
the AutoCAD/LibreCAD way of writing a subscript), so every program lays the index out with its
own font and it never collides with its base.

ezdxf is imported inside :class:`Sheet` only (``tmm --help`` stays fast).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .layout import (CLEAR, DESCENT, GOST_SCALES, SUB_DESCENT, Label, Obstacles, inside, readable, ring_positions,
                     text_corners)

SHEET_W, SHEET_H = 841.0, 594.0  # A1 landscape [mm]
FRAME = (20.0, 5.0, SHEET_W - 5.0, SHEET_H - 5.0)  # x0, y0, x1, y1 of the frame
TB_W, TB_H = 185.0, 55.0  # title block form 1
TB_ORIGIN = (FRAME[2] - TB_W, FRAME[1])  # its lower-left corner
TB_BOX = (TB_ORIGIN[0], TB_ORIGIN[1], TB_ORIGIN[0] + TB_W, TB_ORIGIN[1] + TB_H)
TEXT_HEIGHTS = (2.5, 3.5, 5.0, 7.0, 10.0, 14.0, 20.0)  # ГОСТ 2.304
MIN_WIDTH_FACTOR = 0.6  # narrower text is hard to read; wrap first
# A CAD program without osifont draws the sheet's text in its own font: LibreCAD 2.2's stroke font is
# about 30 % wider. Every text with a width to keep (a cell, a field, the frame) is laid out as if it
# were ROOM times as wide as osifont sets it, and aligned by the DXF itself (centre, right), so the
# wider font stays inside its cell too; our PDF keeps osifont (with that much room to spare).
ROOM = 1.3
MIN_HEIGHT = 2.5  # ГОСТ 2.304: never smaller (only the title block's cells use it)
H_LABEL = 5.0  # labels and dimensions on A1
H_MIN_LABEL = 3.5  # the smallest label (dense constructions)
H_TITLE = 7.0  # view titles

GOST_SCALE_LABELS = tuple(lab for lab, _ in GOST_SCALES)

# layer: (ACI colour, lineweight [1/100 mm], linetype)
LAYERS = {
    "Основные": (7, 70, "Continuous"),
    "Рабочие": (7, 100, "Continuous"),  # the working (active) part of the tooth profiles: one heavy line
    "Тонкие": (7, 25, "Continuous"),
    "Осевые": (1, 25, "CENTER"),
    "Штриховые": (7, 25, "DASHED"),
    "Размеры": (3, 25, "Continuous"),
    "Текст": (7, 25, "Continuous"),
    "Рамка": (7, 70, "Continuous"),
}
LTSCALE = 12.0  # CENTER: 15 mm dashes, 3 mm gaps; DASHED: 6 mm dashes, 1.2 mm gaps (ГОСТ 2.303)
XDATA_APP = "TMM_FIELD"
STYLE = "OpenGostTypeB-Regular"  # LibreCAD maps this name to its GOST type B font; others use FONT
FONT = "osifont.ttf"  # ships in tmm_cli/render/sheets/fonts (GPL with the font exception)
FONT_DIR = Path(__file__).with_name("fonts")
# characters osifont lacks, written with ones it has
# osifont has no U+2212 (minus): a minus is set as the en dash it has (a hyphen is too short beside
# the digits, ГОСТ 2.304 draws the minus as long as the plus's bar)
GLYPHS = str.maketrans({"′": "'", "−": "–", "→": "–", "…": "...", "\u2009": " ", "\u202f": " ", "\xa0": " "})
_MINUS = re.compile(r"(?<![\w.,)\]])-(?=\d)")  # a hyphen-minus before a number (not in a word or range)


def glyphs(text: str) -> str:
    """`text` in the glyphs of the sheet's font: the translations above, a number's minus as «–».

    >>> glyphs("e = -20,65 мм; (-0,29 %); радиус-вектор; 1-68; М 1:2")
    'e = –20,65 мм; (–0,29 %); радиус-вектор; 1-68; М 1:2'
    """
    return _MINUS.sub("–", text.translate(GLYPHS))


def gost_scale(label: str) -> float:
    """Paper mm per real mm of a ГОСТ 2.302 scale label ("1:2", "2,5:1"; a dot is accepted).

    >>> gost_scale("1:2"), gost_scale("2.5:1")
    (0.5, 2.5)
    """
    lab = label.replace(".", ",")
    for name, f in GOST_SCALES:
        if name == lab:
            return f
    raise ValueError(f"{label} is not a scale of ГОСТ 2.302")


def gost_label(factor: float) -> str:
    """The ГОСТ 2.302 label of a factor (paper/real), e.g. 0.5 -> '1:2'."""
    for name, f in GOST_SCALES:
        if abs(f / factor - 1.0) < 1e-9:
            return name
    raise ValueError(f"{factor} is not a scale of ГОСТ 2.302")


def fit_scale(extent_real: tuple[float, float], room: tuple[float, float], choices=None) -> tuple[str, float]:
    """The largest ГОСТ 2.302 scale at which a drawing of `extent_real` (w, h) [mm] fits `room`.

    >>> fit_scale((300.0, 100.0), (250.0, 250.0))
    ('1:2', 0.5)
    """
    best = None
    for name, f in GOST_SCALES if choices is None else choices:
        if extent_real[0] * f <= room[0] and extent_real[1] * f <= room[1]:
            if best is None or f > best[1]:
                best = (name, f)
    return best or GOST_SCALES[0]


# ----------------------------------------------------------------------------------------------
# geometry helpers (pure; sheet millimetres)


def clip_polyline(pts: np.ndarray, box: tuple[float, float, float, float]) -> list[np.ndarray]:
    """Pieces of a polyline inside `box` (x0, y0, x1, y1); crossings interpolated."""
    pts = np.asarray(pts, dtype=float)
    x0, y0, x1, y1 = box
    inside = (pts[:, 0] >= x0) & (pts[:, 0] <= x1) & (pts[:, 1] >= y0) & (pts[:, 1] <= y1)
    pieces, cur = [], []

    def cross(a, b):
        # parameter where segment a→b leaves/enters the box (Liang–Barsky on one segment)
        t0, t1 = 0.0, 1.0
        d = b - a
        for p, q in ((-d[0], a[0] - x0), (d[0], x1 - a[0]), (-d[1], a[1] - y0), (d[1], y1 - a[1])):
            if p == 0:
                if q < 0:
                    return None
                continue
            r = q / p
            if p < 0:
                t0 = max(t0, r)
            else:
                t1 = min(t1, r)
        return None if t0 > t1 else (a + t0 * d, a + t1 * d)

    for i in range(len(pts)):
        if inside[i]:
            if not cur and i > 0:
                c = cross(pts[i - 1], pts[i])
                if c is not None:
                    cur.append(c[0])
            cur.append(pts[i])
        else:
            if cur:
                c = cross(pts[i - 1], pts[i])
                if c is not None:
                    cur.append(c[1])
                pieces.append(np.array(cur))
                cur = []
            elif i > 0:
                c = cross(pts[i - 1], pts[i])
                if c is not None and np.hypot(*(c[1] - c[0])) > 1e-9:
                    pieces.append(np.array([c[0], c[1]]))
    if cur:
        pieces.append(np.array(cur))
    return [p for p in pieces if len(p) >= 2]


def circle_arcs_in_box(c, r: float, box) -> list[tuple[float, float]] | None:
    """Angle intervals [deg, counter-clockwise] of a circle inside `box`; None = whole circle."""
    x0, y0, x1, y1 = box
    if c[0] - r >= x0 and c[0] + r <= x1 and c[1] - r >= y0 and c[1] + r <= y1:
        return None
    t = np.linspace(0.0, 360.0, 1441)
    x = c[0] + r * np.cos(np.radians(t))
    y = c[1] + r * np.sin(np.radians(t))
    ins = (x >= x0) & (x <= x1) & (y >= y0) & (y <= y1)
    if not ins.any():
        return []
    out = []
    start = None
    for i, flag in enumerate(ins):
        if flag and start is None:
            start = t[i]
        if not flag and start is not None:
            out.append((start, t[i - 1]))
            start = None
    if start is not None:
        out.append((start, 360.0))
    if len(out) > 1 and out[0][0] == 0.0 and out[-1][1] == 360.0:  # join across 0°
        out = [(out[-1][0], out[0][1] + 360.0)] + out[1:-1]
    return [(a, b) for a, b in out if b - a > 0.3]


def thin_out(pts: np.ndarray, step: float) -> np.ndarray:
    """Every point at least `step` (along the path) from the last kept one, ends kept: a drawing
    needs no more vertices than it can show (the tooth flanks come at 400 points each)."""
    pts = np.asarray(pts, dtype=float)
    if len(pts) < 3:
        return pts
    seg = np.hypot(*np.diff(pts, axis=0).T)
    s = np.concatenate([[0.0], np.cumsum(seg)])
    keep = [0]
    last = 0.0
    for i in range(1, len(pts) - 1):
        if s[i] - last >= step:
            keep.append(i)
            last = s[i]
    keep.append(len(pts) - 1)
    return pts[keep]


# ----------------------------------------------------------------------------------------------
# rich text: "ψ_{у}", "r_0", "S^{2}"

_RICH = re.compile(r"_\{([^}]*)\}|\^\{([^}]*)\}|_(\w)")


def rich_parts(text: str) -> list[tuple[str, int]]:
    """Split markup into (text, level): 0 normal, -1 subscript, +1 superscript.

    >>> rich_parts("ψ_{у} = 10°")
    [('ψ', 0), ('у', -1), (' = 10°', 0)]
    >>> rich_parts("r_0")
    [('r', 0), ('0', -1)]
    """
    parts, pos = [], 0
    for m in _RICH.finditer(text):
        if m.start() > pos:
            parts.append((text[pos:m.start()], 0))
        if m.group(1) is not None:
            parts.append((m.group(1), -1))
        elif m.group(2) is not None:
            parts.append((m.group(2), 1))
        else:
            parts.append((m.group(3), -1))
        pos = m.end()
    if pos < len(text):
        parts.append((text[pos:], 0))
    return [(t, lv) for t, lv in parts if t]


def plain(text: str) -> str:
    """The markup without its marks (for searching the DXF)."""
    return "".join(t for t, _ in rich_parts(text))


SUB_RATIO = 0.7
SUPERSCRIPTS = str.maketrans({"2": "²", "3": "³"})  # a power written inline (osifont has these two)


SUB_DROP = 0.25  # a subscript's baseline below the text's, in heights


def dxf_literal(text: str) -> str:
    """A person's text as a TEXT entity's string that every reader shows as the characters given.

    >>> dxf_literal("%%uIvanov G^{2}")
    '%%%%%%uIvanov G^ {2}'
    """
    return text.replace("%", "%%%").replace("^", "^ ")


def mtext_content(text: str) -> str:
    """The MTEXT string of a marked-up text: an index stacked under nothing (``\\S^ 0;``) is the
    subscript of AutoCAD and LibreCAD, one over nothing (``\\S2^ ;``) the superscript.

    >>> mtext_content("ψ_{у} = 10°")
    'ψ\\\\S^ у; = 10°'
    >>> mtext_content("S^{2}")
    'S\\\\S2^ ;'
    """
    out = []
    for part, lv in rich_parts(text):
        part = part.replace("\\", "\\\\").replace("{", "\\{").replace("}", "\\}")
        if lv < 0:
            out.append(f"\\S^ {part};")
        elif lv > 0:
            out.append(f"\\S{part}^ ;")
        else:
            out.append(part)
    return "".join(out)


_MTEXT_RUN = re.compile(r"\\S\^ ([^;]*);|\\S([^;^]*)\^ ;")


def mtext_runs(content: str) -> list[tuple[str, int]]:
    """The runs (text, level) of an MTEXT string written by :func:`mtext_content`.

    >>> mtext_runs('ψ\\\\S^ у; = 10°')
    [('ψ', 0), ('у', -1), (' = 10°', 0)]
    """
    parts, pos = [], 0
    for m in _MTEXT_RUN.finditer(content):
        if m.start() > pos:
            parts.append((content[pos:m.start()], 0))
        parts.append((m.group(1), -1) if m.group(1) is not None else (m.group(2), 1))
        pos = m.end()
    if pos < len(content):
        parts.append((content[pos:], 0))
    return [(t.replace("\\{", "{").replace("\\}", "}").replace("\\\\", "\\"), lv) for t, lv in parts if t]


def run_offsets(runs, h: float, width) -> list[tuple[str, float, float, float]]:
    """(text, dx, dy, height) of each run of a one-line text of cap height `h` whose base is at
    (0, 0): an index at 0.7·h, SUB_DROP·h below (or 0.55·h above) the baseline; `width(text, hh)`
    measures a run."""
    out, x = [], 0.0
    for t, lv in runs:
        hh = h if lv == 0 else h * SUB_RATIO
        dy = 0.0 if lv == 0 else (-SUB_DROP * h if lv < 0 else 0.55 * h)
        out.append((t, x, dy, hh))
        x += width(t, hh)
    return out


def register_font() -> None:
    """Make ezdxf find the bundled osifont (the PDF is drawn with it); no silent fallback: a tmm
    installed without its font is broken and says so."""
    from ezdxf.fonts import fonts

    global _FONT_READY
    if _FONT_READY:
        return
    if not (FONT_DIR / FONT).is_file():  # pragma: no cover - a broken installation
        from ...errors import TmmError

        raise TmmError(f"the sheet font {FONT_DIR / FONT} is missing; reinstall tmm")
    fonts.font_manager.scan_folder(FONT_DIR)  # tmm's copy wins over an osifont.ttf of the system
    _FONT_READY = True


_FONT_READY = False


@dataclass
class Field:
    """A drawing field on the sheet: its box, heading and (for true-to-scale fields) transform."""

    sheet: "Sheet"
    name: str
    box: tuple[float, float, float, float]
    origin: tuple[float, float] = (0.0, 0.0)
    scale: float = 1.0  # paper mm per drawing unit
    scale_label: str = ""
    inner: tuple[float, float, float, float] = field(default=(0, 0, 0, 0))
    clip: tuple[float, float, float, float] | None = None  # drawing is cut to this box (default inner)

    def to_sheet(self, pts) -> np.ndarray:
        a = np.asarray(pts, dtype=float)
        return np.asarray(self.origin) + self.scale * a

    def p(self, x: float, y: float) -> tuple[float, float]:
        return (self.origin[0] + self.scale * x, self.origin[1] + self.scale * y)

    @property
    def cut(self):
        return self.clip or self.inner

    # drawing in the field's own units, clipped to the field
    def poly(self, pts, layer="Основные", linetype=None, closed=False, clip=True):
        q = self.to_sheet(pts)
        if closed:
            q = np.vstack([q, q[:1]])
        if not clip:
            return [self.sheet.poly(q, layer, linetype)]
        return [self.sheet.poly(piece, layer, linetype) for piece in clip_polyline(q, self.cut)]

    def circle(self, c, r, layer="Основные", linetype=None):
        cc = self.p(*c)
        return self.sheet.circle_in(cc, r * self.scale, self.cut, layer, linetype)

    def line(self, a, b, layer="Тонкие", linetype=None):
        return self.poly([a, b], layer, linetype)

    def label(self, text, at, h=H_LABEL, **kw):
        """A label near the point `at` (field units), placed inside the field."""
        kw.setdefault("within", self.inner)
        return self.sheet.label(text, self.p(*at), h, **kw)


class Sheet:
    """One A1 drawing: ezdxf document, layers, text style, frame, title block, fields, labels."""

    def __init__(self, lang: str = "ru"):
        import ezdxf

        self.lang = lang
        doc = ezdxf.new("R2010", setup=["linetypes"])
        doc.units = 4  # millimetres
        doc.header["$INSUNITS"] = 4
        doc.header["$MEASUREMENT"] = 1
        doc.header["$LUNITS"] = 2  # decimal
        doc.header["$LTSCALE"] = LTSCALE
        doc.header["$PSLTSCALE"] = 1
        doc.header["$CELTSCALE"] = 1.0
        doc.header["$LWDISPLAY"] = 1
        doc.header["$EXTMIN"] = (0, 0, 0)
        doc.header["$EXTMAX"] = (SHEET_W, SHEET_H, 0)
        doc.header["$LIMMIN"] = (0, 0)
        doc.header["$LIMMAX"] = (SHEET_W, SHEET_H)
        doc.header["$LIMCHECK"] = 0
        for name, (color, lw, lt) in LAYERS.items():
            doc.layers.add(name, color=color, lineweight=lw, linetype=lt)
        register_font()
        self.font_file = FONT
        st = doc.styles.add(STYLE, font=FONT)
        st.set_extended_font_data(family="osifont", italic=False, bold=False)
        doc.styles.get("Standard").dxf.font = FONT
        doc.appids.add(XDATA_APP)
        self.doc = doc
        self.msp = doc.modelspace()
        self._fonts: dict = {}
        self._widths: dict = {}
        self.fields: list[Field] = []
        self.obstacles = Obstacles()
        self.labels: list[Label] = []
        self.unplaced: list[str] = []  # labels no free place was found for (tests fail on them)
        self.leaders: list[tuple] = []  # the labels' leaders (start, end) [sheet mm]
        self.omitted: list[str] = []  # optional labels left out for want of a free place (the caller says so)
        self.finished = False

    # ------------------------------------------------------------------ primitives (sheet mm)
    def _attr(self, layer, linetype=None, **kw):
        a = {"layer": layer}
        if linetype:
            a["linetype"] = linetype
        a.update(kw)
        return a

    def line(self, a, b, layer="Тонкие", linetype=None):
        a = (float(a[0]), float(a[1]))
        b = (float(b[0]), float(b[1]))
        self.obstacles.add_polyline(np.array([a, b]))
        return self.msp.add_line(a, b, dxfattribs=self._attr(layer, linetype))

    def poly(self, pts, layer="Основные", linetype=None, closed=False, lineweight=None):
        arr = np.asarray(pts, dtype=float)
        self.obstacles.add_polyline(np.vstack([arr, arr[:1]]) if closed else arr)
        pts = [(float(x), float(y)) for x, y in arr]
        a = self._attr(layer, linetype)
        if lineweight is not None:
            a["lineweight"] = lineweight
        e = self.msp.add_lwpolyline(pts, format="xy", close=closed, dxfattribs=a)
        if (linetype or LAYERS.get(layer, (0, 0, "Continuous"))[2]) != "Continuous":
            e.dxf.flags |= 128  # linetype generation: the pattern runs on across the vertices
        return e

    def rect(self, x0, y0, x1, y1, layer="Тонкие"):
        return self.poly([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], layer, closed=True)

    def circle(self, c, r, layer="Основные", linetype=None):
        self.obstacles.add_circle(c, float(r))
        return self.msp.add_circle((float(c[0]), float(c[1])), float(r), dxfattribs=self._attr(layer, linetype))

    def arc(self, c, r, a0, a1, layer="Тонкие", linetype=None):
        self.obstacles.add_circle(c, float(r), float(a0), float(a1))
        return self.msp.add_arc((float(c[0]), float(c[1])), float(r), float(a0), float(a1), dxfattribs=self._attr(layer, linetype))

    def circle_in(self, c, r, box, layer="Основные", linetype=None):
        """A circle, or its arcs inside `box` when it does not fit."""
        spans = circle_arcs_in_box(c, r, box)
        if spans is None:
            return [self.circle(c, r, layer, linetype)]
        return [self.arc(c, r, a % 360.0, b % 360.0 if b % 360.0 else 360.0, layer, linetype) for a, b in spans]

    def solid(self, pts, layer="Размеры"):
        p = [(float(x), float(y)) for x, y in pts]
        self.obstacles.add_polyline(np.array(p + p[:1]))
        if len(p) == 3:
            p.append(p[2])
        return self.msp.add_solid(p, dxfattribs={"layer": layer})

    def dot(self, c, r=0.7, layer="Основные"):
        """A filled point (a small solid disc as a thick donut polyline)."""
        x, y = float(c[0]), float(c[1])
        self.obstacles.add_circle((x, y), r)
        return self.msp.add_lwpolyline([(x - r / 2, y, r, r, 1.0), (x + r / 2, y, r, r, 1.0)], format="xyseb", close=True,
                                       dxfattribs={"layer": layer})

    def arrow(self, tip, direction, layer="Размеры", length=3.5, width=1.0):
        d = np.asarray(direction, dtype=float)
        d = d / (np.hypot(*d) or 1.0)
        n = np.array([-d[1], d[0]])
        t = np.asarray(tip, dtype=float)
        base = t - length * d
        return self.solid([t, base + n * width / 2, base - n * width / 2], layer)

    def wavy(self, a, b, amp=1.6, wave=9.0, layer="Тонкие"):
        """A thin wavy break line from a to b (ГОСТ 2.303)."""
        a, b = np.asarray(a, float), np.asarray(b, float)
        L = float(np.hypot(*(b - a)))
        if L < 1e-6:
            return None
        u = (b - a) / L
        n = np.array([-u[1], u[0]])
        t = np.linspace(0.0, L, max(8, int(L / 1.0)))
        w = amp * np.sin(2 * np.pi * t / wave) * np.minimum(1.0, np.minimum(t, L - t) / 2.0)
        return self.poly(a + np.outer(t, u) + np.outer(w, n), layer)

    # ------------------------------------------------------------------------ dimensions
    def dim_linear(self, a, b, offset, text: str, h: float = H_LABEL, ext: bool = True, within=None, priority=5):
        """A dimension between points a, b [sheet mm], its line shifted by the vector `offset`:
        extension lines, a thin line with two arrows, the text above the line (placed by the label
        placer along it, or beyond an end on a shelf), exploded into plain entities so that every
        CAD program shows it as drawn."""
        a, b, off = (np.asarray(v, dtype=float) for v in (a, b, offset))
        pa, pb = a + off, b + off
        d = pb - pa
        L = float(np.hypot(*d))
        if L < 1e-6:
            return
        u = d / L
        if ext and np.hypot(*off) > 0.5:
            n = off / np.hypot(*off)
            self.line(a + n * 1.0, pa + n * 2.0, "Размеры")
            self.line(b + n * 1.0, pb + n * 2.0, "Размеры")
        inside_ = L > 9.0
        if inside_:
            self.line(pa, pb, "Размеры")
            self.arrow(pa, -u, "Размеры", 3.0, 0.9)
            self.arrow(pb, u, "Размеры", 3.0, 0.9)
        else:  # arrows from outside
            self.line(pa - 7 * u, pb + 7 * u, "Размеры")
            self.arrow(pa, u, "Размеры", 3.0, 0.9)
            self.arrow(pb, -u, "Размеры", 3.0, 0.9)
        rot = readable(math.degrees(math.atan2(u[1], u[0])))
        ur = np.array([math.cos(math.radians(rot)), math.sin(math.radians(rot))])
        nr = np.array([-ur[1], ur[0]])
        w = self.text_width(text, h)
        sub = any(lv for _, lv in rich_parts(text))
        d_lo = (SUB_DESCENTS if sub else DESCENTS) * h
        pos = []
        for lift in (1.0, 2.5):
            for t in ((0.5, 0.3, 0.7, 0.15, 0.85) if inside_ else (0.5,)):
                m = pa + d * t
                for side in (1.0, -1.0):
                    # above the line: the box's bottom `lift` over it; below: its top `lift` under it
                    off = (lift + d_lo + CLEAR) if side > 0 else -(lift + h + CLEAR)
                    base = m - ur * w / 2 + nr * off
                    pos.append((float(base[0]), float(base[1]), rot))
        self.label(text, tuple((pa + pb) / 2), h, within=within, positions=tuple(pos), dirs=(), dists=(),
                   leader=True, priority=priority, rot=rot,
                   anchors=[tuple(pa + d * t) for t in (0.3, 0.7, 0.15, 0.85)] if inside_ else ())

    def dim_arc(self, c, r, a0, a1, text: str, h: float = H_LABEL, ext_from: float | None = None, within=None,
                priority=5):
        """An angular/arc dimension: an arc of radius r [sheet mm] from a0 to a1 [deg, ccw] with
        arrows at both ends; extension lines from radius `ext_from`; the text upright beside the
        arc's middle (placed by the label placer)."""
        c = np.asarray(c, dtype=float)
        self.arc(c, r, a0, a1, "Размеры")
        for ang, sgn in ((a0, 1.0), (a1, -1.0)):
            e = math.radians(ang)
            tip = c + r * np.array([math.cos(e), math.sin(e)])
            tang = np.array([-math.sin(e), math.cos(e)]) * -sgn
            self.arrow(tip, tang, "Размеры", 3.0, 0.9)
            if ext_from is not None:
                q0 = c + ext_from * np.array([math.cos(e), math.sin(e)])
                q1 = c + (r + 2.0) * np.array([math.cos(e), math.sin(e)])
                self.line(q0, q1, "Размеры")
        if text:
            am = math.radians((a0 + a1) / 2)
            q = c + r * np.array([math.cos(am), math.sin(am)])
            out = np.array([math.cos(am), math.sin(am)])
            dirs = _dirs_towards(out)
            self.label(text, tuple(q), h, within=within, dirs=dirs, dists=(1.0, 2.5, 5.0), priority=priority)

    # ------------------------------------------------------------------------------ text
    def font(self, h: float, wf: float = 1.0):
        from ezdxf.fonts import fonts

        key = (round(h, 4), round(wf, 4))
        if key not in self._fonts:
            self._fonts[key] = fonts.make_font(self.font_file, h, wf)
        return self._fonts[key]

    def _w(self, part: str, h: float, wf: float = 1.0) -> float:
        key = (part, round(h, 4), round(wf, 4))
        w = self._widths.get(key)
        if w is None:
            w = self._widths[key] = self.font(h, wf).text_width(part)
        return w

    def text_width(self, text: str, h: float, wf: float = 1.0, literal: bool = False) -> float:
        w = 0.0
        for part, lv in ([(text, 0)] if literal else rich_parts(glyphs(text))):
            w += self._w(part, h if lv == 0 else h * SUB_RATIO, wf)
        return w

    def caption(self, x0: float, x1: float, y_bottom: float, lines: list[str], h: float, step: float) -> float:
        """`lines` of height `h` stacked `step` mm apart upwards from `y_bottom`, the last one lowest,
        each kept within x0 … x1 (2 mm in from either side); returns the top of the block."""
        y = y_bottom + step * (len(lines) - 1)
        top = y + h
        for t in lines:
            self.text(x0 + 2.0, y, t, h, width=x1 - x0 - 4.0)
            y -= step
        return top

    def _put(self, x, y, text: str, h: float, wf: float, rot: float, layer: str, register: bool = True,
             align: str = "left", room: float = ROOM, literal: bool = False):
        """One line of text, (x, y) the left end, the centre or the right end of its baseline
        (`align`), aligned so in the DXF (a CAD program with a wider font keeps it centred or
        right-aligned in its cell); TEXT when plain (its width factor `wf`), MTEXT when it carries an
        index — MTEXT has no width factor every program reads (LibreCAD prints ``\\W0.8;`` as text),
        so a narrowed text with an index is a TEXT with its indices written inline (``μv``, ``м²``).
        A `literal` text (a person's: a name, a group) is one TEXT of the characters given: no index,
        no glyph swapped, its "%%" codes written as "%%%" (AutoCAD's percent sign), so «%%u» is not
        an underline, and a caret as "^ " (not a control character)."""
        from ezdxf.enums import TextEntityAlignment

        if literal:
            parts = [(dxf_literal(text), 0)]
        else:
            text = glyphs(text)
            parts = rich_parts(text)
        sub = any(lv for _, lv in parts)
        if sub and wf < 1.0 - 1e-6:  # narrowed: one TEXT with its width factor, its indices inline
            target = self.text_width(text, h, wf)  # as wide as the fitted text with its indices
            parts = [(t.translate(SUPERSCRIPTS) if lv > 0 else t, 0) for t, lv in parts]
            text, sub = "".join(t for t, _ in parts), False
            wf = wf * target / max(self.text_width(text, h, wf), 1e-9)
        if not sub:
            e = self.msp.add_text("".join(t for t, _ in parts), height=h, rotation=rot,
                                  dxfattribs={"layer": layer, "style": STYLE, "width": wf})
            e.set_placement((float(x), float(y)), align={"left": TextEntityAlignment.LEFT,
                                                         "center": TextEntityAlignment.CENTER,
                                                         "right": TextEntityAlignment.RIGHT}[align])
        else:
            e = self.msp.add_mtext(mtext_content(text), dxfattribs={
                "layer": layer, "style": STYLE, "char_height": h, "insert": (float(x), float(y)),
                "attachment_point": {"left": 7, "center": 8, "right": 9}[align], "rotation": rot})
        if register:  # the room a wider font takes, about the alignment point
            w = self.text_width(text, h, wf, literal) * room
            c, s_ = math.cos(math.radians(rot)), math.sin(math.radians(rot))
            dx = {"left": 0.0, "center": -w / 2, "right": -w}[align]
            self.obstacles.add_box(text_corners(x + c * dx, y + s_ * dx, w, h, rot, sub=sub))
        return e

    def text(self, x, y, text: str, h: float = 3.5, *, align: str = "left", valign: str = "base",
             width: float | None = None, rot: float = 0.0, layer: str = "Текст", max_lines: int = 1,
             line_gap: float = 0.5, height_max: float | None = None, min_h: float = MIN_HEIGHT,
             min_wf: float = MIN_WIDTH_FACTOR, literal: bool = False) -> list:
        """Text at (x, y) [sheet mm] with ГОСТ height `h`; markup _{sub}, ^{sup} (none in a
        `literal` text: a person's, set as the characters given).

        A text wider than `width` is first narrowed (width factor down to `min_wf`), then wrapped
        into at most `max_lines` lines, then set a size smaller (never below `min_h`), and at the
        smallest size narrowed as far as needed — never spilled over a line.
        `height_max` limits the height of the whole block (valign 'top'/'middle' blocks).
        Returns the entities.
        """
        if not text:
            return []
        h, wf, lines = self._fit(text, h, width, max_lines, height_max, line_gap, min_h, min_wf, literal)
        n = len(lines)
        step = h * (1.0 + line_gap + 0.15)
        if valign == "top":
            y0 = -h
        elif valign == "middle":
            y0 = -h / 2 + (n - 1) * step / 2
        elif valign == "bottom":
            y0 = (n - 1) * step + 0.0
        else:
            y0 = 0.0
        out = []
        c, s = math.cos(math.radians(rot)), math.sin(math.radians(rot))
        for k, line in enumerate(lines):
            dy = y0 - k * step
            X, Y = x - s * dy, y + c * dy
            out.append(self._put(X, Y, line, h, wf, rot, layer, align=align, literal=literal))
        return out

    def _fit(self, text, h, width, max_lines, height_max, gap, min_h=MIN_HEIGHT, min_wf=MIN_WIDTH_FACTOR, literal=False):
        def block_h(hh, n):
            return hh * n + (n - 1) * hh * (gap + 0.15)

        heights = [x for x in TEXT_HEIGHTS if min_h - 1e-9 <= x <= h + 1e-9][::-1] or [h]
        for hh in heights:
            if height_max is not None and block_h(hh, 1) > height_max + 1e-9 and hh != heights[-1]:
                continue
            for n in range(1, max_lines + 1):
                if height_max is not None and block_h(hh, n) > height_max + 1e-9:
                    break
                lines = _wrap(text, n) if n > 1 else [text]
                if lines is None:
                    continue
                if width is None:
                    return hh, 1.0, lines
                w = max(self.text_width(t, hh, 1.0, literal) for t in lines) * ROOM
                if w <= width:
                    return hh, 1.0, lines
                if w * min_wf <= width:
                    return hh, max(min_wf, width / w * 0.999), lines
        # last resort: the smallest height, as many lines as allowed, narrowed as far as needed
        hh = heights[-1]
        best = [text]
        for n in range(2, max_lines + 1):
            if height_max is not None and block_h(hh, n) > height_max + 1e-9:
                break
            best = _wrap(text, n) or best
        w = max(self.text_width(t, hh, 1.0, literal) for t in best) * (ROOM if width else 1.0)
        return hh, min(1.0, (width or w) / w * 0.999), best

    # ---------------------------------------------------------------------------- labels
    def label(self, text: str, anchor, h: float = H_LABEL, *, within=None, rot: float = 0.0, dirs=None,
              dists=None, leader: bool = True, priority: int = 0, positions=(), dot: bool = False,
              anchors=(), optional: bool = False, wide: bool = False) -> Label:
        """Queue a label near `anchor` [sheet mm]; :meth:`place_labels` puts it where it touches no
        line and no text (candidates: `positions` first — (x, y, rot) insertion points —, then
        the directions `dirs` at the distances `dists`, then rings farther out with a leader).
        `wide`: every place with room for a CAD program's wider font, a leader's too, before any
        without it (a crowded drawing, where a wider font would otherwise run into a neighbour)."""
        lab = Label(text=text, anchor=(float(anchor[0]), float(anchor[1])), h=h, within=within or FRAME_INNER,
                    rot=readable(rot), leader=leader, priority=priority, positions=tuple(positions), dot=dot,
                    order=len(self.labels), anchors=tuple(tuple(map(float, a)) for a in anchors),
                    optional=optional, wide=wide)
        if dirs is not None:
            lab.dirs = tuple(dirs)
        if dists is not None:
            lab.dists = tuple(dists)
        self.labels.append(lab)
        return lab

    def place_labels(self) -> None:
        """Place every queued label (higher priority first, then in the order asked)."""
        todo = sorted(self.labels, key=lambda lb: (-lb.priority, lb.order))
        self.labels = []
        for lab in todo:
            self._place(lab)

    def _free(self, corners, within) -> bool:
        return inside(corners, within) and self.obstacles.free(corners)

    def _free_text(self, x, y, w, h, rot, sub, within) -> bool:
        """:meth:`_free` of the box :func:`text_corners` gives (pad CLEAR); an upright one from its
        sides, with the same arithmetic (the same cells), without building its corners."""
        if rot != 0.0:
            return self._free(text_corners(x, y, w, h, rot, sub=sub, pad=CLEAR), within)
        d = (SUB_DESCENT if sub else DESCENT) * h
        x0, y0, x1, y1 = x + -CLEAR, y + (-d - CLEAR), x + (w + CLEAR), y + (h + CLEAR)
        return within[0] <= x0 and within[1] <= y0 and x1 <= within[2] and y1 <= within[3] \
            and self.obstacles.free_rect(x0, y0, x1, y1)

    def _place(self, lab: Label) -> None:
        """The label at the first free candidate: the caller's positions (left ends of the baseline,
        as measured in osifont), then around the anchor with ROOM for a wider font — the text aligned
        towards the anchor (right-aligned on its left, centred above and below it), so that a
        wider font grows away from the anchor, into the room kept for it."""
        text = glyphs(lab.text)
        h = lab.h
        w = self.text_width(text, h)
        wr = w * ROOM
        sub = any(lv for _, lv in rich_parts(text))
        cands = [(x, y, r, w, "left") for x, y, r in lab.positions]
        rings = []
        for ww in (wr, w):  # each place with room for a wider font, else as osifont sets it
            ring = []
            if lab.rot == 0.0:
                for x, y in ring_positions(lab.anchor, ww, h, lab.dirs, lab.dists, sub):
                    mid = x + ww / 2 - lab.anchor[0]
                    align = "center" if abs(mid) < ww / 4 else ("left" if mid > 0 else "right")
                    ring.append((x, y, 0.0, ww, align))
            else:  # a turned label: along its direction, centred on the anchor's normal
                c, s = math.cos(math.radians(lab.rot)), math.sin(math.radians(lab.rot))
                for dist in lab.dists:
                    for side in (1.0, -1.0):
                        off = dist + (0 if side > 0 else h + DESCENTS * h)
                        x = lab.anchor[0] - c * ww / 2 - s * off * side
                        y = lab.anchor[1] - s * ww / 2 + c * off * side
                        ring.append((x, y, lab.rot, ww, "center"))
            rings.append(ring)
        if lab.wide and lab.leader:  # room for a wider font first, near (the ring) or farther (a leader)
            for x, y, r, ww, align in cands + rings[0]:
                if self._free_text(x, y, ww, h, r, sub, lab.within):
                    self._put_in(x, y, ww, text, h, r, align, ROOM if lab.wide else 1.0)
                    return
            if self._leader_spot(lab, text, w, h, sub, ROOM) is not None:
                return
        cands += [c for pair in zip(*rings) for c in pair]
        for x, y, r, ww, align in cands:
            if self._free_text(x, y, ww, h, r, sub, lab.within):
                self._put_in(x, y, ww, text, h, r, align, ROOM if lab.wide else 1.0)
                return
        if lab.leader:
            for room in (ROOM, 1.0):
                if self._leader_spot(lab, text, w, h, sub, room) is not None:
                    return
        if lab.optional:  # a label that may be left out rather than crowd another (the caller says so)
            self.omitted.append(lab.text)
            return
        # nowhere free: the least crowded candidate, and the sheet remembers it (tests fail on it)
        x, y, r, ww, align = min(cands, key=lambda c: self._cost(text_corners(c[0], c[1], c[3], h, c[2], sub=sub,
                                                                               pad=CLEAR), lab))
        self._put_in(x, y, ww, text, h, r, align, ROOM if lab.wide else 1.0)
        self.unplaced.append(text)

    def _put_in(self, x, y, w, text, h, rot, align, room: float = 1.0):
        """A label in the box of length `w` whose baseline starts at (x, y), aligned in it."""
        k = {"left": 0.0, "center": 0.5, "right": 1.0}[align]
        c, s = math.cos(math.radians(rot)), math.sin(math.radians(rot))
        # indexed as osifont sets it (the room kept is the label's own: labels keep their old density),
        # a `wide` label's with the room of a wider font (no later label takes it)
        self._put(x + c * k * w, y + s * k * w, text, h, 1.0, rot, "Текст", align=align, room=room)

    def _cost(self, box, lab) -> float:
        return (0.0 if inside(box, lab.within) else 100.0) + 3.0 * self.obstacles.text_hits(box) \
            + self.obstacles.line_hits(box)

    def _leader_spot(self, lab: Label, text, w, h, sub, room: float = ROOM):
        """A place farther out with a leader: the text on a shelf, a thin line from the anchor to
        the shelf's near end; neither the text nor the leader touches text (the leader may cross
        lines, as on any drawing)."""
        d_lo = (SUB_DESCENTS if sub else DESCENTS) * h
        w = w * room  # room for a wider font, the text aligned at the shelf's near end
        anchors = [lab.anchor] + list(lab.anchors)
        for dist in (7.0, 10.0, 14.0, 19.0, 25.0, 32.0, 40.0, 50.0, 62.0, 76.0, 92.0):
            for k in range(24):
              for ax, ay in anchors:
                t = 2 * math.pi * k / 24 + math.pi / 4
                ex, ey = ax + dist * math.cos(t), ay + dist * math.sin(t)
                right = math.cos(t) >= -1e-9
                x = ex if right else ex - w
                y = ey + d_lo + 0.6
                if not self._free_text(x, y, w, h, 0.0, sub, lab.within):
                    continue
                shelf = ((x - 0.5, ey), (x + w + 0.5, ey))
                start = np.array([ax, ay]) + 0.4 * np.array([math.cos(t), math.sin(t)])
                if self.obstacles.segment_hits_text(start, (ex, ey)) or self.obstacles.segment_hits_text(*shelf):
                    continue
                if lab.optional and any(_segments_cross(start, (ex, ey), a, b) for a, b in self.leaders):
                    continue  # a leader that crosses another's is not read
                self.leaders.append((tuple(map(float, start)), (float(ex), float(ey))))
                self.line(start, (ex, ey), "Тонкие")
                self.line(*shelf, "Тонкие")
                if lab.dot:
                    self.dot((ax, ay), 0.5, "Тонкие")
                self._put_in(x, y, w, text, h, 0.0, "left" if right else "right", ROOM if lab.wide else 1.0)
                return True
        return None

    # ----------------------------------------------------------------------------- fields
    def add_field(self, name: str, box, heading: str, *, origin=(0.0, 0.0), scale: float = 1.0,
                  scale_label: str = "", heading_h: float = H_TITLE, scale_text: str | None = None,
                  heading_pad: float = 2.0) -> Field:
        """A field with its heading centred at the top (upper case, as on the book's sheets).

        The heading carries XDATA: name, box, origin, scale, scale label (read by the tests).
        `scale_text` is printed under the heading (e.g. "М 1:2"). The heading keeps `heading_pad`
        from either side of the box (it wraps, then shrinks to 5 mm, rather than come closer).
        """
        x0, y0, x1, y1 = box
        head = self.text((x0 + x1) / 2, y1 - 2.0, heading.upper(), heading_h, align="center", valign="top",
                         width=x1 - x0 - 2 * heading_pad, max_lines=2, min_h=5.0)
        low = min(e.dxf.insert[1] for e in head)
        top = low - DESCENTS * heading_h - 2.0
        if scale_text:  # on its own line under the heading (ГОСТ 2.316: «М 1:2»)
            self.text((x0 + x1) / 2, top - 0.5, scale_text, H_LABEL, align="center", valign="top", width=x1 - x0 - 4,
                      min_h=3.5)
            top -= 0.5 + H_LABEL * (1 + SUB_DESCENTS) + 1.5
        tags = [(1000, name)] + [(1040, float(v)) for v in (*box, *origin, scale)] + [(1000, scale_label or "")]
        head[0].set_xdata(XDATA_APP, tags)
        f = Field(self, name, tuple(box), tuple(origin), scale, scale_label, inner=(x0 + 1.0, y0 + 1.0, x1 - 1.0, top))
        self.fields.append(f)
        return f

    def heading_height(self, heading: str, width: float, heading_h: float = H_TITLE, heading_pad: float = 2.0) -> float:
        """How far below a field's top its inner box starts (the heading as :meth:`add_field` sets it)."""
        h, _, lines = self._fit(heading.upper(), heading_h, width - 2 * heading_pad, 2, None, 0.5, 5.0, MIN_WIDTH_FACTOR)
        return 2.0 + h + (len(lines) - 1) * h * (1.0 + 0.5 + 0.15) + DESCENTS * heading_h + 2.0

    def set_field_transform(self, f: Field, origin, scale: float, scale_label: str) -> None:
        """Fix a field's transform after its heading was written (the XDATA follows)."""
        f.origin, f.scale, f.scale_label = tuple(origin), scale, scale_label
        for e in self.msp:
            if e.has_xdata(XDATA_APP):
                tags = [t.value for t in e.get_xdata(XDATA_APP)]
                if tags[0] == f.name:
                    new = [(1000, f.name)] + [(1040, float(v)) for v in (*f.box, *f.origin, f.scale)] + [(1000, scale_label)]
                    e.set_xdata(XDATA_APP, new)

    # ------------------------------------------------------------------- frame, title block
    def frame(self):
        self.rect(0, 0, SHEET_W, SHEET_H, "Тонкие")
        self.rect(*FRAME, "Рамка")

    def title_block(self, title, *, name: str, designation: str, scale: str, org_extra: str = ""):
        """ГОСТ 2.104 form 1 at the lower-right corner of the frame, filled from `title`."""
        X, Y = TB_ORIGIN
        thick, thin = "Рамка", "Тонкие"

        def L(x0, y0, x1, y1, layer):
            self.line((X + x0, Y + y0), (X + x1, Y + y1), layer)

        self.rect(X, Y, X + TB_W, Y + TB_H, thick)
        # left part: columns 7, 10, 23, 15, 10 mm; rows of 5 mm
        for x in (17, 40, 55, 65):
            L(x, 0, x, 55, thick)
        L(7, 30, 7, 55, thick)
        for y in (5, 10, 15, 20, 25, 40, 45, 50):
            L(0, y, 65, y, thin)
        for y in (30, 35):
            L(0, y, 65, y, thick)
        # right part
        L(65, 40, 185, 40, thick)
        L(65, 15, 185, 15, thick)
        L(135, 0, 135, 40, thick)
        L(135, 35, 185, 35, thick)
        L(135, 20, 185, 20, thick)
        L(150, 20, 150, 40, thick)
        L(167, 20, 167, 40, thick)
        L(140, 20, 140, 35, thin)
        L(145, 20, 145, 35, thin)
        L(155, 15, 155, 20, thick)

        def T(x, y, s, h=2.5, w=None, align="left", **kw):
            kw.setdefault("min_wf", 0.3)
            return self.text(X + x, Y + y, s, h, width=w, align=align, **kw)

        for x, w, s in ((0, 7, "Изм."), (7, 10, "Лист"), (17, 23, "№ докум."), (40, 15, "Подп."), (55, 10, "Дата")):
            T(x + w / 2, 31.2, s, 2.5, w - (2 if w <= 10 else 3), "center")
        # lower rows, top down: Разраб. 25–30, Пров. 20–25, Т.контр. 15–20, (free), Н.контр., Утв.
        for k, s in enumerate(("Разраб.", "Пров.", "Т.контр.", "", "Н.контр.", "Утв.")):
            if s:
                T(0.8, 25 - k * 5 + 1.2, s, 2.5, 15.5)
        # a full name: one line of 3.5 or 2.5 mm, condensed as far as needed (never smaller)
        T(18.0, 26.2, title.student, 3.5, 21.0, height_max=3.6, min_wf=0.6, literal=True)  # a person's text, as typed; 1 mm clear of the cell's lines
        T(18.0, 21.2, title.teacher, 3.5, 21.0, height_max=3.6, min_wf=0.6, literal=True)
        for x, w, s in ((135, 15, "Лит."), (150, 17, "Масса"), (167, 18, "Масштаб")):
            T(x + w / 2, 36.2, s, 2.5, w - (2 if w <= 10 else 3), "center")
        T(176, 27.5, scale, 5.0, 16, "center", valign="middle")
        T(137.5, 27.5, "У", 3.5, 4, "center", valign="middle")  # литера: учебный документ
        T(136, 16.2, "Лист 1", 2.5, 18)
        T(156, 16.2, "Листов 1", 2.5, 28)
        T(125, 47.5, designation, 7.0, 114, "center", valign="middle", literal=True)
        # a long name goes onto two or three lines before it is narrowed far
        T(100, 27.5, name, 5.0, 66, "center", valign="middle", max_lines=3, height_max=23, min_wf=0.75)
        org = ", ".join(s for s in (title.org, ("гр. " + title.group) if title.group else "") if s)
        if org_extra:
            org = f"{org}, {org_extra}" if org else org_extra
        T(160, 7.5, org, 3.5, 48, "center", valign="middle", max_lines=3, height_max=13.5, literal=True)

    # ---------------------------------------------------------------------------- finish
    def finish(self) -> None:
        """Place the labels, then the paper space: one layout "A1" of 841 × 594 mm printing the
        model at 1:1 (plot settings, limits, units), and no text style nobody uses."""
        if self.finished:
            return
        self.finished = True
        self.place_labels()
        doc = self.doc
        names = [lay for lay in doc.layouts.names() if lay != "Model"]
        for n in names[1:]:
            doc.layouts.delete(n)
        if names and names[0] != "A1":
            doc.layouts.rename(names[0], "A1")
        ps = doc.layouts.get("A1")
        ps.page_setup(size=(SHEET_W, SHEET_H), margins=(0, 0, 0, 0), units="mm", offset=(0, 0), rotation=0,
                      scale=16, name="ISO_full_bp_A1_(841.00_x_594.00_MM)", device="DWG To PDF.pc3")
        ps.add_viewport(center=(SHEET_W / 2, SHEET_H / 2), size=(SHEET_W, SHEET_H),
                        view_center_point=(SHEET_W / 2, SHEET_H / 2), view_height=SHEET_H)
        lay = ps.dxf_layout.dxf
        lay.limmin = (0, 0)
        lay.limmax = (SHEET_W, SHEET_H)
        lay.extmin = (0, 0, 0)
        lay.extmax = (SHEET_W, SHEET_H, 0)
        doc.header["$PLIMMIN"] = (0, 0)
        doc.header["$PLIMMAX"] = (SHEET_W, SHEET_H)
        used = {STYLE, "Standard"}
        for st in list(doc.styles):
            if st.dxf.name not in used:
                doc.styles.remove(st.dxf.name)


FRAME_INNER = (FRAME[0] + 1.0, FRAME[1] + 1.0, FRAME[2] - 1.0, FRAME[3] - 1.0)
DESCENTS = 0.25  # = layout.DESCENT
SUB_DESCENTS = 0.45  # = layout.SUB_DESCENT


def _segments_cross(a, b, c, d) -> bool:
    """Whether the segments a–b and c–d cross (touching ends do not count)."""
    a, b, c, d = (np.asarray(q, dtype=float) for q in (a, b, c, d))

    def side(p, q, r):
        return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])

    d1, d2, d3, d4 = side(c, d, a), side(c, d, b), side(a, b, c), side(a, b, d)
    return d1 * d2 < -1e-12 and d3 * d4 < -1e-12


def _dirs_towards(v) -> tuple[str, ...]:
    """The compass directions ordered by closeness to the vector v (a label goes outward first)."""
    vecs = {"e": (1, 0), "ne": (0.707, 0.707), "n": (0, 1), "nw": (-0.707, 0.707), "w": (-1, 0),
            "sw": (-0.707, -0.707), "s": (0, -1), "se": (0.707, -0.707)}
    return tuple(sorted(vecs, key=lambda k: -(vecs[k][0] * v[0] + vecs[k][1] * v[1])))


def _wrap(text: str, n: int) -> list[str] | None:
    """Split `text` at spaces into `n` lines, the longest as short as it can be (None if it has too
    few words).

    >>> _wrap("Синтез кулачкового механизма", 2)
    ['Синтез кулачкового', 'механизма']
    """
    words = text.split(" ")
    if len(words) < n:
        return None
    from functools import lru_cache

    @lru_cache(maxsize=None)
    def best(i: int, k: int) -> tuple[int, tuple[int, ...]]:
        """(the longest line, the break positions) of words[i:] on k lines."""
        if k == 1:
            return len(" ".join(words[i:])), ()
        out = (10 ** 9, ())
        for j in range(i + 1, len(words) - k + 2):
            head = len(" ".join(words[i:j]))
            rest, cuts = best(j, k - 1)
            cand = (max(head, rest), (j, *cuts))
            if cand[0] < out[0]:
                out = cand
        return out

    cuts = (0, *best(0, n)[1], len(words))
    return [" ".join(words[a:b]) for a, b in zip(cuts[:-1], cuts[1:])]
