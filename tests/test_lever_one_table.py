"""Zhukovsky's lever by one method in sheet 2 and in the note (issue 32): the note's table of the
forces' arms and moments, its F_ур and M_ур, and the sheet's caption (read back from the DXF) give
the same terms with the same numbers, at the same μ; the terms add up, F_ур·(pa) balances them,
and M_ур = F_ур·l_1 agrees with the force analysis (recomputed here from the printed numbers and
from linkage.json, not from the code that prints them)."""

from __future__ import annotations

import json
import re
import tomllib
from pathlib import Path

import ezdxf
import pytest
from click.testing import CliRunner

from sheet_check import field_boxes, text_boxes
from test_sheets import TITLE
from tmm_cli.cli import cli
from tmm_cli.project import analyse_linkage, run_project
from tmm_cli.render.note import build_note
from tmm_cli.render.note.model import Formula, Paragraph, Table
from tmm_cli.render.sheets.dynamics_sheet import sheet2 as build_sheet2
from tmm_cli.variants import get_variant

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"
NAMES = ["shaper", "four_bar"]  # the examples `tmm project --mechanism` takes


def norm(text: str) -> str:
    """A number as both print it, the typographic minus and the thousands' narrow space aside."""
    return text.replace("\u202f", "").replace("\u00a0", "").replace("−", "-").replace("–", "-").strip('"')


def value(text: str) -> float:
    return float(norm(text).replace(",", "."))


def lever_caption(path: Path) -> list[str]:
    """The texts of the lever's field (its scale line, its caption), top down, from the DXF."""
    doc = ezdxf.readfile(path)
    box = field_boxes(doc)["lever"]
    out = []
    for _e, c, h, _rot, t in text_boxes(doc):
        mid = c.mean(axis=0)
        if box[0] <= mid[0] <= box[2] and box[1] <= mid[1] <= box[3] and (h < 4.0 or t.startswith("μ")):
            out.append((-mid[1], mid[0], norm(t)))
    return [t for *_, t in sorted(out)]


def note_math(doc, start: str) -> str:
    for b in doc.blocks:
        if isinstance(b, Formula):
            for piece in b.math.split(" \\ "):
                if piece.startswith(start):
                    return piece
    raise AssertionError(f"no formula {start}")


@pytest.fixture(scope="module", params=NAMES)
def both(request, tmp_path_factory):
    name = request.param
    tables = tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))
    s2 = analyse_linkage(tables, f"{name}.toml")
    r = run_project(get_variant("17"), linkage=s2, linkage_name=f"{name}.toml")
    doc = build_note(r, "ru", {})
    folder = tmp_path_factory.mktemp(name)
    path = folder / "sheet2.dxf"
    build_sheet2(s2, "ru", TITLE).doc.saveas(path)
    res = CliRunner().invoke(cli, ["linkage", str(EXAMPLES / f"{name}.toml"), "--no-plots", "--out", str(folder),
                                   "--lang", "ru"])
    assert res.exit_code == 0, res.output
    data = json.loads((folder / "linkage" / "linkage.json").read_text(encoding="utf-8"))
    return name, doc, lever_caption(path), data, res.output


def test_the_same_terms_in_the_sheet_and_the_note(both):
    name, doc, caption, _, _ = both
    text = " ".join(caption)
    rows = next(b for b in doc.blocks if isinstance(b, Table) and b.name == "dyn_lever").rows
    terms = rows[:-1]
    assert len(terms) >= 3
    found = []
    for _sym, _pt, f, h, fh in terms:
        # the sheet: «Φ5: -10,70·156,66 = -1676,2» — the sign of the moment before F·h
        sign = "-" if value(fh) < 0 else ""
        item = f"{sign}{norm(f)}·{norm(h)} = {norm(fh)}"
        assert item in text, (name, item, caption)
        found.append(text.index(item))
    assert found == sorted(found)  # in the same order
    assert len(re.findall(r": -?[\d,]+·[\d,]+ = ", text)) == len(terms)  # and no other
    # the moments add up; the printed F·h agrees with the printed F and h
    total = value(rows[-1][-1])
    assert sum(value(r[-1]) for r in terms) == pytest.approx(total, abs=0.06 * len(terms))
    for _sym, _pt, f, h, fh in terms:
        assert value(f) * value(h) == pytest.approx(abs(value(fh)), abs=0.006 * (value(f) + value(h)) + 0.06)
    assert f"ΣF·h = {norm(rows[-1][-1])} Н·мм" in text


def test_the_same_balancing_force_and_moment(both):
    name, doc, caption, data, _ = both
    text = " ".join(caption)
    f_b = note_math(doc, 'F_"ур" =')
    m_b = note_math(doc, 'M_"ур"^"Ж" =')
    nums_f = [norm(x) for x in re.findall(r'"([^"]+)"', f_b) if re.match(r"[\d−]", x)]
    nums_m = [norm(x) for x in re.findall(r'"([^"]+)"', m_b) if re.match(r"[\d−]", x)]
    # the sheet: the same substitution and the same result
    assert f"F ур = |ΣF·h|/(pa) = {nums_f[0]}/{nums_f[1]} = {nums_f[2]} Н".replace("F ур", "Fур") in text, (f_b, caption)
    assert f"= {nums_m[-1]} Н·м" in text and f"{nums_m[0]}·" in text, (m_b, caption)
    # the lever in equilibrium: F_ур·(pa) = |ΣF·h|, and M_ур by the lever is the force analysis's
    assert value(nums_f[0]) / value(nums_f[1]) == pytest.approx(value(nums_f[2]), abs=0.006)
    pos = next(p for p in data["positions"] if p["label"] == data["forces"]["position"])
    assert value(nums_m[-1]) == pytest.approx(abs(pos["balancing_moment_Nm"]), abs=6e-4)
    # one scale: the note's μ_v of the lever is the one the sheet states and draws the arms at
    para = next(b.text for b in doc.blocks if isinstance(b, Paragraph) and "повёрнутый на 90°" in b.text)
    mu = re.search(r'μ_v = "?([\d,]+)"?\$', para).group(1)
    assert any(t.startswith(f"μv = {mu} (м/с)/мм") for t in caption) or f"при μv = {mu} (м/с)/мм" in text


def test_the_difference_is_given_to_its_digits(both):
    """Δ to the digits it has (not «0,00 %»), the same in both; below 10⁻⁹ % (a computer's rounding,
    not a value) as the bound «< 10⁻⁹ %»."""
    _, doc, caption, data, _ = both
    pos = next(p for p in data["positions"] if p["label"] == data["forces"]["position"])
    # (|M_ур| − |M_ур by the lever|)/|M_ур|: the JSON's signed difference (its moments are rounded to 12 digits)
    diff = pos["zhukovsky_difference_pct"] * (1 if pos["balancing_moment_Nm"] > 0 else -1)
    line = next(x for t in caption for x in t.split(";  ") if x.startswith("Δ ="))
    rel, shown = re.search(r"·100 ([=<]) (\S+) %$", line).groups()
    math = note_math(doc, "Δ =")
    n_rel, n_shown = re.search(r'dot 100 ([=<]) ("[^"]+"|\S+) thin', math).groups()
    assert "0,00" not in shown
    if abs(diff) < 1e-9 and diff != 0.0:
        assert (rel, shown) == ("<", "10⁻⁹") and (n_rel, n_shown) == ("<", "10^(-9)")
    else:
        assert rel == n_rel == "=" and norm(n_shown) == shown
        assert value(shown) == pytest.approx(diff, rel=0.05, abs=1e-12)


def test_the_terminal_gives_the_same_table(both):
    """`tmm linkage`'s table of the lever: the note's F, h and ±F·h in each row, and its F_ур."""
    name, doc, _, _, output = both
    rows = next(b for b in doc.blocks if isinstance(b, Table) and b.name == "dyn_lever").rows
    lines = [norm(x) for x in output.splitlines()]
    start = next(k for k, x in enumerate(lines) if x.startswith("Рычаг Жуковского"))
    body = lines[start:start + len(rows) + 12]
    for _sym, _pt, f, h, fh in rows[:-1]:
        assert any(re.search(rf"│ +{re.escape(norm(f))} │ +{re.escape(norm(h))} │ +{re.escape(norm(fh))} │", x)
                   for x in body), (name, f, h, fh)
    f_b = note_math(doc, 'F_"ур" =').split(" = ")[-1].split(" thin")[0]
    assert f"= {norm(f_b)} Н" in re.sub(r"\s+", " ", " ".join(body))  # the caption wraps at the terminal's width
