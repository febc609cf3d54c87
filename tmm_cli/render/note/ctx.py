"""What every chapter builder needs: the result, the language, numbers as the note prints them,
formulas whose substitutions reproduce their results, the «где» of each new symbol, figures.

Numbers: decimal comma under ru, the typographic minus, a no-break space between a number and its
unit, a narrow no-break space between thousands. Inside typst math a number with a comma is a
string (``"0,875"``), so that typst sets no space after the comma.
"""

from __future__ import annotations

import math

from dataclasses import dataclass, field

from ...i18n import ntr, tr, trc
from ...i18n.numbers import num
from .mathsyntax import check_line, parse, top_level_splits, width
from .model import Document, Figure, Formula, Paragraph, Table, WhereItem

NBSP = "\u00a0"
NNBSP = "\u202f"  # narrow no-break space: thousands (12 345)


@dataclass
class V:
    """A number to print in a substitution: the exact value and its format (``sig`` significant
    digits or ``decimals``); ``exact`` numbers (counts, given data) print as they are; ``deg``
    appends °. :meth:`Ctx.calc` adds digits to the leaves until the substitution reproduces the
    printed result."""

    x: float
    sig: int | None = None
    decimals: int | None = None
    exact: bool = False
    deg: bool = False


@dataclass
class Ctx:
    r: object  # ProjectResult
    lang: str
    figures: dict = field(default_factory=dict)  # name -> (svg file, png file or None, width cm, height cm)
    doc: Document = None  # type: ignore[assignment]
    explained: set = field(default_factory=set)  # symbols already explained in a «где»
    glossary: dict = field(default_factory=dict)  # symbol -> its meaning (an English msgid)
    off: list = field(default_factory=list)  # substitutions that could not be made to reproduce
    _scales: dict | None = None  # the scale of each kind of number (:func:`scales`), found when first asked

    def __post_init__(self):
        if self.doc is None:
            self.doc = Document(self.lang)

    # -- words -------------------------------------------------------------------------------------
    def t(self, msgid: str) -> str:
        """`msgid` (English) in the note's language, from the catalogue."""
        return tr(self.lang, msgid)

    def tc(self, context: str, msgid: str) -> str:
        """`msgid` in the note's language where the note words it otherwise than the rest of tmm
        (msgctxt `context`: "Student" on the title page is «Автор работы», not «Студент»)."""
        return trc(self.lang, context, msgid)

    def nt(self, singular: str, plural: str, n: int) -> str:
        """The form of `singular`/`plural` for the count `n` (the catalogue's plural forms)."""
        return ntr(self.lang, singular, plural, n)

    # -- numbers -----------------------------------------------------------------------------------
    def zero(self, x, kind: str) -> float:
        """`x`, or 0 where it is zero to the problem's precision: below :data:`ZERO` of the scale of
        its kind (:func:`scales`: v_A for a velocity, the largest force for a force, …) it is the
        computer's rounding (3,8·10⁻¹⁷ m/s of a block at rest in its slot), not a value."""
        if self._scales is None:
            self._scales = scales(self.r)
        scale = self._scales.get(kind)
        x = float(x)
        return 0.0 if scale is not None and abs(x) <= ZERO * scale else x

    def nz(self, x, kind: str, **kw) -> str:
        """:meth:`n` of :meth:`zero`: a number of the kind `kind` ("m/s", "N", …) for the text."""
        return self.n(self.zero(x, kind), **kw)

    def nf(self, x, kind: str = "N") -> str:
        """A force (`kind` "N") or a moment ("N·m") for a table or a list: one decimal from 10 up,
        three significant digits below it in decimals (0,00228, not 0,00 nor 2,28·10⁻³), 0 where
        it is zero (:meth:`zero`)."""
        x = self.zero(x, kind)
        if x == 0.0:
            return "0"
        return self.n(x, decimals=1) if abs(x) >= 10.0 else self.n(x, sig=3, sci=False)

    def n(self, x, **kw) -> str:
        """A number for the text: decimal comma (ru), typographic minus, narrow space in thousands."""
        text = num(x, self.lang, minus="−", **kw)
        return group_thousands(text, self.lang)

    def q(self, x, **kw) -> str:
        """A number inside typst math (a string when it holds more than digits)."""
        return mq(self.n(x, **kw))

    def qd(self, x, **kw) -> str:
        """An angle in degrees inside typst math."""
        return '"' + self.n(x, **kw) + '°"'

    def qty(self, x, unit: str, **kw) -> str:
        """"48,86 мм" with a no-break space (text)."""
        return self.n(x, **kw) + NBSP + unit

    def pct(self, x, decimals: int = 2, sign: bool = False) -> str:
        text = self.n(x, decimals=decimals)
        if sign and x > 0 and text.strip("0,.") != "":
            text = "+" + text
        return text + NBSP + "%"

    def pct_digits(self, x) -> str:
        """A small difference in % to the digits it has: two significant digits (0,0042 %), not 0,00 %;
        below 10⁻⁹ % (a computer's rounding) «less than 10⁻⁹ %»."""
        a = abs(float(x))
        if a >= 0.1:
            return self.pct(x, decimals=2)
        if a < 1e-9:
            return self.t("less than {v}").format(v="$10^(-9)$" + NBSP + "%")
        return self.pct(x, decimals=1 - math.floor(math.log10(a)))

    @staticmethod
    def u(unit: str) -> str:
        """A unit after a value inside typst math."""
        return 'thin "' + unit + '"'

    def leaf(self, v: V, extra: int = 0) -> str:
        if isinstance(v, (int, str)):
            return mq(str(v)) if isinstance(v, str) else mq(self.n(v))
        if v.exact:
            # given data print as given: up to 9 significant digits (a synthesised 0,0646537 m is not 0,06465)
            text = self.n(v.x, sig=9) if v.sig is None and v.decimals is None else self.n(v.x, sig=v.sig or 4,
                                                                                             decimals=v.decimals)
        elif v.decimals is not None:
            text = self.n(v.x, decimals=v.decimals + extra)
        else:
            text = self.n(v.x, sig=(v.sig or 4) + extra)
        if v.deg:
            text += "°"
        return mq(text)

    # -- formulas ----------------------------------------------------------------------------------
    def calc(self, lhs: str, sub: str | None, vals=(), result: V | None = None, unit: str | None = None) -> str:
        """``lhs = sub = result unit`` as typst math, the leaves of `sub` ({0}, {1}, …) printed with
        as many digits as it takes for the substitution to give the printed result (to its last
        digit). `lhs` may hold ``=`` itself (symbol = formula)."""
        res = self.leaf(result) if result is not None else None
        tail = (" = " + res if res is not None else "") + (" " + self.u(unit) if unit else "")
        if sub is None:
            return lhs + tail
        line = ""
        for extra in range(0, 5):
            line = lhs + " = " + sub.format(*(self.leaf(v, extra) for v in vals)) + tail
            if all(c.ok for c in check_line(line)):
                return line
        self.off.append(line)
        return line

    def formula(self, *pieces: str, label: str | None = None, numbered: bool = True, where=()) -> Formula:
        """A display formula of one or more pieces (joined by ``; quad``), with the «где» of the
        symbols in `where` not yet explained in the note."""
        math = fit_lines(list(pieces))
        parse(math)  # a formula the writers cannot read never reaches the document
        items = []
        for sym in where:
            if isinstance(sym, tuple):
                sym, meaning = sym
            else:
                meaning = self.glossary_text(sym)
            if sym in self.explained:
                continue
            self.explained.add(sym)
            items.append(WhereItem(sym, meaning))
        return self.doc.add(Formula(math, label=label, numbered=numbered, where=items))

    def glossary_text(self, sym: str) -> str:
        return self.t(self.glossary[sym])

    def p(self, text: str, indent: bool = True) -> Paragraph:
        return self.doc.add(Paragraph(text, indent))

    def table(self, name: str, caption: str, header: list[str], rows: list[list[str]], align=None, widths=None) -> Table:
        return self.doc.add(Table(name, caption, header, rows, align, widths))

    # -- figures ---------------------------------------------------------------------------------
    def fig(self, name: str, caption: str) -> bool:
        """Embed the note's figure `name` if it was drawn (``--no-plots`` draws none)."""
        spec = self.figures.get(name)
        if not spec:
            return False
        svg, png, w, h = spec
        self.doc.add(Figure(name, svg, caption, w, h, png))
        return True

    def has(self, name: str) -> bool:
        return name in self.figures

    def if_fig(self, name: str, text: str) -> str:
        """`text` (which refers to figure `name`) if the figure is drawn, else nothing."""
        return text if name in self.figures else ""

    def planets(self, k: int) -> str:
        """"4 сателлита" / "4 planets"."""
        return self.nt("{k} planet", "{k} planets", k).format(k=k)


ZERO = 1e-9  # a number below this share of the scale of its kind prints as 0 (:meth:`Ctx.zero`)


def scales(r) -> dict[str, float]:
    """The scale of each kind of number of the lever mechanism's chapters, keyed by its unit: the
    crank pin's velocity ω₁l₁ and acceleration ω₁²l₁, ω₁ and ω₁², the largest applied force of
    the cycle and that force on the crank's arm (or the largest couple). Nothing without a mechanism.

    >>> from types import SimpleNamespace as NS
    >>> import numpy as np
    >>> crank = NS(omega=-10.0, length=0.1)
    >>> s1 = NS(mechanism=NS(crank=crank))
    >>> s2 = NS(sheet1=s1, loading=NS(forces=[NS(f=np.array([3 + 4j, 1]))], couples=[NS(m=np.array([2.0]))]))
    >>> sorted(scales(NS(linkage=s2)).items())
    [('N', 5.0), ('N·m', 2.0), ('m/s', 1.0), ('m/s²', 10.0), ('rad/s', 10.0), ('rad/s²', 100.0)]
    """
    import numpy as np

    s1 = sheet1_of(r)
    if s1 is None:
        return {}
    cr = s1.mechanism.crank
    w, l1 = abs(float(cr.omega)), float(cr.length)
    out = {"m/s": w * l1, "m/s²": w * w * l1, "rad/s": w, "rad/s²": w * w}
    loading = getattr(getattr(r, "linkage", None), "loading", None)
    if loading is not None:
        f = max((float(np.max(np.abs(np.asarray(x.f)))) for x in loading.forces), default=0.0)
        m = max((float(np.max(np.abs(np.asarray(x.m)))) for x in loading.couples), default=0.0)
        out["N"] = f
        out["N·m"] = max(f * l1, m)
    return out


LINE_EM = 30.0  # the width of a display formula line in :func:`width`'s em: 16,5 cm (33 em) less the number «(NN)» and a gap, and the rough estimate's error


def fit_lines(pieces: list[str], limit: float = LINE_EM) -> str:
    """Pieces joined by "; quad" on one line while they fit, else on lines of their own (typst
    ``\\``); a piece too wide by itself breaks before an "=" of its own.

    >>> fit_lines(["a = b", "c = d"])
    'a = b; quad c = d'
    """
    def w(src: str) -> float:
        return width(parse(src))

    out: list[str] = []
    for piece in pieces:
        for part in _split_piece(piece, limit, w):
            if out and w(out[-1] + "; quad " + part) <= limit:
                out[-1] = out[-1] + "; quad " + part
            else:
                out.append(part)
    return " \\ ".join(out)


def _split_piece(piece: str, limit: float, w) -> list[str]:
    if w(piece) <= limit:
        return [piece]
    cuts = top_level_splits(piece)
    lines, start = [], 0
    for k, pos in enumerate(cuts):
        nxt = cuts[k + 1] if k + 1 < len(cuts) else len(piece)
        if w(piece[start:nxt]) > limit and pos > start:
            lines.append(piece[start:pos])
            start = pos + 1  # the next line starts with "= …"
    lines.append(piece[start:])
    return lines


def mq(text: str) -> str:
    """A printed number inside typst math: bare digits stay, anything else is a string."""
    return text if text.isdigit() else '"' + text + '"'


def group_thousands(text: str, lang: str) -> str:
    """12345,7 → 12 345,7 (narrow no-break space, ГОСТ) for numbers of five digits and more.

    >>> group_thousands("12345,7", "ru"), group_thousands("1234,5", "ru"), group_thousands("−400000", "ru")
    ('12\\u202f345,7', '1234,5', '−400\\u202f000')
    """
    if lang != "ru":
        return text
    sign = text[0] if text[:1] in "−-+" else ""
    body = text[len(sign):]
    whole, sep, frac = body.partition(",")
    if not whole.isdigit() or len(whole) < 5:
        return text
    groups = []
    while whole:
        groups.insert(0, whole[-3:])
        whole = whole[:-3]
    return sign + NNBSP.join(groups) + sep + frac


def sheet1_of(r):
    """Sheet 1 of the project's result, or None (no mechanism file)."""
    linkage = getattr(r, "linkage", None)
    if linkage is None:
        return None
    return getattr(linkage, "sheet1", linkage)
