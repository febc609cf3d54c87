"""The measurement card of a planet carrier (seed 004): parse and validate its CSV text.

Seed 004 (Леонтьев, Насонов, Бедный, «Математическая модель для уточнённого определения
комплексных погрешностей сателлитных узлов планетарных передач», 2012), Figs. 2–4: the plant's
quality-control department measures on each cheek of the carrier the radial centre distances
R_i = |P_i|, R'_i = |P'_i| (Fig. 3), the chordal centre distances h_i = |P_i P_{i−1}|,
h'_i = |P'_i P'_{i−1}| with h_1 = |P_1 P_{z_c}| (Fig. 4), the skew s_i of bore i's axis about the
carrier's axis X (counter-clockwise seen from the end of X positive, Fig. 3), and the skew of
neighbouring axes (the preview stops before defining it; column ``e``, the project's
reconstruction, see :mod:`.measurements`).

The card is CSV text, one row per bore in order 1…z_c, header ``bore,R,R_prime,h,h_prime,s`` and
optionally ``e``, millimetres; the columns are separated by commas, semicolons or tabs (cells may
be quoted), and the decimal separator is a point or a comma (a comma inside an unquoted
comma-separated row splits the row, as a spreadsheet would). Empty cells at the end of a row (a
spreadsheet's trailing separators) are dropped. An empty ``e`` cell means that skew was not
measured. Lines starting with ``#`` are comments.

The command reads the file; this module takes its text and returns a :class:`Card` in metres
(SI inside), or raises :class:`~tmm_cli.errors.TmmError` naming the row and the column.

>>> card = parse_card('''bore;R;R_prime;h;h_prime;s
... 1;125,003;124,998;216,510;216,500;0,004
... 2;124,990;125,001;216,490;216,505;-0,002
... 3;125,010;125,000;216,520;216,495;0,001''')
>>> card.z_c, card.radial[0], card.has_pair_skew
(3, 0.125003, False)
"""

from __future__ import annotations

import math
import re

from ..errors import TmmError
from ..limits import CARD_BORES, CARD_BYTES
from ..records import record

MM = 1e-3
"""One millimetre [m]: the card's unit."""

REQUIRED = ("bore", "R", "R_prime", "h", "h_prime", "s")
"""The card's columns, in the order the issue gives them; ``e`` is optional."""

OPTIONAL = ("e",)

DISTANCES = ("R", "R_prime", "h", "h_prime")
"""Columns that are distances: positive."""


@record
class Card:
    """A validated measurement card [m]; index 0 is bore 1 (seed 004, Figs. 3–4).

    ``pair_skew`` holds e_i, or None for a skew not measured (an empty cell, or no ``e`` column).
    """

    radial: tuple[float, ...]  # R_i = |P_i| [m]
    radial_prime: tuple[float, ...]  # R'_i = |P'_i| [m]
    chord: tuple[float, ...]  # h_i = |P_i P_{i-1}| [m], h_1 = |P_1 P_{z_c}|
    chord_prime: tuple[float, ...]  # h'_i = |P'_i P'_{i-1}| [m]
    skew: tuple[float, ...]  # s_i = (P_i × P'_i)/|P_i| [m]
    pair_skew: tuple[float | None, ...]  # e_i [m] (reconstruction) or None

    @property
    def z_c(self) -> int:
        """Number of bores (planets) z_c."""
        return len(self.radial)

    @property
    def has_pair_skew(self) -> bool:
        """Whether any skew of neighbouring axes e_i was measured."""
        return any(v is not None for v in self.pair_skew)


_NUMBER = re.compile(r"[+-]?(\d+([.]\d*)?|[.]\d+)([eE][+-]?\d+)?")


def _number(cell: str, where: str, column: str) -> float:
    text = cell.strip().replace("\u2212", "-").replace(" ", "").replace("\u00a0", "")
    if text.count(",") == 1 and "." not in text:  # a decimal comma (a CSV split has left it in the cell)
        text = text.replace(",", ".")
    if not _NUMBER.fullmatch(text):
        raise TmmError(f"{where}: {column} is '{cell.strip()}', not a number; give millimetres such as 125.003")
    value = float(text)
    if not math.isfinite(value):
        raise TmmError(f"{where}: {column} is '{cell.strip()}'; give a finite number of millimetres")
    return value


def _split(line: str, sep: str) -> list[str]:
    """The cells of one CSV line (quotes as the csv module reads them), trailing empty ones dropped.

    >>> _split('1;"125,003"; 124,998;;', ";")
    ['1', '125,003', '124,998']
    """
    import csv

    try:
        cells = next(csv.reader([line], delimiter=sep), [])
    except csv.Error:
        cells = line.split(sep)
    cells = [c.strip() for c in cells]
    while cells and not cells[-1]:
        cells.pop()
    return cells


def parse_card(text: str, source: str = "card") -> Card:
    """The :class:`Card` [m] in CSV ``text`` (millimetres); ``source`` names it in errors.

    >>> parse_card("bore,R,R_prime,h,h_prime\\n1,1,1,1,1")
    Traceback (most recent call last):
    tmm_cli.errors.TmmError: card: the column 's' is missing; the header must be bore,R,R_prime,h,h_prime,s (and optionally e)
    """
    if len(text.encode("utf-8", "surrogatepass")) > CARD_BYTES:
        raise TmmError(f"{source} is larger than {CARD_BYTES >> 10} KiB; a card has one row per bore (3 to 12)")
    lines = [(n, ln.strip()) for n, ln in enumerate(text.lstrip("\ufeff").splitlines(), 1)]
    lines = [(n, ln) for n, ln in lines if ln and not ln.startswith("#")]
    if not lines:
        raise TmmError(f"{source} is empty; give the header {','.join(REQUIRED)} and one row per bore")
    head_no, head = lines[0]
    sep = ";" if ";" in head else ("\t" if "\t" in head else ",")
    names = _split(head, sep)
    known = {c.lower(): c for c in REQUIRED + OPTIONAL}
    columns: list[str] = []
    for name in names:
        canon = known.get(name.lower())
        if canon is None:
            raise TmmError(f"{source}: unknown column '{name}'; the header must be {','.join(REQUIRED)} "
                           f"(and optionally e)")
        if canon in columns:
            raise TmmError(f"{source}: the column '{canon}' is given twice")
        columns.append(canon)
    for name in REQUIRED:
        if name not in columns:
            raise TmmError(f"{source}: the column '{name}' is missing; the header must be {','.join(REQUIRED)} "
                           f"(and optionally e)")
    rows = lines[1:]
    lo, hi = CARD_BORES
    if not lo <= len(rows) <= hi:
        raise TmmError(f"{source} has {len(rows)} bore rows; a carrier card needs one row per bore, "
                       f"from {lo} to {hi} bores")
    values: dict[str, list] = {c: [] for c in REQUIRED + OPTIONAL}
    for index, (line_no, line) in enumerate(rows, 1):
        cells = _split(line, sep)
        where = f"{source} line {line_no}"
        if len(cells) > len(columns):
            hint = "; with decimal commas separate the columns by semicolons" if sep == "," else ""
            raise TmmError(f"{where} has {len(cells)} cells, the header {len(columns)}{hint}")
        row = dict(zip(columns, cells + [""] * (len(columns) - len(cells))))  # short: the last cells empty
        bore = row["bore"].strip()
        if bore != str(index):
            raise TmmError(f"{where}: bore is '{bore}', expected {index}; list the bores in order 1, 2, … "
                           f"counter-clockwise seen from the end of the carrier's axis")
        where = f"{source} bore {index}"
        for column in REQUIRED[1:] + OPTIONAL:
            if column not in row:
                continue
            if column == "e" and not row[column].strip():
                values[column].append(None)
                continue
            if not row[column].strip():
                raise TmmError(f"{where}: {column} is empty; every bore needs {', '.join(REQUIRED[1:])}")
            value = _number(row[column], where, column)
            if column in DISTANCES and value <= 0:
                raise TmmError(f"{where}: {column} is {value:g} mm; a centre distance must be positive")
            values[column].append(value * MM)
    z = len(rows)
    radial, chord = values["R"], values["h"]
    radial_p, chord_p = values["R_prime"], values["h_prime"]
    for i in range(z):
        for name, radius, r, h in (("h", "R", radial, chord), ("h_prime", "R_prime", radial_p, chord_p)):
            reach = r[i] + r[i - 1]
            if h[i] > reach:
                prev = i if i else z  # bore i's neighbour, 1-based
                raise TmmError(f"{source} bore {i + 1}: {name} is {h[i] / MM:g} mm, longer than "
                               f"{radius}{i + 1} + {radius}{prev} = {reach / MM:g} mm (a chord is at most a diameter); "
                               f"check the row")
    pair = values["e"] if "e" in columns else [None] * z
    return Card(radial=tuple(radial), radial_prime=tuple(radial_p), chord=tuple(chord),
                chord_prime=tuple(chord_p), skew=tuple(values["s"]), pair_skew=tuple(pair))
