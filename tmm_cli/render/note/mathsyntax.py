"""The note's formulas: the subset of typst math the chapters write, read into a small tree.

The chapters write every formula once, as typst math (``k_φ = φ_"р"/b = 210/240 = "0,875" thin
"°/мм"``). The typst writer passes it through; the DOCX writer (:mod:`.omml`) and the Markdown
writer turn this tree into Word equations and text; :func:`check_line` recomputes every
"formula = substitution = result" of a line from the numbers it prints (the note's own test, and
the builder's guard while it writes).

The subset: single letters (Latin, Greek, Cyrillic) are variables; quoted strings are upright
text (numbers with a decimal comma are written as strings: ``"0,875"``); digits; ``_`` and ``^``
attachments with ``(…)`` grouping; ``a/b`` fractions binding the nearest unit on each side, as
typst does (parentheses around a numerator or denominator are dropped); ``\\/`` a slash kept on
the line; ``\\`` a line break; the named symbols of :data:`WORDS`; ``sqrt(…)``, ``abs(…)``, ``arrow(…)`` (a vector: an arrow above).
Anything else is an error (:class:`MathSyntaxError`), so that a formula the writers cannot read
never reaches a document.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from functools import lru_cache

# named symbols (typst names) and what they print as
WORDS = {
    "dot": "·", "times": "×", "approx": "≈", "quad": "\u2003", "thin": "\u2009", "med": "\u205f",
    "thick": "\u2004", "space": " ", "plus.minus": "±", "minus.plus": "∓", "dots": "…", "dots.h": "…",
    "infinity": "∞", "lt.eq": "≤", "gt.eq": "≥", "eq.not": "≠", "arrow.r": "→", "degree": "°", "pi": "π",
    "prime": "′",
}
# upright operators (typst's built-in math operators; "tg" is written as a string, "tg")
FUNCTIONS = {"sin", "cos", "tan", "tg", "ctg", "arctg", "max", "min", "ln", "log", "exp", "gcd", "lim", "mod",
             "inv"}
WRITTEN_AS_STRINGS = {"tg", "ctg", "arctg", "inv"}  # typst has no such operators: write "tg" φ
SYMBOL_OPS = {"<=": "≤", ">=": "≥", "=>": "⇒", "!=": "≠", "->": "→", "-": "−", "*": "∗"}
RELATIONS = {"=", "≈", "<", ">", "≤", "≥", "≠", "⇒"}


class MathSyntaxError(ValueError):
    """A formula outside the subset (a bug in a chapter builder, or an edited formula)."""


# --- the tree -----------------------------------------------------------------------------------


@dataclass
class Sym:
    """A leaf: ``kind`` var (italic letter), num (digits), text (upright string), op (operator or
    symbol), fn (upright function name), space."""

    text: str
    kind: str


@dataclass
class Seq:
    items: list = field(default_factory=list)


@dataclass
class Frac:
    num: object
    den: object


@dataclass
class Attach:
    base: object
    sub: object = None
    sup: object = None


@dataclass
class Group:
    """Visible delimiters around a body: ( ), [ ], { }, | |."""

    open: str
    body: Seq
    close: str


@dataclass
class Func:
    """sqrt(x), abs(x), arrow(x) (a vector, not a number)."""

    name: str
    arg: Seq


@dataclass
class Break:
    """A line break inside a display formula (typst ``\\``)."""


# --- tokens -------------------------------------------------------------------------------------

_TOKEN = re.compile(r"""
    (?P<ws>\s+)
  | (?P<str>"(?:[^"\\]|\\.)*")
  | (?P<escape>\\[/\\ ]|\\$)
  | (?P<name>[A-Za-z]+(?:\.[a-z]+)*)
  | (?P<letter>[^\W\d_])
  | (?P<num>\d+(?:\.\d+)?)
  | (?P<op><=|>=|=>|!=|->|[=+\-−*/^_'′()\[\]{}|,;:<>≤≥≈≠·×°%!?&⇒→±∓…∞∈])
""", re.X)


def tokens(src: str) -> list[tuple[str, str]]:
    out, i = [], 0
    while i < len(src):
        m = _TOKEN.match(src, i)
        if not m:
            raise MathSyntaxError(f"unexpected {src[i]!r} at {i} in {src!r}")
        kind = m.lastgroup
        text = m.group(0)
        i = m.end()
        if kind == "ws":
            out.append(("ws", " "))
        elif kind == "str":
            out.append(("str", re.sub(r"\\(.)", r"\1", text[1:-1])))
        elif kind == "escape":
            out.append(("slash", "/") if text == "\\/" else ("break", ""))
        elif kind == "name":
            if len(text) == 1:
                out.append(("letter", text))
            else:
                out.append(("name", text))
        else:
            out.append((kind, text))
    return out


# --- parser -------------------------------------------------------------------------------------


class _Parser:
    def __init__(self, src: str):
        self.src = src
        self.toks = tokens(src)
        self.i = 0

    def peek(self, skip_ws: bool = True):
        j = self.i
        while skip_ws and j < len(self.toks) and self.toks[j][0] == "ws":
            j += 1
        return self.toks[j] if j < len(self.toks) else (None, None)

    def take(self):
        while self.i < len(self.toks) and self.toks[self.i][0] == "ws":
            self.i += 1
        t = self.toks[self.i]
        self.i += 1
        return t

    def error(self, what: str):
        raise MathSyntaxError(f"{what} in {self.src!r}")

    def seq(self, closer: str | None = None) -> Seq:
        """Items up to `closer` (not consumed) or the end; fractions folded."""
        items: list = []
        while True:
            kind, text = self.peek(skip_ws=False)
            if kind is None:
                if closer is not None:
                    self.error(f"missing {closer!r}")
                break
            if kind == "ws":
                self.i += 1
                if items and not (isinstance(items[-1], Sym) and items[-1].kind == "space"):
                    items.append(Sym(" ", "space"))
                continue
            if kind == "op" and text == closer:
                break
            if kind == "op" and text in ")]}" and closer is None:
                self.error(f"unbalanced {text!r}")
            if kind == "op" and text == "/":
                self.i += 1
                while items and isinstance(items[-1], Sym) and items[-1].kind == "space":
                    items.pop()
                if not items:
                    self.error("a fraction without a numerator")
                num = items.pop()
                den = self.unit()
                items.append(Frac(_unwrap(num), _unwrap(den)))
                continue
            items.append(self.unit())
        while items and isinstance(items[-1], Sym) and items[-1].kind == "space":
            items.pop()
        return Seq(items)

    def unit(self):
        """One primary with its attachments."""
        kind, text = self.peek()
        if kind is None:
            self.error("unexpected end")
        base = self.primary()
        sub = sup = None
        while True:
            k, t = self.peek(skip_ws=False)
            if k == "op" and t in ("'", "′"):
                self.i += 1
                base = Seq([base, Sym("′", "op")]) if not isinstance(base, Seq) else Seq(base.items + [Sym("′", "op")])
                continue
            if k == "op" and t in "_^":
                self.i += 1
                arg = self.attachment()
                if t == "_":
                    sub = arg
                else:
                    sup = arg
                continue
            break
        return Attach(base, sub, sup) if (sub is not None or sup is not None) else base

    def attachment(self):
        k, t = self.peek(skip_ws=False)
        if k == "op" and t == "(":
            self.i += 1
            body = self.seq(")")
            self.take()
            return body
        if k == "op" and t in "-−+*":  # h^* , 10^-3 (typst takes one token)
            self.i += 1
            if t in "-−":
                nk, nt = self.peek(skip_ws=False)
                if nk == "num":
                    self.i += 1
                    return Seq([Sym("−", "op"), Sym(nt, "num")])
            return Sym("∗" if t == "*" else SYMBOL_OPS.get(t, t), "op")
        return self.primary()

    def primary(self):
        kind, text = self.take()
        if kind == "letter":
            return Sym(text, "var")
        if kind == "num":
            return Sym(text, "num")
        if kind == "str":
            return Sym(text, "fn" if text in FUNCTIONS else "text")
        if kind == "slash":
            return Sym("/", "op")
        if kind == "break":
            return Break()
        if kind == "name":
            if text in ("sqrt", "abs", "arrow"):
                k, t = self.peek(skip_ws=False)
                if not (k == "op" and t == "("):
                    self.error(f"{text} without (")
                self.take()
                body = self.seq(")")
                self.take()
                return Func(text, body)
            if text in WORDS:
                return Sym(WORDS[text], "space" if text in ("quad", "thin", "med", "thick", "space") else "op")
            if text in FUNCTIONS and text not in WRITTEN_AS_STRINGS:
                return Sym(text, "fn")
            self.error(f"unknown name {text!r}")
        if kind == "op":
            if text in "([{":
                close = {"(": ")", "[": "]", "{": "}"}[text]
                body = self.seq(close)
                self.take()
                return Group(text, body, close)
            if text == "|":
                # |x|: the body up to the next bar
                body = self.seq("|")
                self.take()
                return Group("|", body, "|")
            return Sym(SYMBOL_OPS.get(text, text), "op")
        self.error(f"unexpected {text!r}")


def _unwrap(node):
    """typst drops the parentheses around a fraction's numerator or denominator."""
    if isinstance(node, Group) and node.open == "(":
        return node.body
    return node


@lru_cache(maxsize=8192)
def parse(src: str) -> Seq:
    """The tree of a formula (typst math source); the same tree for the same text (do not change it).

    >>> t = parse('k_φ = φ_"р"/b = 210/240 = "0,875"')
    >>> [type(x).__name__ for x in t.items if not isinstance(x, Sym) or x.kind != "space"]
    ['Attach', 'Sym', 'Frac', 'Sym', 'Frac', 'Sym', 'Sym']
    """
    p = _Parser(src)
    out = p.seq()
    if p.i < len(p.toks):
        p.error("unbalanced")
    return out


# --- text (Markdown) ----------------------------------------------------------------------------


def to_text(node, html: bool = True) -> str:
    """The formula as readable text, with <sub>/<sup> (html) or _ and ^.

    >>> to_text(parse('k_φ = φ_"р"/b = 210/240 = "0,875" thin "°/мм"'))
    'k<sub>φ</sub> = φ<sub>р</sub>/b = 210/240 = 0,875 °/мм'
    >>> to_text(parse("(π dot 1000)/30 + sqrt(a^2 - b)"), html=False)
    '(π · 1000)/30 + √(a^2 − b)'
    """
    def t(n, top=False) -> str:
        if n is None:
            return ""
        if isinstance(n, Seq):
            return "".join(t(x) for x in n.items)
        if isinstance(n, Sym):
            if n.kind == "space":
                return " "
            return n.text
        if isinstance(n, Frac):
            return _wrap(t(n.num), n.num) + "/" + _wrap(t(n.den), n.den)
        if isinstance(n, Attach):
            out = t(n.base)
            if n.sub is not None:
                out += f"<sub>{t(n.sub)}</sub>" if html else "_" + _wrap(t(n.sub), n.sub)
            if n.sup is not None:
                out += f"<sup>{t(n.sup)}</sup>" if html else "^" + _wrap(t(n.sup), n.sup)
            return out
        if isinstance(n, Group):
            return n.open + t(n.body) + n.close
        if isinstance(n, Func):
            if n.name == "arrow":
                return t(n.arg) + "\u20d7"  # a combining arrow above
            return ("√(" + t(n.arg) + ")") if n.name == "sqrt" else ("|" + t(n.arg) + "|")
        if isinstance(n, Break):
            return "; "
        raise TypeError(n)

    text = t(node)
    text = re.sub(r"[ \u2009\u2003\u205f\u2004]+", " ", text).strip()
    return re.sub(r" °(?!/)", "°", text)


def _wrap(text: str, node) -> str:
    simple = isinstance(node, Sym) or (isinstance(node, Attach) and not isinstance(node.base, (Frac, Seq))) \
        or isinstance(node, (Group, Func))
    return text if simple else f"({text})"


# --- numbers and the check of substitutions -------------------------------------------------------

_SUP = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")
_NUMBER = re.compile(r"^[−\-+]?[\d\u00a0\u202f\u2009 ]*\d(?:[,.]\d+)?(?:·10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?°?$")


def number_value(text: str) -> tuple[float, float] | None:
    """(value, one unit of its last printed digit) of a printed number, or None.

    >>> number_value("−20,65"), number_value("1,458·10⁻⁴"), number_value("360°"), number_value("мм")
    ((-20.65, 0.01), (0.0001458, 1e-07), (360.0, 1.0), None)
    """
    s = text.strip()
    if not s or not _NUMBER.match(s):
        return None
    s = s.replace("\u00a0", "").replace("\u202f", "").replace("\u2009", "").replace(" ", "").rstrip("°")
    s = s.replace("−", "-").replace(",", ".")
    exp = 0
    if "·10" in s:
        s, e = s.split("·10")
        exp = int(e.translate(_SUP))
    decimals = len(s.split(".")[1]) if "." in s else 0
    return float(s) * 10.0 ** exp, 10.0 ** (exp - decimals)


class NotNumeric(Exception):
    """The part holds a symbol: it is a formula, not a substitution."""


def _flatten(seq: Seq) -> list:
    return [x for x in seq.items if not (isinstance(x, Sym) and x.kind == "space")]


def evaluate(node) -> tuple[float, float]:
    """(value, last-digit unit) of a numeric part: numbers, + − · /, powers, √, |…|, π, sin/cos/tg
    (of degrees when the angle is printed with °). A trailing unit (text after the number) is
    dropped; the unit is that of the last number printed. NotNumeric for a part with a symbol.

    >>> round(evaluate(parse('(π dot "1000")/30 thin "рад/с"'))[0], 4)
    104.7198
    >>> evaluate(parse('"0,425" dot 115'))[0]
    48.875
    >>> round(evaluate(parse('("3,2632"/"3,2727" - 1) dot 100 %'))[0], 3)
    -0.29
    """
    items = node.items if isinstance(node, Seq) else [node]
    ev = _Eval(items)
    value = ev.expr()
    return value, ev.last_unit


class _Eval:
    """Precedence climbing over the flat item list: + − lowest, then · / and juxtaposition, then
    unary minus, then powers and functions."""

    def __init__(self, items):
        self.items = [x for x in items if not (isinstance(x, Sym) and x.kind == "space")]
        # drop a trailing unit: text that is not a number, and % or °
        while self.items and isinstance(self.items[-1], Sym) and (
                (self.items[-1].kind == "text" and number_value(self.items[-1].text) is None)
                or self.items[-1].text in ("%", "°")):
            self.items.pop()
        self.i = 0
        self.last_unit = 1.0
        if not self.items:
            raise NotNumeric("empty")

    def peek(self):
        return self.items[self.i] if self.i < len(self.items) else None

    def expr(self) -> float:
        v = self.term()
        while isinstance(self.peek(), Sym) and self.peek().text in ("+", "−", "-"):
            op = self.peek().text
            self.i += 1
            r = self.term()
            v = v + r if op == "+" else v - r
        if self.peek() is not None:
            raise NotNumeric(f"left over {self.peek()!r}")
        return v

    def term(self) -> float:
        v = self.unary()
        while True:
            n = self.peek()
            if isinstance(n, Sym) and n.text in ("·", "×", "∗"):
                self.i += 1
                v *= self.unary()
            elif isinstance(n, Sym) and n.text in ("/", "÷"):
                self.i += 1
                v /= self.unary()
            elif n is not None and not (isinstance(n, Sym) and n.kind == "op" and n.text in ("+", "−", "-")):
                v *= self.unary()  # juxtaposition: 2(…), π 4
            else:
                return v

    def unary(self) -> float:
        n = self.peek()
        if isinstance(n, Sym) and n.text in ("−", "-"):
            self.i += 1
            return -self.unary()
        if isinstance(n, Sym) and n.text == "+":
            self.i += 1
            return self.unary()
        return self.atom()

    def atom(self) -> float:
        n = self.peek()
        self.i += 1
        if isinstance(n, Sym) and n.kind == "fn":
            arg_node = self.peek()
            deg = _printed_in_degrees(arg_node)
            x = self.unary()
            if n.text in ("sin", "cos", "tan", "tg", "ctg"):
                x = math.radians(x) if deg else x
                f = {"sin": math.sin, "cos": math.cos, "tan": math.tan, "tg": math.tan,
                     "ctg": lambda a: 1 / math.tan(a)}[n.text]
                return f(x)
            raise NotNumeric(n.text)
        return _value(n, self)


def _printed_in_degrees(node) -> bool:
    if isinstance(node, Sym):
        return node.text.endswith("°")
    if isinstance(node, Seq):
        return any(_printed_in_degrees(x) for x in node.items)
    if isinstance(node, Frac):
        return _printed_in_degrees(node.num)
    return False


def _value(n, ev: _Eval) -> float:
    if isinstance(n, Sym):
        if n.text == "π":
            return math.pi
        if n.kind in ("num", "text"):
            nv = number_value(n.text)
            if nv is None:
                raise NotNumeric(n.text)
            ev.last_unit = nv[1]
            return nv[0]
        raise NotNumeric(n.text)
    if isinstance(n, Frac):
        a = evaluate(_as_seq(n.num))[0]
        b, unit = evaluate(_as_seq(n.den))
        return a / b
    if isinstance(n, Group):
        if n.open == "|":
            return abs(evaluate(n.body)[0])
        if n.open in "([":
            v, unit = evaluate(n.body)
            return v
        raise NotNumeric(n.open)
    if isinstance(n, Attach):
        if n.sub is not None:
            raise NotNumeric("subscript")
        base = _value(n.base, ev)
        exp = evaluate(_as_seq(n.sup))[0]
        return base ** exp
    if isinstance(n, Func):
        if n.name == "arrow":
            raise NotNumeric("a vector")
        v = evaluate(n.arg)[0]
        return math.sqrt(v) if n.name == "sqrt" else abs(v)
    if isinstance(n, Seq):
        return evaluate(n)[0]
    raise NotNumeric(type(n).__name__)


def _as_seq(node) -> Seq:
    return node if isinstance(node, Seq) else Seq([node])


@dataclass
class Check:
    """One numeric link of a formula line: ``left`` (its printed form), its value, the relation,
    and the value it must agree with."""

    text: str
    value: float
    relation: str
    target: float
    unit: float
    ok: bool


def segments(seq: Seq) -> list[list]:
    """The line split at top-level ; and quad (several equalities on one line) and at line breaks."""
    out, cur = [], []
    items = seq.items
    for i, x in enumerate(items):
        if isinstance(x, Break):
            nxt = next((y for y in items[i + 1:] if not (isinstance(y, Sym) and y.kind == "space")), None)
            if isinstance(nxt, Sym) and nxt.kind == "op" and nxt.text in RELATIONS:
                continue  # "a = b \ = c": the chain goes on
        if (isinstance(x, Sym) and x.text in (";", "\u2003")) or isinstance(x, Break):
            if any(not (isinstance(y, Sym) and y.kind == "space") for y in cur):
                out.append(cur)
            cur = []
        else:
            cur.append(x)
    if any(not (isinstance(y, Sym) and y.kind == "space") for y in cur):
        out.append(cur)
    return out


def check_line(src: str) -> list[Check]:
    """Every numeric part of a formula line against the result of its chain.

    A chain is split at its relations (=, ≈, <, >, ≤, ≥); the numeric parts joined by "=" must
    agree with the last numeric part of the chain (the result) to half a unit of the result's last
    printed digit (the printed result is the rounding of what the substitution gives); "≈" allows half a unit of the rounded side; <, >, ≤, ≥ must hold.

    >>> [c.ok for c in check_line('x_(i k) = k\\'_S/k_(S k) x_i = "0,425" dot 115 = "48,86" thin "мм"')]
    [False]
    >>> [c.ok for c in check_line('x = "0,425" dot "114,96" = "48,86" thin "мм"')]
    [True]
    >>> [c.ok for c in check_line('z_1 = 17/"0,72" = "23,61" approx 24; quad i = 17/24 = "0,7083"')]
    [True, True, True]
    >>> [c.ok for c in check_line('sin π/4 = "0,7071" > (24 + 2)/62 = "0,4194"')]
    [True, True, True]
    >>> [c.ok for c in check_line('x = "0,425" dot 115 ' + chr(92) + ' = "48,86"')]
    [False]
    """
    out: list[Check] = []
    for seg in segments(parse(src)):
        parts, rels, cur = [], [], []
        for x in seg:
            if isinstance(x, Sym) and x.kind == "op" and x.text in RELATIONS:
                parts.append(cur)
                rels.append(x.text)
                cur = []
            else:
                cur.append(x)
        parts.append(cur)
        values: list[tuple[str, float, float] | None] = []
        for p in parts:
            try:
                v, u = evaluate(Seq(p))
                values.append((to_text(Seq(p), html=False), v, u))
            except (NotNumeric, ZeroDivisionError, ValueError, OverflowError):
                values.append(None)
        # "=" runs: every numeric member against the run's last numeric member
        run: list[int] = [0]
        for j, rel in enumerate(rels):
            if rel == "=":
                run.append(j + 1)
                continue
            out += _run_checks(values, run)
            a, b = values[j], values[j + 1]
            if a is not None and b is not None and rel != "⇒":
                out.append(_relation(a, b, rel))
            run = [j + 1]
        out += _run_checks(values, run)
    return out


def _run_checks(values, run) -> list[Check]:
    nums = [values[k] for k in run if values[k] is not None]
    if len(nums) < 2:
        return []
    text, target, unit = nums[-1]
    tol = 0.5 * unit * (1 + 1e-6) + 1e-12 * abs(target)  # the printed result is the rounding of the substitution
    return [Check(t, v, "=", target, unit, abs(v - target) <= tol) for t, v, _ in nums[:-1]]


def _relation(a, b, rel) -> Check:
    (ta, va, ua), (tb, vb, ub) = a, b
    if rel == "≈":
        ok = abs(va - vb) <= 0.5 * ub * (1 + 1e-9) + ua
    elif rel == "<":
        ok = va < vb
    elif rel == ">":
        ok = va > vb
    elif rel == "≤":
        ok = va <= vb + 1e-12 * abs(vb)
    elif rel == "≥":
        ok = va >= vb - 1e-12 * abs(vb)
    else:  # ≠
        ok = va != vb
    return Check(ta, va, rel, vb, ub, ok)


# --- width (to break a display formula that would not fit the line) ---------------------------------


def width(node) -> float:
    """Rough width of a formula in em of the body text: fractions as wide as their wider part,
    attachments at 0,7. Only for deciding where a display formula breaks.

    >>> width(parse("a/b")) < width(parse("a + b"))
    True
    """
    if node is None:
        return 0.0
    if isinstance(node, Seq):
        return sum(width(x) for x in node.items)
    if isinstance(node, Sym):
        if node.kind == "space":
            return {"\u2003": 1.0, "\u2009": 0.17}.get(node.text, 0.25)
        if node.kind == "op":
            return 1.0 if node.text in "=+−<>≤≥≈·×⇒" else 0.4
        return 0.5 * len(node.text) + (0.15 if node.kind == "fn" else 0.0)
    if isinstance(node, Frac):
        return max(width(node.num), width(node.den)) + 0.3
    if isinstance(node, Attach):
        return width(node.base) + 0.7 * max(width(node.sub), width(node.sup))
    if isinstance(node, Group):
        return width(node.body) + 0.7
    if isinstance(node, Func):
        return width(node.arg) + {"sqrt": 1.0, "abs": 0.5}.get(node.name, 0.5)  # arrow: the accent and its attachments
    return 0.0


def top_level_splits(src: str, sep: str = " = ") -> list[int]:
    """Positions of `sep` outside parentheses and strings."""
    out, depth, quoted = [], 0, False
    i = 0
    while i < len(src):
        ch = src[i]
        if ch == '"' and (i == 0 or src[i - 1] != "\\"):
            quoted = not quoted
        elif not quoted:
            if ch in "([{":
                depth += 1
            elif ch in ")]}":
                depth -= 1
            elif depth == 0 and src.startswith(sep, i):
                out.append(i)
        i += 1
    return out
