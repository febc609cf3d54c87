"""What every figure of tmm shares: a fixed layout, cheap PNG encoding, book symbols with real
subscripts (matplotlib mathtext) and tick labels with the reader's decimal sign.

Why fixed layouts: the figures' contents never change their arrangement (a title of known lines,
axes, a legend of known rows), so the margins are set once from the figure size instead of
asking the constrained-layout engine, which draws every figure twice (half of the saving time).

matplotlib is imported inside the functions only, so importing this module stays cheap.
"""

from __future__ import annotations

import functools
import math
import os
import re
import sys

from ...i18n.numbers import num

PT = 1 / 72  # inch per point

# x_sub where x is one Latin or Greek letter and sub letters, digits or a prime: "i_пл", "z_c′",
# "φ_у", "ν_max", "l_OC", "φ_α1". Not inside a word ("phi_deg" stays as it is).
_SYMBOL = re.compile(r"(?<![A-Za-zА-Яа-яЁёα-ωΑ-Ω_\\$])([A-Za-zα-ωΑ-Ω])_([0-9A-Za-zА-Яа-яЁёα-ω′]+)")


def mt(text: str) -> str:
    """Book symbols of `text` as mathtext: a letter, then its subscript set upright and small.

    The subscript is ``x_\\text{k}`` (matplotlib ≥ 3.8): the same pixels as ``x_\\mathregular{k}``
    (compared), parsed in half the time — mathtext's grammar takes a braced group character by
    character, ``\\text`` reads it as one literal, and a legend entry or a title is parsed anew for
    every variant, its numbers being new. Older matplotlib gets ``x_\\mathregular{k}``.

    >>> mt("i_пл = n_д/n_кр").replace(_subscript_command(), "\\\\text")
    '$i_\\\\text{пл}$ = $n_\\\\text{д}$/$n_\\\\text{кр}$'
    >>> mt("r_0 = 48,9; z_12")
    '$r_0$ = 48,9; $z_{12}$'
    >>> mt("2z_c").replace(_subscript_command(), "\\\\text")
    '2$z_\\\\text{c}$'
    >>> mt("rise, max 31°")
    'rise, max 31°'
    """
    def sub(m) -> str:
        x, s = m.group(1), m.group(2)
        if s.isdigit():  # digits are upright in mathtext anyway: no font switch to parse
            return f"${x}_{s}$" if len(s) == 1 else f"${x}_{{{s}}}$"
        return f"${x}_{_subscript_command()}{{{s}}}$"

    return _SYMBOL.sub(sub, text)


@functools.cache
def _subscript_command() -> str:
    """``\\text`` where matplotlib's mathtext has it (3.8 and later), else ``\\mathregular``."""
    try:
        from importlib.metadata import version

        major, minor = (int(p) for p in version("matplotlib").split(".")[:2])
    except Exception:  # no metadata (a vendored matplotlib): the form every version reads
        return "\\mathregular"
    return "\\text" if (major, minor) >= (3, 8) else "\\mathregular"


def _canvas_class():
    import matplotlib
    import numpy as np
    from matplotlib.backends.backend_agg import FigureCanvasAgg, RendererAgg
    from matplotlib.mathtext import MathTextParser

    cached = getattr(MathTextParser._parse_cached, "__wrapped__", None)
    if cached is not None:  # one variant's ~30 formulas, the batch's repeated ones (matplotlib keeps 50)
        import functools

        MathTextParser._parse_cached = functools.lru_cache(_MATHTEXT_CACHE)(cached)
    parsers: list = []  # the first renderer's parser, given to every other one

    def forget_fonts() -> None:
        """In a forked child: drop the parser and its formulas, which hold the parent's FreeType
        fonts. A font object must never cross a fork (it reads its file through a descriptor the
        two processes share: interleaved reads give "FT_Load_Glyph … invalid outline");
        matplotlib drops its own font cache in the child for the same reason."""
        parsers.clear()
        _RENDERERS.clear()
        clear = getattr(MathTextParser._parse_cached, "cache_clear", None)
        if clear is not None:
            clear()

    if hasattr(os, "register_at_fork"):
        os.register_at_fork(after_in_child=forget_fonts)

    from matplotlib.backends.backend_agg import get_hinting_flag

    class TmmRenderer(RendererAgg):
        """Agg, but a plain (non-math) text is rendered as one bitmap and blitted at a whole pixel,
        as matplotlib did up to 3.10, and the bitmap is kept: a text met again (a tick value, an
        axis label, a legend entry; the batch repeats most of them) costs one blit.

        Why: matplotlib 3.11 lays the string out again and renders every glyph on its own at a
        sub-pixel place on every draw (≈ 0.1 ms a character, ≈ 0.3 s for a project's figures).
        The text lands within half a pixel of 3.11's place, as it always did before 3.11 (compared
        side by side: no visible difference). Formulas (mathtext) stay matplotlib's: drawn as one
        bitmap (its 'agg' output) their glyphs snap to whole pixels and a word can gape
        ("пособи ю"). A text with font features or a language set goes matplotlib's way too.
        """

        def draw_text(self, gc, x, y, s, prop, angle, ismath=False, mtext=None):
            if ismath or _shaped(mtext):
                return super().draw_text(gc, x, y, s, prop, angle, ismath=ismath, mtext=mtext)
            image, descent, xo, yo, _ = self._bitmap(s, prop, bool(gc.get_antialiased()))
            # the descent turned with the text (matplotlib 3.10's draw_text)
            x = round(x + xo + descent * math.sin(math.radians(angle)))
            y = round(y + yo + descent * math.cos(math.radians(angle)))
            self._renderer.draw_text_image(image, x, y + 1, angle, gc)

        def get_text_width_height_descent(self, s, prop, ismath):
            """matplotlib's, but a plain text is rendered as it is measured and the bitmap kept for
            :meth:`draw_text`: laying a string out (``FT2Font.set_text``, ≈ 0.05 ms a character
            under matplotlib 3.11) was done twice for every new text, once to measure, once to draw."""
            if ismath or not isinstance(s, str):
                return super().get_text_width_height_descent(s, prop, ismath)
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
                super()._draw_text_glyphs_and_boxes(gc, x, y, angle, (), boxes)

        def _get_font_height_metrics(self, prop):
            """(ascent, descent, line gap) [px] of the font of `prop` at this renderer's dpi, as
            matplotlib ≥ 3.11 computes them in ``Text._get_layout`` from the font's OS/2 (or hhea)
            table — the same numbers, kept: it looked the font up and read two tables again for
            every layout of every text (≈ 5 % of a figure's saving time). matplotlib < 3.11 never
            asks."""
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

    class TmmCanvas(FigureCanvasAgg):
        """Agg, but an opaque figure goes to PNG as RGB by :func:`png_rgb` (a quarter less to
        encode than RGBA, and no row filters tried). Pixels are the same.

        Figures of one size share a renderer (drawing is one figure at a time in a process), and
        every renderer one mathtext parser: matplotlib caches text metrics per renderer and parsed
        formulas per parser, so a label, a tick value or a formula met before is not laid out again
        (the batch's figures repeat most of theirs)."""

        def get_renderer(self):
            w, h = self.get_width_height(physical=True)
            key = (w, h, self.figure.dpi)
            if self._lastKey != key:
                renderer = _RENDERERS.pop(key, None)
                if renderer is None:
                    renderer = TmmRenderer(w, h, self.figure.dpi)
                    if not parsers:
                        parsers.append(_shared_fontsets(renderer.mathtext_parser))
                    renderer.mathtext_parser = parsers[0]
                _RENDERERS[key] = renderer  # the most recently used last
                while len(_RENDERERS) > _RENDERERS_KEPT:
                    _RENDERERS.pop(next(iter(_RENDERERS)))
                self.renderer, self._lastKey = renderer, key
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
            with matplotlib.cbook.open_file_cm(filename_or_obj, "wb") as fh:
                fh.write(data)

    return TmmCanvas


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


_CLASS = []
_RENDERERS: dict = {}  # (width px, height px, dpi) -> a RendererAgg shared by the figures of that size
_RENDERERS_KEPT = 8  # 2–9 MB each; the eight figures of a project come in at most eight sizes
_MATHTEXT_CACHE = 512  # parsed formulas kept (matplotlib's default is 50)
_TEXT_BITMAPS: dict = {}  # (text, font, hinting, antialiased, dpi) -> its bitmap, descent, offsets
_TEXT_BITMAPS_KEPT = 4096  # small grey images (a label is a few kB)
_GLYPHS: dict = {}  # (font, size, dpi, glyph, flags, antialiased, turn, 1/64 px fractions) -> bitmap, left, top
_GLYPHS_KEPT = 50_000  # a glyph's bitmap is ≈ 100 bytes; a batch meets ≈ 8 000 keys
_GLYPH_MATRICES: dict = {}  # (angle, slant, extend) -> FreeType's 16.16 transform
_HEIGHT_METRICS: dict = {}  # (font, dpi) -> (ascent, descent, line gap) [px]: a few fonts and sizes


def _shared_fontsets(parser):
    """`parser` (a MathTextParser), made to keep its fontsets: matplotlib makes a new one for every
    formula, and with it forgets the glyph metrics it looked up (a fontset caches them), so every
    character of every formula, the words around the symbols too, was looked up again. One fontset
    per font and hinting, kept for the parser's life, halves the time of a formula (14 → 6 ms for a
    legend entry); the figures come out pixel for pixel the same (compared)."""
    def keeping(make):
        made: dict = {}

        def fontset(prop, load_glyph_flags):
            key = (_font_key(prop), load_glyph_flags)
            if key not in made:
                made[key] = _sized_kerning(make(prop, load_glyph_flags))
            return made[key]

        return fontset

    if getattr(parser, "_output_type", None) != "vector":  # matplotlib < 3.11: Agg's formulas are bitmaps,
        return parser  # drawn from glyph objects a shared font forgets (“glyph num is out of range”)
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


def new_figure(width_in: float, height_in: float):
    """An empty figure of the given size with no layout engine (the caller places the axes)."""
    if not _CLASS:
        _CLASS.extend((_figure_class(), _canvas_class()))
    fig = _CLASS[0](figsize=(width_in, height_in), layout="none")
    _CLASS[1](fig)
    return fig


def title_height(lines: int, fontsize: float = 12.0, pad_pt: float = 8.0) -> float:
    """Height [inch] of a title of `lines` lines at `fontsize` points, with its padding."""
    return (lines * fontsize * 1.25 + pad_pt) * PT


def legend_height(entries: int, ncol: int, fontsize: float = 8.0) -> float:
    """Height [inch] of a frameless legend of `entries` in `ncol` columns at `fontsize`."""
    rows = max(1, math.ceil(entries / ncol))
    return (rows * fontsize * 1.75 + 6.0) * PT


def bottom_legend(fig, handles, labels, ncol: int, fontsize: float = 8.0) -> None:
    """The legend in one frameless block centred at the bottom edge of the figure."""
    fig.legend(handles, labels, loc="lower center", bbox_to_anchor=(0.5, 0.003), ncol=ncol, fontsize=fontsize,
               frameon=False)


def suptitle(fig, text: str, fontsize: float = 12.0) -> None:
    """The figure title at the top edge (fixed place: no layout engine moves it)."""
    fig.suptitle(text, y=1.0 - 4 * PT / fig.get_figheight(), va="top", fontsize=fontsize)


def decimal_commas(fig, lang: str) -> None:
    """Tick labels with a decimal comma under ru (every axis of `fig`, secondary axes too)."""
    if lang != "ru":
        return
    from matplotlib.ticker import ScalarFormatter

    class CommaFormatter(ScalarFormatter):
        def __call__(self, x, pos=None):
            return super().__call__(x, pos).replace(".", ",")

        def get_offset(self):
            return super().get_offset().replace(".", ",")

    def axes_of(ax):
        yield ax
        for child in getattr(ax, "child_axes", ()):
            yield from axes_of(child)

    for top in fig.axes:
        for ax in axes_of(top):
            for axis in (ax.xaxis, ax.yaxis):
                if type(axis.get_major_formatter()) is ScalarFormatter:
                    axis.set_major_formatter(CommaFormatter())


def fmt(lang: str):
    """``f(x, **kw) = num(x, lang, **kw)``: numbers in figure texts as the reader writes them."""
    return lambda x, **kw: num(x, lang, **kw)


def _warm_up() -> None:
    """Build what both processes need once, before the fork: mathtext's grammar (~0.2 s, kept on
    the parser class) and the DejaVu fonts (regular, bold, oblique)."""
    import io

    fig = new_figure(1, 1)
    fig.text(0.1, 0.5, mt("x_пл"), fontsize=10)
    fig.text(0.1, 0.2, "x", fontsize=10, weight="bold")
    fig.savefig(io.BytesIO(), format="png", dpi=10)


_SVG_TEXT: list = []  # the one TextToPath of every SVG renderer in this process (see share_svg_text)
_SVG_METRICS: dict = {}  # (text, font properties, ismath) -> (width, height, descent) in SVG points


def share_svg_text() -> None:
    """Every SVG renderer of this process lays its text out with one ``TextToPath`` and one table
    of text metrics, so the formulas parsed and the strings measured for one SVG copy serve the
    next (matplotlib gives each renderer its own, and its formula cache is keyed by the parser:
    a variant's ~30 formulas were parsed again for every SVG copy of the note, a quarter of the
    time of the copies; a tick label was measured again in every figure). The files are the same
    byte for byte. A forked child starts afresh (the parsed formulas hold FreeType fonts, which
    must never cross a fork; see forget_fonts)."""
    from matplotlib.backends import backend_svg

    renderer = backend_svg.RendererSVG
    if getattr(renderer, "_tmm_shared_text", False):
        return
    init = renderer.__init__

    def __init__(self, *args, **kwargs):
        init(self, *args, **kwargs)
        if _SVG_TEXT:
            self._text2path = _SVG_TEXT[0]
        else:
            _SVG_TEXT.append(self._text2path)

    def get_text_width_height_descent(self, s, prop, ismath):
        key = (s, tuple(prop.__dict__.values()), ismath)
        got = _SVG_METRICS.get(key)
        if got is None:
            got = _SVG_METRICS[key] = self._text2path.get_text_width_height_descent(s, prop, ismath)
        return got

    renderer.__init__ = __init__
    renderer.get_text_width_height_descent = get_text_width_height_descent
    renderer._tmm_shared_text = True
    if hasattr(os, "register_at_fork"):
        os.register_at_fork(after_in_child=_SVG_TEXT.clear)


_FORKED = False  # set in a child forked here: it never forks again (two cores are busy already)


def can_fork() -> bool:
    """Whether work may be spread over a forked child process (Linux, more than one core, and not
    inside such a child already)."""
    return sys.platform.startswith("linux") and (os.cpu_count() or 1) > 1 and hasattr(os, "fork") and not _FORKED


class SharedWork:
    """Tasks shared by this process and a forked child, each run once, whoever is free first.

    `shared` tasks (largest first) go into a queue both processes take from; `child_first` tasks
    the child runs before it takes from the queue (the sheets, which no report waits for). This
    process takes its part with :meth:`run_here`; :meth:`wait_shared` returns once every shared
    task is done, :meth:`wait` once everything is. A task the child took but did not finish (it
    failed, or was killed) is run here instead, so the files come out the same and an error
    surfaces here as usual. :meth:`abort` kills the child at once (SIGKILL) and reaps it: the child
    writes only into the caller's staging folder, which the caller removes. Used as a context
    manager, an exception in the body aborts; a normal exit waits for everything.

    The queue is a pipe holding one byte per task (a read of one byte is atomic); the child
    reports each finished task through a second pipe and leaves with ``os._exit``, so it runs
    none of this process's ``finally`` blocks or exit handlers. Without fork (other systems, one
    core, ``fork=False``) everything runs here, in order.
    """

    def __init__(self, shared=(), child_first=(), fork: bool = True):
        self.tasks = list(shared) + list(child_first)
        self.n_shared = len(shared)
        if len(self.tasks) > 255:
            raise ValueError("at most 255 tasks")
        self.done: set[int] = set()
        self.pid = self._r = self._q = None
        self._buf = b""
        if not (fork and self.tasks and can_fork()):
            return
        q_r, q_w = os.pipe()
        os.write(q_w, bytes(range(self.n_shared)))
        os.close(q_w)
        r, w = os.pipe()
        sys.stdout.flush()
        sys.stderr.flush()
        pid = os.fork()
        if pid == 0:  # the child
            global _FORKED
            _FORKED = True
            code = 1
            try:
                os.close(r)
                for i in range(self.n_shared, len(self.tasks)):
                    self.tasks[i]()
                    os.write(w, bytes([i]))
                while True:
                    got = os.read(q_r, 1)
                    if not got:
                        break
                    self.tasks[got[0]]()
                    os.write(w, got)
                code = 0
            finally:
                os._exit(code)
        os.close(w)
        self.pid, self._r, self._q = pid, r, q_r

    def run_here(self) -> None:
        """Take shared tasks from the queue and run them here until it is empty."""
        if self._q is None:
            for i in range(self.n_shared):
                if i not in self.done:
                    self.tasks[i]()
                    self.done.add(i)
            return
        while True:
            got = os.read(self._q, 1)
            if not got:
                break
            self.tasks[got[0]]()
            self.done.add(got[0])

    def _read_until(self, needed) -> None:
        """Read the child's reports until `needed` are done or the child is gone."""
        while self._r is not None and not needed <= self.done:
            data = os.read(self._r, 64)
            if not data:  # the child has left (finished or failed)
                self._reap()
                return
            self.done.update(data)

    def _reap(self) -> None:
        for fd in (self._r, self._q):
            if fd is not None:
                os.close(fd)
        self._r = self._q = None
        if self.pid is not None:
            os.waitpid(self.pid, 0)
            self.pid = None

    def _finish(self, needed) -> None:
        self.run_here()
        self._read_until(needed)
        for i in sorted(needed - self.done):  # the child left without them: run them here
            self.tasks[i]()
            self.done.add(i)

    def run_until(self, needed) -> None:
        """Take shared tasks here until every task of `needed` is done (by either process): what
        waits for some tasks only (the note's figures) can start while the rest are drawn."""
        needed = set(needed)
        if self._q is None:
            for i in sorted(needed - self.done):
                self.tasks[i]()
                self.done.add(i)
            return
        import select

        while not needed <= self.done:
            while self._r is not None and select.select([self._r], [], [], 0)[0]:
                data = os.read(self._r, 64)
                if not data:
                    self._reap()
                    break
                self.done.update(data)
            if needed <= self.done or self._q is None:
                break
            got = os.read(self._q, 1)
            if not got:  # the queue is empty: the rest is the child's, wait for it
                self._read_until(needed)
                break
            self.tasks[got[0]]()
            self.done.add(got[0])
        for i in sorted(needed - self.done):  # the child left without them: run them here
            self.tasks[i]()
            self.done.add(i)

    def wait_shared(self) -> None:
        """Every shared task done (this process takes what is left in the queue first)."""
        self._finish(set(range(self.n_shared)))

    def wait(self) -> None:
        """Everything done and the child reaped."""
        self._finish(set(range(len(self.tasks))))
        if self._r is not None:
            self._read_until(set(range(len(self.tasks) + 1)))  # to the end of the pipe: the child left

    def abort(self) -> None:
        if self.pid is not None:
            try:
                os.kill(self.pid, 9)
            except ProcessLookupError:
                pass
        self._reap()

    def __enter__(self):
        return self

    def __exit__(self, exc_type, exc, tb):
        if exc_type is None:
            try:
                self.wait()
            except BaseException:  # a signal while waiting for the child: it must not outlive this
                self.abort()
                raise
        else:
            self.abort()
        return False


def bare_xaxis(ax, ticks, grid_alpha: float | None = None) -> None:
    """The x axis of `ax` drawn as its grid lines and bottom tick marks at `ticks` only, for the
    upper panels of stacked axes whose x tick labels show on the bottom panel alone.

    Two Line2Ds (the grid lines joined by NaN gaps, the tick marks as one marker line) instead of a
    Tick per position, each of five artists created and laid out at every save: the same pixels
    (the same colours, widths, transforms and drawing order as matplotlib's own) at a fraction of
    the cost. The Axis itself is hidden, so nothing of it is created or drawn.
    """
    import matplotlib as mpl
    import numpy as np
    from matplotlib.lines import TICKDOWN, TICKUP, Line2D

    rc = mpl.rcParams

    def rc_or(key, fallback):
        value = rc.get(key)
        return rc[fallback] if value is None else value

    xs = np.asarray(ticks, dtype=float)
    zorder = ax.xaxis.get_zorder()  # the Axis draws its ticks at its own zorder
    ax.xaxis.set_visible(False)
    gx = np.repeat(xs, 3)
    gx[2::3] = np.nan
    gy = np.tile([0.0, 1.0, np.nan], len(xs))
    alpha = rc_or("grid.major.alpha", "grid.alpha") if grid_alpha is None else grid_alpha
    grid = Line2D(gx, gy, color=rc_or("grid.major.color", "grid.color"), alpha=alpha,
                  linestyle=rc_or("grid.major.linestyle", "grid.linestyle"),
                  linewidth=rc_or("grid.major.linewidth", "grid.linewidth"), marker="", zorder=zorder,
                  transform=ax.get_xaxis_transform("grid"))
    ax.add_artist(grid)  # clipped to the axes patch, like a grid line; the data limits stay
    color = rc["xtick.color"]
    marker = {"out": TICKDOWN, "in": TICKUP, "inout": "|"}[rc["xtick.direction"]]
    marks = Line2D(xs, np.zeros_like(xs), color=color, linestyle="none", marker=marker, markeredgecolor=color,
                   markersize=rc["xtick.major.size"], markeredgewidth=rc["xtick.major.width"], zorder=zorder,
                   transform=ax.get_xaxis_transform("tick1"), clip_on=False)
    ax.add_artist(marks)
    marks.set_clip_path(None)
    marks.set_clip_on(False)


def hide_axis(*axes_axis) -> None:
    """Axes' x or y Axis objects with no ticks and no label, hidden: nothing of them is made or
    drawn (``set_xticks([])`` still makes a major and a minor Tick, five artists each, and lays
    them out at every save). The spines stay."""
    from matplotlib.ticker import NullLocator

    for axis in axes_axis:
        axis.set_major_locator(NullLocator())
        axis.set_visible(False)


def _figure_class():
    """matplotlib's Figure whose Axes copy their ticks (:func:`copying_ticks`)."""
    from matplotlib.figure import Figure

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


_COPYING_AXIS: dict = {}  # matplotlib's XAxis / YAxis -> its subclass that copies ticks


def copying_ticks(*axes) -> None:
    """Make the x and y Axis of each of `axes` add a tick as a copy of its first one.

    matplotlib makes every further tick anew — five artists from rcParams, each Line2D copying a
    marker twice over with ``deepcopy`` — and then copies the first tick's properties onto it
    (``Axis._copy_tick_props``): ≈ 0.7 ms a tick, ≈ 160 ticks a variant (a tenth of a batch row's
    time). A copy of the first tick, with its own containers (callbacks, font properties, lists),
    is what that copying aims at, in ≈ 0.05 ms; its position and text are set at every draw, as
    for any tick. Child axes (a secondary axis) can be given here after they are made; an axis of
    another class (polar, 3D) is left as it is. Pixels are the same (compared on every figure).
    """
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


_COPIER = []


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
