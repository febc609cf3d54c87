"""tmm's Agg canvas: matplotlib's own, made cheaper by hooks into matplotlib's private parts.

A private part can change in any matplotlib release, so each hook is used only
- on the releases it was compared on, pixel for pixel with plain matplotlib (:data:`TESTED`), and
- where the parts it reaches for are there (feature detection: :func:`available`);
elsewhere matplotlib draws as it does (the figures are the same drawings; a text may sit half a
pixel elsewhere). ``TMM_MPL_HOOKS=off`` (or a comma list of hook names) chooses by hand, to compare.

The hooks (:data:`HOOKS`). What they save, measured by `bench/figure_hooks.py` (CPU time of drawing
and saving a project's eight figures and the note's SVG copies, matplotlib 3.11.2, median of 5 on a
shared 2-core machine, ±4 %): without any, one project's figures take 21 % longer and a batch
worker's next variant 62 % longer; without one of them (one project / the next variant):
text_bitmaps +12 % / +21 %, formula_cache −3 % / +13 %, svg_text +2 % / +11 %, copied_ticks
+2 % / +7 %, height_metrics +1 % / +6 %, glyph_bitmaps +2 % / +6 %, shared_fontsets +4 % / +1 %.

- ``text_bitmaps`` — a plain text rendered as one bitmap, kept, blitted at a whole pixel (matplotlib
  ≤ 3.10's way; 3.11 lays out and renders every glyph on its own at every draw), and rendered as it
  is measured (one FreeType layout, not two);
- ``glyph_bitmaps`` — matplotlib ≥ 3.11's glyph-by-glyph drawing of formulas, each glyph's bitmap
  kept by its 1/64-pixel place;
- ``formula_cache`` — 512 parsed formulas kept instead of 50;
- ``shared_fontsets`` — one mathtext fontset per font for the shared parser (matplotlib makes one
  per formula and looks every glyph's metrics up again), kerning read at the formula's own size;
- ``height_metrics`` — a font's ascent, descent and line gap kept (matplotlib ≥ 3.11 reads them
  from the font's tables for every layout of every text);
- ``copied_ticks`` — a new tick is a copy of its axis's first one, not five artists made anew;
- ``svg_text`` — every SVG renderer lays its text out with one ``TextToPath`` and one table of text
  metrics (:func:`share_svg_text`).

What uses public API only is always on: figures of one size share a renderer, every renderer one
mathtext parser, and an opaque figure goes to PNG as RGB by :func:`png_rgb`.

matplotlib is imported inside the functions only, so importing this module stays cheap.
"""

from __future__ import annotations

import math
import os

# The matplotlib releases the hooks were compared on: from 3.8.4 (the package's floor) up to, not
# including, 3.12. A release outside it draws with plain matplotlib until someone compares it
# (tests/test_figures_agg.py, the floors test on the lowest and the newest release) and moves this.
TESTED = ((3, 8, 4), (3, 12, 0))

HOOKS = ("text_bitmaps", "glyph_bitmaps", "formula_cache", "shared_fontsets", "height_metrics", "copied_ticks",
         "svg_text")

_STATE: dict = {}  # "hooks": the frozenset in use, "classes": (figure class, canvas class), "parse": matplotlib's own
_RENDERERS: dict = {}  # (width px, height px, dpi) -> a renderer shared by the figures of that size
_RENDERERS_KEPT = 8  # 2–9 MB each; the eight figures of a project come in at most eight sizes
_PARSERS: list = []  # the first renderer's mathtext parser, given to every other one
_MATHTEXT_CACHE = 512  # parsed formulas kept (matplotlib's default is 50)
_TEXT_BITMAPS: dict = {}  # (text, font, hinting, antialiased, dpi) -> its bitmap, descent, offsets
_TEXT_BITMAPS_KEPT = 4096  # small grey images (a label is a few kB)
_GLYPHS: dict = {}  # (font, size, dpi, glyph, flags, antialiased, turn, 1/64 px fractions) -> bitmap, left, top
_GLYPHS_KEPT = 50_000  # a glyph's bitmap is ≈ 100 bytes; a batch meets ≈ 8 000 keys
_GLYPH_MATRICES: dict = {}  # (angle, slant, extend) -> FreeType's 16.16 transform
_HEIGHT_METRICS: dict = {}  # (font, dpi) -> (ascent, descent, line gap) [px]: a few fonts and sizes
_SVG_TEXT: list = []  # the one TextToPath of every SVG renderer in this process (see share_svg_text)
_SVG_METRICS: dict = {}  # (text, font, ismath) -> (width, height, descent) in SVG points


def in_tested_range(version_info=None) -> bool:
    """Whether this matplotlib (or `version_info`, (major, minor, micro)) is in :data:`TESTED`.

    >>> in_tested_range((3, 8, 4)), in_tested_range((3, 11, 9)), in_tested_range((3, 8, 3)), in_tested_range((3, 12, 0))
    (True, True, False, False)
    """
    if version_info is None:
        import matplotlib

        version_info = getattr(matplotlib, "__version_info__", None)
        if version_info is None:
            return False
        version_info = (version_info.major, version_info.minor, version_info.micro)
    return TESTED[0] <= tuple(version_info[:3]) < TESTED[1]


def available() -> frozenset[str]:
    """The hooks this matplotlib allows: in the tested range, and each finding what it reaches for."""
    if not in_tested_range():
        return frozenset()
    found = set()
    for name in HOOKS:
        try:
            if _DETECT[name]():
                found.add(name)
        except Exception:  # anything missing or shaped otherwise: matplotlib's own way
            pass
    return frozenset(found)


def hooks() -> frozenset[str]:
    """The hooks in use in this process: :func:`available`, or those ``TMM_MPL_HOOKS`` names among
    them (``off`` for none)."""
    on = _STATE.get("hooks")
    if on is None:
        on = available()
        asked = os.environ.get("TMM_MPL_HOOKS", "").strip()
        if asked:
            on = on & {h.strip() for h in asked.split(",")}
        on = _STATE["hooks"] = frozenset(on)
    return on


def use(names) -> frozenset[str]:
    """Use the hooks `names` (those available) from now on in this process — for tests and
    comparisons; figures made before keep their classes. Returns the hooks in use."""
    _forget_fonts()
    _STATE.pop("classes", None)
    _STATE["hooks"] = available() & frozenset(names)
    _install_formula_cache("formula_cache" in _STATE["hooks"])
    if "svg_text" not in _STATE["hooks"]:
        _unshare_svg_text()
    return _STATE["hooks"]


def classes():
    """(figure class, canvas class) for the hooks in use, made once."""
    made = _STATE.get("classes")
    if made is None:
        on = hooks()
        _install_formula_cache("formula_cache" in on)
        _register_fork_handler()
        made = _STATE["classes"] = (_figure_class(on), _canvas_class(on))
    return made


# --- feature detection: what each hook reaches for -----------------------------------------------

def _has_text_bitmaps() -> bool:
    from matplotlib.backends.backend_agg import RendererAgg, get_hinting_flag  # noqa: F401
    from matplotlib.ft2font import FT2Font

    renderer = RendererAgg(1, 1, 72)
    return (callable(getattr(renderer, "_prepare_font", None)) and hasattr(renderer._renderer, "draw_text_image")
            and all(hasattr(FT2Font, m) for m in ("set_text", "get_width_height", "get_descent",
                                                  "draw_glyphs_to_bitmap", "get_bitmap_offset", "get_image")))


def _has_glyph_bitmaps() -> bool:
    import inspect

    from matplotlib.backends.backend_agg import RendererAgg
    from matplotlib.ft2font import FT2Font, RenderMode  # noqa: F401  (3.11)

    draw = getattr(RendererAgg, "_draw_text_glyphs_and_boxes", None)
    return (draw is not None and list(inspect.signature(draw).parameters) == ["self", "gc", "x", "y", "angle", "glyphs", "boxes"]
            and hasattr(FT2Font, "_set_transform") and hasattr(FT2Font, "_render_glyph"))


def _has_formula_cache() -> bool:
    from matplotlib.mathtext import MathTextParser

    cached = _STATE.get("parse", MathTextParser._parse_cached)
    return hasattr(cached, "__wrapped__") and hasattr(cached, "cache_clear")


def _has_shared_fontsets() -> bool:
    import inspect

    from matplotlib.backends.backend_agg import RendererAgg

    parser = RendererAgg(1, 1, 72).mathtext_parser
    mapping = getattr(type(parser), "_font_type_mapping", None)
    fontset = next(iter(mapping.values())) if isinstance(mapping, dict) and mapping else None
    return (getattr(parser, "_output_type", None) == "vector"  # 3.11: Agg's formulas are paths (before, bitmaps
            and fontset is not None                            # drawn from glyph objects a shared font forgets)
            and hasattr(fontset, "_get_info") and len(inspect.signature(fontset.get_kern).parameters) == 10)


def _has_height_metrics() -> bool:
    import matplotlib.text
    from matplotlib.font_manager import fontManager

    # matplotlib asks a renderer for them where it has the method (Text._get_layout, 3.11): the
    # name is among those its code reads
    code = matplotlib.text.Text._get_layout.__code__
    return ("_get_font_height_metrics" in code.co_names + code.co_consts
            and callable(getattr(fontManager, "_find_fonts_by_props", None)))


def _has_copied_ticks() -> bool:
    from matplotlib.axis import XAxis
    from matplotlib.cbook import CallbackRegistry
    from matplotlib.lines import Line2D
    from matplotlib.text import Text

    line, text = Line2D([0], [0]), Text(0, 0, "x")
    return (isinstance(line._callbacks, CallbackRegistry) and isinstance(line._path_effects, list)
            and hasattr(line, "_xorig") and hasattr(text, "_fontproperties")
            and all(hasattr(XAxis, m) for m in ("majorTicks", "minorTicks", "get_majorticklocs", "get_minorticklocs")))


def _has_svg_text() -> bool:
    import io

    from matplotlib.backends.backend_svg import RendererSVG
    from matplotlib.textpath import TextToPath

    code = RendererSVG.__dict__["get_text_width_height_descent"].__code__  # its own: it asks its TextToPath
    return (isinstance(getattr(RendererSVG(1, 1, io.StringIO()), "_text2path", None), TextToPath)
            and {"_text2path", "get_text_width_height_descent"} <= set(code.co_names))


_DETECT = {"text_bitmaps": _has_text_bitmaps, "glyph_bitmaps": _has_glyph_bitmaps, "formula_cache": _has_formula_cache,
           "shared_fontsets": _has_shared_fontsets, "height_metrics": _has_height_metrics,
           "copied_ticks": _has_copied_ticks, "svg_text": _has_svg_text}


# --- the process-wide parts: the formula cache, fonts across a fork --------------------------------

def _install_formula_cache(on: bool) -> None:
    """matplotlib's cache of parsed formulas (``MathTextParser._parse_cached``, 50 entries) made
    :data:`_MATHTEXT_CACHE` long (one variant has ≈ 30 formulas, a batch repeats most), or put back."""
    import functools

    from matplotlib.mathtext import MathTextParser

    own = _STATE.setdefault("parse", MathTextParser._parse_cached)
    if on:
        if MathTextParser._parse_cached is own:
            MathTextParser._parse_cached = functools.lru_cache(_MATHTEXT_CACHE)(own.__wrapped__)
    else:
        MathTextParser._parse_cached = own


def _forget_fonts() -> None:
    """Drop the shared renderers and parser and the parsed formulas, which hold FreeType fonts.

    Run in a forked child: a font object must never cross a fork (it reads its file through a
    descriptor the two processes share: interleaved reads give "FT_Load_Glyph … invalid outline");
    matplotlib drops its own font cache in the child for the same reason."""
    _PARSERS.clear()
    _RENDERERS.clear()
    from matplotlib.mathtext import MathTextParser

    clear = getattr(MathTextParser._parse_cached, "cache_clear", None)
    if clear is not None:
        clear()


def _register_fork_handler() -> None:
    if "fork" not in _STATE and hasattr(os, "register_at_fork"):
        os.register_at_fork(after_in_child=_forget_fonts)
    _STATE["fork"] = True


# --- the classes ---------------------------------------------------------------------------------

def _renderer_class(on: frozenset):
    """RendererAgg with the renderer hooks of `on` (RendererAgg itself if none)."""
    import numpy as np
    from matplotlib.backends.backend_agg import RendererAgg, get_hinting_flag

    methods: dict = {}
    if "text_bitmaps" in on:
        def draw_text(self, gc, x, y, s, prop, angle, ismath=False, mtext=None):
            """A plain text as one bitmap blitted at a whole pixel, as matplotlib did up to 3.10, the
            bitmap kept: a text met again (a tick value, an axis label, a legend entry; the batch
            repeats most of them) costs one blit. matplotlib 3.11 lays the string out again and
            renders every glyph on its own at a sub-pixel place on every draw (≈ 0.1 ms a
            character); the text lands within half a pixel of 3.11's place, as it always did before
            3.11. Formulas (mathtext) stay matplotlib's: drawn as one bitmap their glyphs snap to
            whole pixels and a word can gape ("пособи ю"). A text with font features or a language
            goes matplotlib's way too."""
            if ismath or _shaped(mtext):
                return RendererAgg.draw_text(self, gc, x, y, s, prop, angle, ismath=ismath, mtext=mtext)
            image, descent, xo, yo, _ = self._bitmap(s, prop, bool(gc.get_antialiased()))
            # the descent turned with the text (matplotlib 3.10's draw_text)
            x = round(x + xo + descent * math.sin(math.radians(angle)))
            y = round(y + yo + descent * math.cos(math.radians(angle)))
            self._renderer.draw_text_image(image, x, y + 1, angle, gc)

        def get_text_width_height_descent(self, s, prop, ismath):
            """matplotlib's, but a plain text is rendered as it is measured and the bitmap kept for
            draw_text: laying a string out (``FT2Font.set_text``, ≈ 0.05 ms a character under
            matplotlib 3.11) was done twice for every new text, once to measure, once to draw."""
            if ismath or not isinstance(s, str):
                return RendererAgg.get_text_width_height_descent(self, s, prop, ismath)
            return self._bitmap(s, prop, True)[4]

        def _bitmap(self, s, prop, aa: bool):
            """(bitmap, descent, x and y offsets [px], (width, height, descent) [px]) of the plain
            text `s`, kept (the most recently used last)."""
            flags = get_hinting_flag()
            key = (s, _font_key(prop), flags, aa, self.dpi)
            hit = _TEXT_BITMAPS.pop(key, None)
            if hit is None:
                font = self._prepare_font(prop)
                font.set_text(s, 0.0, flags=flags)
                w, h = font.get_width_height()  # of the unrotated string [1/64 px]
                d = font.get_descent()
                font.draw_glyphs_to_bitmap(antialiased=aa)
                xo, yo = font.get_bitmap_offset()
                hit = (np.array(font.get_image()), d / 64.0, xo / 64.0, yo / 64.0, (w / 64.0, h / 64.0, d / 64.0))
            _TEXT_BITMAPS[key] = hit
            while len(_TEXT_BITMAPS) > _TEXT_BITMAPS_KEPT:
                _TEXT_BITMAPS.pop(next(iter(_TEXT_BITMAPS)))
            return hit

        methods.update(draw_text=draw_text, get_text_width_height_descent=get_text_width_height_descent, _bitmap=_bitmap)

    if "glyph_bitmaps" in on:
        def _draw_text_glyphs_and_boxes(self, gc, x, y, angle, glyphs, boxes):
            """matplotlib ≥ 3.11's drawing of a formula (and of a shaped text) glyph by glyph, but
            each glyph's bitmap is kept: FreeType renders a glyph at its place to 1/64 px, and the
            same glyph at the same fraction of a pixel is the same bitmap moved by whole pixels, so
            the key is (font, size, glyph, flags, turn, the fractions) and a hit is one blit. Over a
            batch four glyphs in five are hits (the legends and titles repeat their words); the
            pixels are matplotlib's exactly, drawn in its order. Rules (fraction bars) are left to
            matplotlib."""
            from matplotlib.ft2font import RenderMode

            cos, sin = math.cos(math.radians(angle)), math.sin(math.radians(angle))
            flags = get_hinting_flag()
            aa = bool(gc.get_antialiased())
            height = self.height
            for font, size, index, slant, extend, dx, dy in glyphs:  # dy is upwards
                turn = (angle, slant, extend)
                matrix = _GLYPH_MATRICES.get(turn)
                if matrix is None:  # as matplotlib makes it, once per turn
                    matrix = _GLYPH_MATRICES[turn] = (
                        0x10000 * np.array([[cos, -sin], [sin, cos]]) @ [[extend, extend * slant], [0, 1]]
                    ).round().astype(int)
                tx = round(0x40 * (x + dx * cos - dy * sin))
                ty = round(0x40 * (height - y + dx * sin + dy * cos))  # FreeType's y is upwards
                key = (font.fname, size, self.dpi, index, flags, aa, turn, tx & 63, ty & 63)
                hit = _GLYPHS.get(key)
                if hit is None:
                    font.set_size(size, self.dpi)
                    font._set_transform(matrix, [tx & 63, ty & 63])
                    bitmap = font._render_glyph(index, flags, RenderMode.NORMAL if aa else RenderMode.MONO)
                    buffer = bitmap.buffer if aa else bitmap.buffer * 0xFF
                    if len(_GLYPHS) >= _GLYPHS_KEPT:
                        _GLYPHS.clear()
                    hit = _GLYPHS[key] = (buffer, bitmap.left, bitmap.top)
                buffer, left, top = hit
                self._renderer.draw_text_image(buffer, left + (tx >> 6), int(height) - (top + (ty >> 6)) + buffer.shape[0], 0, gc)
            boxes = list(boxes)
            if boxes:
                RendererAgg._draw_text_glyphs_and_boxes(self, gc, x, y, angle, (), boxes)

        methods["_draw_text_glyphs_and_boxes"] = _draw_text_glyphs_and_boxes

    if "height_metrics" in on:
        def _get_font_height_metrics(self, prop):
            """(ascent, descent, line gap) [px] of the font of `prop` at this renderer's dpi, as
            matplotlib ≥ 3.11 computes them in ``Text._get_layout`` from the font's OS/2 (or hhea)
            table — the same numbers, kept: it looked the font up and read two tables again for
            every layout of every text (≈ 5 % of a figure's saving time)."""
            key = (_font_key(prop), self.dpi)
            hit = _HEIGHT_METRICS.get(key)
            if hit is None:
                from matplotlib.font_manager import fontManager, get_font

                hit = (None, None, None)
                font = get_font(fontManager._find_fonts_by_props(prop))
                for table_name, gap, ascent, descent in (("OS/2", "sTypoLineGap", "sTypoAscender", "sTypoDescender"),
                                                         ("hhea", "lineGap", "ascent", "descent")):
                    table = font.get_sfnt_table(table_name)
                    if table is None:
                        continue
                    scale = 1 / font.get_sfnt_table("head")["unitsPerEm"] * prop.get_size_in_points() * self.dpi / 72
                    hit = (table[ascent] * scale, -table[descent] * scale, table[gap] * scale)
                    break
                _HEIGHT_METRICS[key] = hit
            return hit

        methods["_get_font_height_metrics"] = _get_font_height_metrics

    if not methods:
        return RendererAgg
    return type("TmmRenderer", (RendererAgg,), {"__module__": __name__, **methods})


def _canvas_class(on: frozenset):
    import matplotlib
    import numpy as np
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    renderer_class = _renderer_class(on)
    share_fontsets = "shared_fontsets" in on

    class TmmCanvas(FigureCanvasAgg):
        """Agg, but an opaque figure goes to PNG as RGB by :func:`png_rgb` (a quarter less to
        encode than RGBA, and no row filters tried). Pixels are the same.

        Figures of one size share a renderer (drawing is one figure at a time in a process), and
        every renderer one mathtext parser: matplotlib caches text metrics per renderer and parsed
        formulas per parser, so a label, a tick value or a formula met before is not laid out again
        (the batch's figures repeat most of theirs)."""

        _tmm_key = None  # (width px, height px, dpi) of self.renderer

        def get_renderer(self):
            w, h = self.get_width_height(physical=True)
            key = (w, h, self.figure.dpi)
            if self._tmm_key != key:
                renderer = _RENDERERS.pop(key, None)
                if renderer is None:
                    renderer = renderer_class(w, h, self.figure.dpi)
                    if not _PARSERS:
                        parser = renderer.mathtext_parser
                        _PARSERS.append(_shared_fontsets(parser) if share_fontsets else parser)
                    renderer.mathtext_parser = _PARSERS[0]
                _RENDERERS[key] = renderer  # the most recently used last
                while len(_RENDERERS) > _RENDERERS_KEPT:
                    _RENDERERS.pop(next(iter(_RENDERERS)))
                self.renderer, self._tmm_key = renderer, key
            return self.renderer

        def print_png(self, filename_or_obj, *, metadata=None, pil_kwargs=None, **_):
            """An opaque figure as RGB by :func:`png_rgb`; anything transparent, or asked with
            Pillow's options, by matplotlib's own path."""
            FigureCanvasAgg.draw(self)
            rgba = np.asarray(self.buffer_rgba())
            if pil_kwargs or int(rgba[..., 3].min()) < 255:
                matplotlib.image.imsave(filename_or_obj, rgba, format="png", origin="upper", dpi=self.figure.dpi,
                                        metadata=metadata, pil_kwargs=pil_kwargs)
                return
            meta = {"Software": f"Matplotlib version{matplotlib.__version__}, https://matplotlib.org/", **(metadata or {})}
            data = png_rgb(rgba[..., :3], self.figure.dpi, {k: v for k, v in meta.items() if v is not None})
            if isinstance(filename_or_obj, (str, os.PathLike)):
                with open(filename_or_obj, "wb") as fh:
                    fh.write(data)
            else:
                filename_or_obj.write(data)

    return TmmCanvas


def _figure_class(on: frozenset):
    """matplotlib's Figure, whose Axes copy their ticks (:func:`copying_ticks`) if that hook is on."""
    from matplotlib.figure import Figure

    if "copied_ticks" not in on:
        return Figure

    class TmmFigure(Figure):
        def add_axes(self, *args, **kwargs):
            ax = super().add_axes(*args, **kwargs)
            copying_ticks(ax)
            return ax

        def add_subplot(self, *args, **kwargs):  # Figure.subplots comes here too
            ax = super().add_subplot(*args, **kwargs)
            copying_ticks(ax)
            return ax

    return TmmFigure


def png_rgb(rgb, dpi: float, text: dict | None = None, level: int = 3) -> bytes:
    """An 8-bit RGB image (numpy array h × w × 3) as a PNG file (ISO/IEC 15948): rows unfiltered,
    zlib at `level`, the resolution in pHYs, `text` as tEXt chunks (Latin-1).

    Why not Pillow: its PNG encoder tries the five row filters on every row, which is most of its
    time on a figure (≈ 20 ms each); a plot is mostly flat colour, which zlib packs as well unfiltered.
    Measured on the eight figures of variant 17: 0.07 s and 857 kB against Pillow's 0.17–0.21 s and
    930 kB at zlib level 1; the pixels are the same.

    >>> import io, numpy as np; from PIL import Image
    >>> img = np.arange(2 * 3 * 3, dtype=np.uint8).reshape(2, 3, 3)
    >>> back = Image.open(io.BytesIO(png_rgb(img, 120, {"Software": "tmm"})))
    >>> back.mode, back.size, bool((np.asarray(back) == img).all()), round(back.info["dpi"][0])
    ('RGB', (3, 2), True, 120)
    """
    import struct
    import zlib

    import numpy as np

    h, w = rgb.shape[:2]
    raw = np.empty((h, 3 * w + 1), np.uint8)  # each row: filter type 0 (none), then the pixels
    raw[:, 0] = 0
    pixels = raw[:, 1:].reshape(h, w, 3)
    for k in range(3):  # channel by channel: ~8x faster than one strided copy out of RGBA
        pixels[..., k] = rgb[..., k]

    def chunk(kind: bytes, body: bytes) -> bytes:
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)

    ppm = round(dpi / 0.0254)  # pixels per metre
    out = [b"\x89PNG\r\n\x1a\n", chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)),
           chunk(b"pHYs", struct.pack(">IIB", ppm, ppm, 1))]
    out += [chunk(b"tEXt", k.encode("latin-1") + b"\0" + v.encode("latin-1", "replace")) for k, v in (text or {}).items()]
    out += [chunk(b"IDAT", zlib.compress(raw, level)), chunk(b"IEND", b"")]
    return b"".join(out)


# --- mathtext's fontsets ----------------------------------------------------------------------------

def _shared_fontsets(parser):
    """`parser` (a MathTextParser), made to keep its fontsets: matplotlib makes a new one for every
    formula, and with it forgets the glyph metrics it looked up (a fontset caches them), so every
    character of every formula, the words around the symbols too, was looked up again. One fontset
    per font and hinting, kept for the parser's life, halves the time of a formula (14 → 6 ms for a
    legend entry); the figures come out pixel for pixel the same (compared). Only where Agg's
    formulas are paths (matplotlib ≥ 3.11): before, they were bitmaps drawn from glyph objects a
    shared font forgets (“glyph num is out of range”); :func:`_has_shared_fontsets` checks."""
    def keeping(make):
        made: dict = {}

        def fontset(prop, load_glyph_flags):
            key = (_font_key(prop), load_glyph_flags)
            if key not in made:
                made[key] = _sized_kerning(make(prop, load_glyph_flags))
            return made[key]

        return fontset

    parser._font_type_mapping = {name: keeping(make) for name, make in type(parser)._font_type_mapping.items()}
    return parser


def _sized_kerning(fontset):
    """`fontset`, its kerning read at the asked size. FreeType's kerning is that of the size the
    font object was last set to, and matplotlib sets it only when it looks a glyph up anew: with
    a fontset kept across formulas most glyphs are known already, so a pair was kerned at whatever
    size the font had last (a tick label's, another formula's) and a legend entry came out a pixel
    wider or narrower depending on the figures drawn before it. Setting the size first makes every
    formula the same whatever came before (a test draws one after others and alone)."""
    kern = fontset.get_kern

    def get_kern(font1, fontclass1, sym1, fontsize1, font2, fontclass2, sym2, fontsize2, dpi):
        if font1 == font2 and fontsize1 == fontsize2:
            fontset._get_info(font1, fontclass1, sym1, fontsize1, dpi).font.set_size(fontsize1, dpi)
        return kern(font1, fontclass1, sym1, fontsize1, font2, fontclass2, sym2, fontsize2, dpi)

    fontset.get_kern = get_kern
    return fontset


def _shaped(mtext) -> bool:
    """Whether a Text asks for font features or a language (matplotlib ≥ 3.11 only)."""
    return mtext is not None and any(getattr(mtext, get, lambda: None)() for get in ("get_fontfeatures", "get_language"))


def _font_key(prop) -> tuple:
    """What tells two FontProperties apart (the tuple matplotlib hashes them by)."""
    return (tuple(prop.get_family()), prop.get_slant(), prop.get_variant(), prop.get_weight(),
            prop.get_stretch(), prop.get_size(), prop.get_file(), prop.get_math_fontfamily())


# --- SVG copies ------------------------------------------------------------------------------------

def share_svg_text() -> None:
    """Every SVG renderer of this process lays its text out with one ``TextToPath`` and one table
    of text metrics, so the formulas parsed and the strings measured for one SVG copy serve the
    next (matplotlib gives each renderer its own, and its formula cache is keyed by the parser:
    a variant's ~30 formulas were parsed again for every SVG copy of the note, a quarter of the
    time of the copies; a tick label was measured again in every figure). The files are the same
    byte for byte. A forked child starts afresh (the parsed formulas hold FreeType fonts, which
    must never cross a fork). Only where the ``svg_text`` hook is in use."""
    if "svg_text" not in hooks():
        return
    from matplotlib.backends import backend_svg

    renderer = backend_svg.RendererSVG
    if "svg" in _STATE:
        return
    init = renderer.__init__
    _STATE["svg"] = (init, renderer.__dict__["get_text_width_height_descent"])

    def __init__(self, *args, **kwargs):
        init(self, *args, **kwargs)
        if _SVG_TEXT:
            self._text2path = _SVG_TEXT[0]
        else:
            _SVG_TEXT.append(self._text2path)

    def get_text_width_height_descent(self, s, prop, ismath):
        key = (s, _font_key(prop), ismath)
        got = _SVG_METRICS.get(key)
        if got is None:
            got = _SVG_METRICS[key] = self._text2path.get_text_width_height_descent(s, prop, ismath)
        return got

    renderer.__init__ = __init__
    renderer.get_text_width_height_descent = get_text_width_height_descent
    if not _STATE.get("svg_fork") and hasattr(os, "register_at_fork"):
        os.register_at_fork(after_in_child=_SVG_TEXT.clear)
        _STATE["svg_fork"] = True


def _unshare_svg_text() -> None:
    """matplotlib's own SVG renderer back (:func:`use` without ``svg_text``)."""
    own = _STATE.pop("svg", None)
    if own is not None:
        from matplotlib.backends import backend_svg

        backend_svg.RendererSVG.__init__, backend_svg.RendererSVG.get_text_width_height_descent = own
        _SVG_TEXT.clear()
        _SVG_METRICS.clear()


# --- ticks ------------------------------------------------------------------------------------------

_COPYING_AXIS: dict = {}  # matplotlib's XAxis / YAxis -> its subclass that copies ticks


def copying_ticks(*axes) -> None:
    """Make the x and y Axis of each of `axes` add a tick as a copy of its first one (where the
    ``copied_ticks`` hook is in use; otherwise nothing).

    matplotlib makes every further tick anew — five artists from rcParams, each Line2D copying a
    marker twice over with ``deepcopy`` — and then copies the first tick's properties onto it
    (``Axis._copy_tick_props``): ≈ 0.7 ms a tick, ≈ 160 ticks a variant (a tenth of a batch row's
    time). A copy of the first tick, with its own containers (callbacks, font properties, lists),
    is what that copying aims at, in ≈ 0.05 ms; its position and text are set at every draw, as
    for any tick. Child axes (a secondary axis) can be given here after they are made; an axis of
    another class (polar, 3D) is left as it is. Pixels are the same (compared on every figure).
    """
    if "copied_ticks" not in hooks():
        return
    for ax in axes:
        for axis in (ax.xaxis, ax.yaxis):
            cls = type(axis)
            copying = _COPYING_AXIS.get(cls)
            if copying is None:
                from matplotlib.axis import XAxis, YAxis

                if cls not in (XAxis, YAxis):
                    continue
                copying = _COPYING_AXIS[cls] = type(f"Copying{cls.__name__}", (_tick_copier(), cls), {"__module__": __name__})
            axis.__class__ = copying


_COPIER: list = []


def _tick_copier():
    """The mixin of :func:`copying_ticks` (made once, matplotlib imported then)."""
    if _COPIER:
        return _COPIER[0]
    import copy

    from matplotlib.cbook import CallbackRegistry

    def copied(artist):
        new = copy.copy(artist)
        new._callbacks = CallbackRegistry(signals=["pchanged"])
        new._path_effects = list(artist._path_effects)
        edges = artist.__dict__.get("_sticky_edges")
        if edges is not None:
            new._sticky_edges = type(edges)(list(edges.x), list(edges.y))
        if "_propobservers" in artist.__dict__:
            new._propobservers = {}
        if "_fontproperties" in artist.__dict__:
            new._fontproperties = artist._fontproperties.copy()
        for name in ("_xorig", "_yorig"):
            if isinstance(artist.__dict__.get(name), list):
                setattr(new, name, list(getattr(artist, name)))
        return new

    def copied_tick(first):
        tick = copied(first)
        for name in ("tick1line", "tick2line", "gridline", "label1", "label2"):
            setattr(tick, name, copied(getattr(first, name)))
        return tick

    class CopyingTicks:
        def get_major_ticks(self, numticks=None):
            if numticks is None:
                numticks = len(self.get_majorticklocs())
            ticks = self.majorTicks  # the first one made by matplotlib
            while len(ticks) < numticks:
                ticks.append(copied_tick(ticks[0]))
            return ticks[:numticks]

        def get_minor_ticks(self, numticks=None):
            if numticks is None:
                numticks = len(self.get_minorticklocs())
            ticks = self.minorTicks
            while len(ticks) < numticks:
                ticks.append(copied_tick(ticks[0]))
            return ticks[:numticks]

    _COPIER.append(CopyingTicks)
    return CopyingTicks
