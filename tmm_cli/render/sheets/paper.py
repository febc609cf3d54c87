"""The A1 sheet itself: an ezdxf document with the ESKD frame, title block, layers and text.

Everything is drawn in sheet millimetres (the model space origin is the sheet's lower-left
corner, 1 unit = 1 mm on paper). A :class:`Field` maps a drawing's own units (real millimetres
of the mechanism) to the sheet by ``sheet = origin + scale·real``; each field records its box,
origin and scale as XDATA on its heading so that a test (or a CAD user) can read them back from
the file.

Facts used (``/work/shared/DRAWING.md``): A1 841 × 594 (ГОСТ 2.301), frame 20/5/5/5 mm; title
block form 1 185 × 55 (ГОСТ 2.104); lines 0.7 / 0.25 mm, dash-dot axes, dashed hidden lines
(ГОСТ 2.303); text heights 2.5 … 10 mm (ГОСТ 2.304); scales of ГОСТ 2.302.

ezdxf is imported inside :func:`new_sheet` only (``tmm --help`` stays fast).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

import numpy as np

SHEET_W, SHEET_H = 841.0, 594.0  # A1 landscape [mm]
FRAME = (20.0, 5.0, SHEET_W - 5.0, SHEET_H - 5.0)  # x0, y0, x1, y1 of the frame
TB_W, TB_H = 185.0, 55.0  # title block form 1
TB_ORIGIN = (FRAME[2] - TB_W, FRAME[1])  # its lower-left corner
TEXT_HEIGHTS = (2.5, 3.5, 5.0, 7.0, 10.0, 14.0, 20.0)  # ГОСТ 2.304
MIN_WIDTH_FACTOR = 0.6  # narrower text is hard to read; wrap or shrink the height instead

# ГОСТ 2.302: reduction, natural and enlargement scales (label, paper mm per real mm)
GOST_SCALES: tuple[tuple[str, float], ...] = (
    ("1:100", 0.01), ("1:75", 1 / 75), ("1:50", 0.02), ("1:40", 0.025), ("1:25", 0.04), ("1:20", 0.05),
    ("1:15", 1 / 15), ("1:10", 0.1), ("1:5", 0.2), ("1:4", 0.25), ("1:2,5", 0.4), ("1:2", 0.5), ("1:1", 1.0),
    ("2:1", 2.0), ("2,5:1", 2.5), ("4:1", 4.0), ("5:1", 5.0), ("10:1", 10.0), ("20:1", 20.0), ("40:1", 40.0),
    ("50:1", 50.0), ("100:1", 100.0),
)
GOST_SCALE_LABELS = tuple(lab for lab, _ in GOST_SCALES)

# layer: (ACI colour, lineweight [1/100 mm], linetype)
LAYERS = {
    "Основные": (7, 70, "Continuous"),
    "Тонкие": (7, 25, "Continuous"),
    "Осевые": (1, 25, "CENTER"),
    "Размеры": (3, 25, "Continuous"),
    "Текст": (7, 25, "Continuous"),
    "Рамка": (7, 70, "Continuous"),
}
LTSCALE = 5.0  # CENTER: 16 mm dashes, 3 mm gaps; DASHED: 6 mm dashes, 1.3 mm gaps (ГОСТ 2.303)
XDATA_APP = "TMM_FIELD"
STYLE = "OpenGostTypeA-Regular"  # LibreCAD picks its GOST stroke font by this name; others use the TTF
FONT_GOST = "osifont.ttf"
FONT_FALLBACK = "DejaVuSans.ttf"


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

    def to_sheet(self, pts) -> np.ndarray:
        a = np.asarray(pts, dtype=float)
        return np.asarray(self.origin) + self.scale * a

    def p(self, x: float, y: float) -> tuple[float, float]:
        return (self.origin[0] + self.scale * x, self.origin[1] + self.scale * y)

    # drawing in the field's own units, clipped to the field
    def poly(self, pts, layer="Основные", linetype=None, closed=False, clip=True):
        q = self.to_sheet(pts)
        if closed:
            q = np.vstack([q, q[:1]])
        if not clip:
            return [self.sheet.poly(q, layer, linetype)]
        return [self.sheet.poly(piece, layer, linetype) for piece in clip_polyline(q, self.box)]

    def circle(self, c, r, layer="Основные", linetype=None):
        cc = self.p(*c)
        return self.sheet.circle_in(cc, r * self.scale, self.box, layer, linetype)

    def line(self, a, b, layer="Тонкие", linetype=None):
        return self.poly([a, b], layer, linetype)


class Sheet:
    """One A1 drawing: ezdxf document, layers, text style, frame, title block, fields."""

    def __init__(self, lang: str = "ru"):
        import ezdxf
        from ezdxf.fonts import fonts

        self.lang = lang
        doc = ezdxf.new("R2010", setup=True)
        doc.units = 4  # millimetres
        doc.header["$INSUNITS"] = 4
        doc.header["$MEASUREMENT"] = 1
        doc.header["$LTSCALE"] = LTSCALE
        doc.header["$LWDISPLAY"] = 1
        doc.header["$EXTMIN"] = (0, 0, 0)
        doc.header["$EXTMAX"] = (SHEET_W, SHEET_H, 0)
        doc.header["$LIMMIN"] = (0, 0)
        doc.header["$LIMMAX"] = (SHEET_W, SHEET_H)
        for name, (color, lw, lt) in LAYERS.items():
            doc.layers.add(name, color=color, lineweight=lw, linetype=lt)
        self.font_file = FONT_GOST if fonts.font_manager.has_font(FONT_GOST) else FONT_FALLBACK
        if not fonts.font_manager.has_font(self.font_file):
            _add_matplotlib_fonts()
        doc.styles.add(STYLE, font=self.font_file)
        doc.appids.add(XDATA_APP)
        self.doc = doc
        self.msp = doc.modelspace()
        self._fonts: dict = {}
        self.fields: list[Field] = []

    # ------------------------------------------------------------------ primitives (sheet mm)
    def _attr(self, layer, linetype=None, **kw):
        a = {"layer": layer}
        if linetype:
            a["linetype"] = linetype
        a.update(kw)
        return a

    def line(self, a, b, layer="Тонкие", linetype=None):
        return self.msp.add_line((float(a[0]), float(a[1])), (float(b[0]), float(b[1])), dxfattribs=self._attr(layer, linetype))

    def poly(self, pts, layer="Основные", linetype=None, closed=False):
        pts = [(float(x), float(y)) for x, y in np.asarray(pts, dtype=float)]
        e = self.msp.add_lwpolyline(pts, format="xy", close=closed, dxfattribs=self._attr(layer, linetype))
        if linetype:
            e.dxf.linetype = linetype
        return e

    def rect(self, x0, y0, x1, y1, layer="Тонкие"):
        return self.poly([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], layer, closed=True)

    def circle(self, c, r, layer="Основные", linetype=None):
        return self.msp.add_circle((float(c[0]), float(c[1])), float(r), dxfattribs=self._attr(layer, linetype))

    def arc(self, c, r, a0, a1, layer="Тонкие", linetype=None):
        return self.msp.add_arc((float(c[0]), float(c[1])), float(r), float(a0), float(a1), dxfattribs=self._attr(layer, linetype))

    def circle_in(self, c, r, box, layer="Основные", linetype=None):
        """A circle, or its arcs inside `box` when it does not fit."""
        spans = circle_arcs_in_box(c, r, box)
        if spans is None:
            return [self.circle(c, r, layer, linetype)]
        return [self.arc(c, r, a % 360.0, b % 360.0 if b % 360.0 else 360.0, layer, linetype) for a, b in spans]

    def solid(self, pts, layer="Размеры"):
        p = [(float(x), float(y)) for x, y in pts]
        if len(p) == 3:
            p.append(p[2])
        return self.msp.add_solid(p, dxfattribs={"layer": layer})

    def dot(self, c, r=0.7, layer="Основные"):
        """A filled point (a small solid disc as a thick donut polyline)."""
        x, y = float(c[0]), float(c[1])
        e = self.msp.add_lwpolyline([(x - r / 2, y, r, r, 1.0), (x + r / 2, y, r, r, 1.0)], format="xyseb", close=True,
                                    dxfattribs={"layer": layer})
        return e

    def arrow(self, tip, direction, layer="Размеры", length=3.5, width=1.0):
        d = np.asarray(direction, dtype=float)
        d = d / (np.hypot(*d) or 1.0)
        n = np.array([-d[1], d[0]])
        t = np.asarray(tip, dtype=float)
        base = t - length * d
        return self.solid([t, base + n * width / 2, base - n * width / 2], layer)

    # ------------------------------------------------------------------------ dimensions
    def dim_linear(self, a, b, offset, text: str, h: float = 3.5, ext: bool = True):
        """A dimension between points a, b [sheet mm], its line shifted by the vector `offset`:
        extension lines, a thin line with two arrows, the text above its middle (exploded into
        plain entities, so every CAD program shows it as drawn)."""
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
        inside = L > 9.0
        if inside:
            self.line(pa, pb, "Размеры")
            self.arrow(pa, -u, "Размеры", 3.0, 0.9)
            self.arrow(pb, u, "Размеры", 3.0, 0.9)
        else:  # arrows from outside
            self.line(pa - 7 * u, pb + 7 * u, "Размеры")
            self.arrow(pa, u, "Размеры", 3.0, 0.9)
            self.arrow(pb, -u, "Размеры", 3.0, 0.9)
        ang = math.degrees(math.atan2(u[1], u[0]))
        if ang > 90.5 or ang < -89.5:
            ang += 180.0
            u = -u
        nrm = np.array([-u[1], u[0]])
        mid = (pa + pb) / 2 + nrm * 1.0
        if not inside:
            mid = mid + u * (L / 2 + 9.0)
        self.text(mid[0], mid[1], text, h, align="center" if inside else "left", rot=((ang + 180) % 360) - 180)

    def dim_arc(self, c, r, a0, a1, text: str, h: float = 3.5, ext_from: float | None = None):
        """An angular/arc dimension: an arc of radius r [sheet mm] from a0 to a1 [deg, ccw] with
        arrows at both ends; extension lines from radius `ext_from`; text outside its middle."""
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
        am = math.radians((a0 + a1) / 2)
        q = c + (r + 1.2) * np.array([math.cos(am), math.sin(am)])
        rot = math.degrees(am) - 90.0
        if math.sin(am) < 0:
            rot += 180.0
            q = c + (r + 1.2 + h) * np.array([math.cos(am), math.sin(am)])
        self.text(q[0], q[1], text, h, align="center", rot=rot)

    # ------------------------------------------------------------------------------ text
    def font(self, h: float, wf: float = 1.0):
        from ezdxf.fonts import fonts

        key = (round(h, 4), round(wf, 4))
        if key not in self._fonts:
            self._fonts[key] = fonts.make_font(self.font_file, h, wf)
        return self._fonts[key]

    def text_width(self, text: str, h: float, wf: float = 1.0) -> float:
        w = 0.0
        for part, lv in rich_parts(text):
            hh = h if lv == 0 else h * SUB_RATIO
            w += self.font(hh, wf).text_width(part)
        return w

    def caption(self, x0: float, x1: float, y_bottom: float, lines: list[str], h: float, step: float) -> None:
        """`lines` of height `h` stacked `step` mm apart upwards from `y_bottom`, the last one lowest,
        each kept within x0 … x1 (2 mm in from either side)."""
        y = y_bottom + step * (len(lines) - 1)
        for t in lines:
            self.text(x0 + 2.0, y, t, h, width=x1 - x0 - 4.0)
            y -= step

    def text(self, x, y, text: str, h: float = 3.5, *, align: str = "left", valign: str = "base",
             width: float | None = None, rot: float = 0.0, layer: str = "Текст", max_lines: int = 1,
             line_gap: float = 0.5, height_max: float | None = None) -> list:
        """Text at (x, y) [sheet mm] with ГОСТ height `h`; markup _{sub}, ^{sup}.

        A text wider than `width` is first narrowed (width factor down to 0.6), then wrapped
        into at most `max_lines` lines, then set a size smaller — never spilled over a line.
        `height_max` limits the height of the whole block (valign 'top'/'middle' blocks).
        Returns the entities.
        """
        if not text:
            return []
        h, wf, lines = self._fit(text, h, width, max_lines, height_max, line_gap)
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
            w = self.text_width(line, h, wf)
            dx = {"left": 0.0, "center": -w / 2, "right": -w}[align]
            dy = y0 - k * step
            cx = dx
            for part, lv in rich_parts(line):
                hh = h if lv == 0 else h * SUB_RATIO
                off = 0.0 if lv == 0 else (-0.3 * h if lv < 0 else 0.55 * h)
                px, py = cx, dy + off
                X, Y = x + c * px - s * py, y + s * px + c * py
                e = self.msp.add_text(part, height=hh, rotation=rot,
                                      dxfattribs={"layer": layer, "style": STYLE, "width": wf})
                e.set_placement((X, Y))
                out.append(e)
                cx += self.font(hh, wf).text_width(part)
        return out

    def _fit(self, text, h, width, max_lines, height_max, gap):
        def block_h(hh, n):
            return hh * n + (n - 1) * hh * (gap + 0.15)

        heights = [x for x in TEXT_HEIGHTS if x <= h + 1e-9][::-1] or [h]
        heights += [2.0, 1.8]
        for hh in heights:
            if height_max is not None and block_h(hh, 1) > height_max + 1e-9:
                continue
            for n in range(1, max_lines + 1):
                if height_max is not None and block_h(hh, n) > height_max + 1e-9:
                    break
                lines = _wrap(text, n) if n > 1 else [text]
                if lines is None:
                    continue
                if width is None:
                    return hh, 1.0, lines
                w = max(self.text_width(t, hh) for t in lines)
                if w <= width:
                    return hh, 1.0, lines
                if w * MIN_WIDTH_FACTOR <= width:
                    return hh, max(MIN_WIDTH_FACTOR, width / w * 0.999), lines
        # last resort: the smallest height, as many lines as allowed, narrowed as far as needed
        hh = heights[-1]
        best = [text]
        for n in range(2, max_lines + 1):
            if height_max is not None and block_h(hh, n) > height_max + 1e-9:
                break
            best = _wrap(text, n) or best
        w = max(self.text_width(t, hh) for t in best)
        return hh, min(1.0, (width or w) / w * 0.999), best

    # ----------------------------------------------------------------------------- fields
    def add_field(self, name: str, box, heading: str, *, origin=(0.0, 0.0), scale: float = 1.0,
                  scale_label: str = "", heading_h: float = 5.0, scale_text: str | None = None) -> Field:
        """A field with its heading centred at the top (upper case, as on the book's sheets).

        The heading carries XDATA: name, box, origin, scale, scale label (read by the tests).
        `scale_text` is printed under the heading (e.g. "М 1:2").
        """
        x0, y0, x1, y1 = box
        head = self.text((x0 + x1) / 2, y1 - 1.5, heading.upper(), heading_h, align="center", valign="top",
                         width=x1 - x0 - 4, max_lines=2)
        top = y1 - 1.5 - heading_h
        if len(head) and head[-1].dxf.insert[1] < top - 1:
            top = head[-1].dxf.insert[1]
        if scale_text:
            self.text((x0 + x1) / 2, top - 2.0, scale_text, 5.0, align="center", valign="top", width=x1 - x0 - 4)
            top -= 2.0 + 5.0
        tags = [(1000, name)] + [(1040, float(v)) for v in (*box, *origin, scale)] + [(1000, scale_label or "")]
        head[0].set_xdata(XDATA_APP, tags)
        f = Field(self, name, tuple(box), tuple(origin), scale, scale_label, inner=(x0, y0, x1, top - 2.0))
        self.fields.append(f)
        return f

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
            return self.text(X + x, Y + y, s, h, width=w, align=align, **kw)

        for x, w, s in ((0, 7, "Изм."), (7, 10, "Лист"), (17, 23, "№ докум."), (40, 15, "Подп."), (55, 10, "Дата")):
            T(x + w / 2, 31.2, s, 2.5, w - 1, "center")
        # lower rows, top down: Разраб. 25–30, Пров. 20–25, Т.контр. 15–20, (free), Н.контр., Утв.
        for k, s in enumerate(("Разраб.", "Пров.", "Т.контр.", "", "Н.контр.", "Утв.")):
            if s:
                T(0.8, 25 - k * 5 + 1.2, s, 2.5, 15.5)
        T(17.6, 27.5, title.student, 3.5, 22.0, valign="middle", max_lines=2, height_max=4.6)
        T(17.6, 22.5, title.teacher, 3.5, 22.0, valign="middle", max_lines=2, height_max=4.6)
        for x, w, s in ((135, 15, "Лит."), (150, 17, "Масса"), (167, 18, "Масштаб")):
            T(x + w / 2, 36.2, s, 2.5, w - 1, "center")
        T(176, 27.5, scale, 5.0, 16, "center", valign="middle")
        T(137.5, 27.5, "У", 3.5, 4, "center", valign="middle")  # литера: учебный документ
        T(136, 16.2, "Лист 1", 2.5, 18)
        T(156, 16.2, "Листов 1", 2.5, 28)
        T(125, 47.5, designation, 7.0, 114, "center", valign="middle")
        T(100, 27.5, name, 5.0, 66, "center", valign="middle", max_lines=3, height_max=23)
        org = ", ".join(s for s in (title.org, ("гр. " + title.group) if title.group else "") if s)
        if org_extra:
            org = f"{org}, {org_extra}" if org else org_extra
        T(160, 7.5, org, 3.5, 48, "center", valign="middle", max_lines=3, height_max=13.5)


def _wrap(text: str, n: int) -> list[str] | None:
    """Split `text` at spaces into `n` lines of about equal length (None if it has too few words)."""
    words = text.split(" ")
    if len(words) < n:
        return None
    target = len(text) / n
    lines, cur = [], ""
    for w in words:
        if cur and len(cur) + 1 + len(w) > target * 1.15 and len(lines) < n - 1:
            lines.append(cur)
            cur = w
        else:
            cur = f"{cur} {w}" if cur else w
    lines.append(cur)
    return lines


def _add_matplotlib_fonts() -> None:
    """Let ezdxf find the DejaVu fonts matplotlib ships (a machine without system fonts)."""
    try:
        from pathlib import Path

        import matplotlib
        from ezdxf.fonts import fonts

        folder = Path(matplotlib.get_data_path()) / "fonts" / "ttf"
        fonts.font_manager.build([str(folder)], support_dirs=False)
    except Exception:  # pragma: no cover - ezdxf then uses its own fallback font
        pass
