"""Word equations (Office Math Markup, OMML) from the note's formula tree (:mod:`.mathsyntax`).

Why not LaTeX → MathML → OMML (latex2mathml + mathml2omml): the formulas are written once, in the
typst subset the typst note compiles, and parsed into a small tree anyway (for the check of every
substitution); emitting OMML from that tree is a few dozen lines, needs no second notation and no
two more packages, and the tests read every formula of all 68 notes through the same parser.

The elements are built as lxml elements in the ``m:`` namespace (python-docx's lxml).
"""

from __future__ import annotations

import re

from .mathsyntax import Attach, Break, Frac, Func, Group, Seq, Sym, parse
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


def _run(text: str, upright: bool = False, bold: bool = False):
    rpr = []
    if upright or bold:
        rpr.append(_el("m:rPr", _el("m:sty", m_val="b" if bold else "p")))
    wr = _el("w:rPr", _el("w:rFonts", w_ascii=FONT, w_hAnsi=FONT, w_cs=FONT))
    t = _el("m:t")
    t.text = text
    t.set(XML_SPACE, "preserve")
    return _el("m:r", *rpr, wr, t)


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
            return [_run(" " if node.text == " " else node.text, upright=True)]
        if node.kind == "var":
            return [_run(node.text)]
        if node.kind == "fn":
            return [_run(node.text + " ", upright=True)]
        if node.kind == "op":
            text = {"−": "−", "·": "·"}.get(node.text, node.text)
            return [_run(text, upright=True)]
        m = SCI.fullmatch(node.text)
        if m:  # "1,458·10⁻⁴": the power of ten as a true superscript
            return [_run(m[1] + "·", upright=True),
                    _el("m:sSup", _el("m:e", _run("10", upright=True)),
                        _el("m:sup", _run(m[2].translate(SUPER_DIGITS), upright=True))), _run(m[3], upright=True) if m[3] else None]
        return [_run(node.text, upright=True)]  # numbers and upright text
    if isinstance(node, Frac):
        return [_el("m:f", _el("m:num", *_elements(node.num)), _el("m:den", *_elements(node.den)))]
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


def omath(src: str):
    """An inline m:oMath element for a formula (one line)."""
    return _el("m:oMath", *[e for line in lines(src) for e in line])


def omath_para(src: str, justify: str = "center"):
    """A display m:oMathPara: one m:oMath per line of the formula."""
    pr = _el("m:oMathParaPr", _el("m:jc", m_val=justify))
    return _el("m:oMathPara", pr, *[_el("m:oMath", *line) for line in lines(src)])
