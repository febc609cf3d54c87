"""Word equations (Office Math Markup, OMML) from the note's formula tree (:mod:`.mathsyntax`).

Why not LaTeX → MathML → OMML (latex2mathml + mathml2omml): the formulas are written once, in the
typst subset the typst note compiles, and parsed into a small tree anyway (for the check of every
substitution); emitting OMML from that tree is a few dozen lines, needs no second notation and no
two more packages, and the tests read every formula of all 68 notes through the same parser.

The elements are built as lxml elements in the ``m:`` namespace (python-docx's lxml).
"""

from __future__ import annotations

import re

from .mathsyntax import RELATIONS, Attach, Break, Frac, Func, Group, Seq, Sym, parse
from .model import SUPER_DIGITS

M = "http://schemas.openxmlformats.org/officeDocument/2006/math"
W = "http://schemas.openxmlformats.org/wordprocessingml/2006/main"
XML_SPACE = "{http://www.w3.org/XML/1998/namespace}space"
FONT = "Cambria Math"


_TAGS: dict = {}
_ETREE: list = []


def _qn(tag: str) -> str:
    q = _TAGS.get(tag)
    if q is None:
        ns, name = tag.split(":", 1)
        q = _TAGS[tag] = f"{{{M if ns == 'm' else W}}}{name}"
    return q


def _el(tag: str, *children, **attrs):
    if not _ETREE:
        from lxml import etree

        _ETREE.append(etree.Element)
    e = _ETREE[0](_qn(tag))
    for k, v in attrs.items():
        e.set(_qn(k.replace("_", ":", 1)), v)
    for c in children:
        if c is not None:
            e.append(c)
    return e


# a number's power of ten, "1,458·10⁻⁴" (model.SCI_EXPONENT), as a true superscript
SCI = re.compile(r"(.*?)·10([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)(.*)")


def _run(text: str, upright: bool = False, bold: bool = False, op: bool = False):
    """One m:r. Upright text (numbers, words, units, function names) is "normal text" (m:nor): Word
    sets it upright in the text's face, and LibreOffice, which ignores m:sty, reads it as quoted
    text (upright) — with m:sty alone «при» and «мм» came out italic there. Operators keep the math
    run (LibreOffice must see "=" as a relation). The size is the text's (w:sz, half points): Word
    takes it; LibreOffice sets every formula at its own Math base size (12 pt by default)."""
    rpr = []
    if bold:
        rpr.append(_el("m:rPr", _el("m:sty", m_val="b")))
    elif op:
        rpr.append(_el("m:rPr", _el("m:sty", m_val="p")))
    elif upright:
        rpr.append(_el("m:rPr", _el("m:nor")))
    wr = _el("w:rPr", _el("w:rFonts", w_ascii=FONT, w_hAnsi=FONT, w_cs=FONT), _el("w:sz", w_val=_SIZE[0]),
             _el("w:szCs", w_val=_SIZE[0]))
    t = _el("m:t")
    t.text = text
    t.set(XML_SPACE, "preserve")
    return _el("m:r", *rpr, wr, t)


_SIZE = ["28"]  # half points of the formula being written (14 pt; 12 pt in a table)
_LINEAR = [False]  # fractions on the line (a/b) instead of stacked: in a table's cells


def _elements(node) -> list:
    """The OMML elements (children of an m:oMath or m:e) for a node of the tree."""
    if node is None:
        return []
    if isinstance(node, Seq):
        out = []
        for x in node.items:
            out += _elements(x)
        return out
    if isinstance(node, Sym):
        if node.kind == "space":
            return [_run(node.text, upright=True)]
        if node.kind == "var":
            return [_run(node.text)]
        if node.kind == "fn":
            return [_run(node.text + " ", upright=True)]
        if node.kind == "op":
            return [_run(node.text, op=True)]
        m = SCI.fullmatch(node.text)
        if m:  # "1,458·10⁻⁴": the power of ten as a true superscript
            return [_run(m[1] + "·", upright=True),
                    _el("m:sSup", _el("m:e", _run("10", upright=True)),
                        _el("m:sup", _run(m[2].translate(SUPER_DIGITS), upright=True))), _run(m[3], upright=True) if m[3] else None]
        return [_run(node.text, upright=True)]  # numbers and upright text
    if isinstance(node, Frac):
        pr = _el("m:fPr", _el("m:type", m_val="lin")) if _LINEAR[0] else None
        return [_el("m:f", pr, _el("m:num", *_elements(node.num)), _el("m:den", *_elements(node.den)))]
    if isinstance(node, Attach):
        base = _el("m:e", *_elements(node.base))
        if node.sub is not None and node.sup is not None:
            return [_el("m:sSubSup", base, _el("m:sub", *_elements(node.sub)), _el("m:sup", *_elements(node.sup)))]
        if node.sub is not None:
            return [_el("m:sSub", base, _el("m:sub", *_elements(node.sub)))]
        return [_el("m:sSup", base, _el("m:sup", *_elements(node.sup)))]
    if isinstance(node, Group):
        pr = _el("m:dPr", _el("m:begChr", m_val=node.open), _el("m:endChr", m_val=node.close))
        return [_el("m:d", pr, _el("m:e", *_elements(node.body)))]
    if isinstance(node, Func):
        if node.name == "arrow":  # a vector: the accent ⃗ above
            return [_el("m:acc", _el("m:accPr", _el("m:chr", m_val="\u20d7")), _el("m:e", *_elements(node.arg)))]
        if node.name == "sqrt":
            return [_el("m:rad", _el("m:radPr", _el("m:degHide", m_val="1")), _el("m:deg"),
                        _el("m:e", *_elements(node.arg)))]
        pr = _el("m:dPr", _el("m:begChr", m_val="|"), _el("m:endChr", m_val="|"))
        return [_el("m:d", pr, _el("m:e", *_elements(node.arg)))]
    if isinstance(node, Break):
        return []
    raise TypeError(node)


def lines(src: str) -> list[list]:
    """The formula's lines (split at typst ``\\``), each a list of OMML elements."""
    tree = parse(src)
    out, cur = [], []
    for x in tree.items:
        if isinstance(x, Break):
            out.append(cur)
            cur = []
        else:
            cur.append(x)
    out.append(cur)
    return [_elements(Seq(items)) for items in out if items]


def omath(src: str, size: float = 14, linear: bool = False):
    """An inline m:oMath element for a formula (one line) at `size` pt; `linear`: fractions a/b on
    the line (in a table's cells, where a stacked fraction makes a tall row)."""
    _SIZE[0], _LINEAR[0] = str(round(2 * size)), linear
    try:
        return _el("m:oMath", *[e for line in lines(src) for e in line])
    finally:
        _SIZE[0], _LINEAR[0] = "28", False


def omath_para(src: str, justify: str = "center", size: float = 14):
    """A display m:oMathPara holding one m:oMath: a formula of several lines is an equation array
    (m:eqArr), one math zone. A line that goes on with a relation («= 146,6 рад/с») starts with an
    empty text run: LibreOffice shows a zone or row that begins with «=» as an error «¿»."""
    _SIZE[0] = str(round(2 * size))
    try:
        rows = lines(src)
        rows = [([_run("", upright=True)] if _starts_with_relation(row) else []) + row for row in rows]
        body = rows[0] if len(rows) == 1 else [_el("m:eqArr", *[_el("m:e", *row) for row in rows])]
    finally:
        _SIZE[0] = "28"
    pr = _el("m:oMathParaPr", _el("m:jc", m_val=justify))
    return _el("m:oMathPara", pr, _el("m:oMath", *body))


def _starts_with_relation(row: list) -> bool:
    if not row or row[0].tag != _qn("m:r"):
        return False
    t = row[0].find(_qn("m:t"))
    return t is not None and (t.text or "").strip()[:1] in RELATIONS
