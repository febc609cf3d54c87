"""Issue 32, the teacher's second reading: what the note and the sheets tell of sheets 1–2.

- With a mechanism file the РЕФЕРАТ's key words name sheet 2's methods (КИНЕТОСТАТИКА, РЫЧАГ
  ЖУКОВСКОГО, МАХОВИК) within ГОСТ 7.32's 5…15 words, and its object, aim and results speak of the
  lever mechanism; the ЗАКЛЮЧЕНИЕ gives K, H (or ψ), M_ур, M_д, J_м, D and the flywheel's mass —
  each checked against what `tmm linkage` exports (linkage.json), not against the code that wrote
  the note. Without a mechanism the abstract and the conclusion say nothing of a lever mechanism.
- A Russian reader sees the groups' kinds in Russian letters (ВВВ, ВВП, ВПВ) on sheet 2 and in the
  note's figures; an English one the Latin letters.
- A mechanism's name in the other alphabet than the document's is warned about.
"""

from __future__ import annotations

import json
import re
import tomllib
from pathlib import Path

import pytest
from click.testing import CliRunner

from tmm_cli.cli import cli
from tmm_cli.i18n.lang import name_script_notes
from tmm_cli.project import analyse_linkage, run_project
from tmm_cli.render.note import build_note
from tmm_cli.render.note.model import Abstract, Heading, ListBlock, Paragraph
from tmm_cli.variants import get_variant

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"
WITH_SHEET2 = ["shaper", "four_bar"]  # the examples `tmm project --mechanism` takes (the compressor's 1450 rpm no motor drives)
_CACHE: dict = {}


def case(name: str, lang: str = "ru"):
    key = (name, lang)
    if key not in _CACHE:
        tables = tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))
        s2 = analyse_linkage(tables, f"{name}.toml")
        r = run_project(get_variant("17"), linkage=s2, linkage_name=f"{name}.toml")
        _CACHE[key] = (r, build_note(r, lang, {}))
    return _CACHE[key]


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    """linkage.json of each example as `tmm linkage` writes it."""
    out = {}
    for name in WITH_SHEET2:
        folder = tmp_path_factory.mktemp(name)
        res = CliRunner().invoke(cli, ["linkage", str(EXAMPLES / f"{name}.toml"), "--no-plots", "--out", str(folder),
                                       "--lang", "ru"])
        assert res.exit_code == 0, res.output
        out[name] = json.loads((folder / "linkage" / "linkage.json").read_text(encoding="utf-8"))
    return out


def ru(x: float, decimals: int) -> str:
    """A number as the Russian note prints it (decimal comma, typographic minus)."""
    text = f"{x:.{decimals}f}".replace(".", ",").replace("-", "−")
    head, _, tail = text.partition(",")
    sign = "−" if head.startswith("−") else ""
    digits = head.lstrip("−")
    if len(digits) > 4:  # a narrow no-break space between thousands
        groups = []
        while digits:
            groups.insert(0, digits[-3:])
            digits = digits[:-3]
        digits = "\u202f".join(groups)
    return sign + digits + ("," + tail if tail else "")


def abstract(doc) -> Abstract:
    return next(b for b in doc.blocks if isinstance(b, Abstract))


def conclusion_text(doc) -> str:
    out, inside = [], False
    for b in doc.blocks:
        if isinstance(b, Heading):
            inside = b.kind == "structural" and b.text in ("Заключение", "Conclusion")
        elif inside and isinstance(b, Paragraph):
            out.append(b.text)
        elif inside and isinstance(b, ListBlock):
            out.extend(b.items)
    return "\n".join(out)


@pytest.mark.parametrize("name", WITH_SHEET2)
def test_the_abstract_tells_sheets_1_and_2(name, exported):
    r, doc = case(name)
    a = abstract(doc)
    words = [w.upper() for w in a.keywords]
    assert {"КИНЕТОСТАТИКА", "РЫЧАГ ЖУКОВСКОГО", "МАХОВИК", "РЫЧАЖНЫЙ МЕХАНИЗМ"} <= set(words), words
    assert 5 <= len(words) <= 15, len(words)  # ГОСТ 7.32-2017 §5.4: from five to fifteen key words
    text = "\n".join(a.text)
    data = exported[name]
    assert "рычажный механизм «" + data.get("name", r.linkage.sheet1.mechanism.name) in text
    assert "маховик" in text
    j = data["dynamics"]["mertsalov"]["flywheel_kgm2"]
    assert re.search(r"J_\"м\"\$ = " + re.escape(_sig(j, 5)), text), text
    assert ru(data["time_ratio"], 3) in text


def _sig(x: float, sig: int) -> str:
    """`x` to `sig` significant digits, as the note prints it."""
    import math

    decimals = max(0, sig - 1 - int(math.floor(math.log10(abs(x)))))
    return ru(x, decimals)


@pytest.mark.parametrize("name", WITH_SHEET2)
def test_the_conclusion_gives_what_sheets_1_and_2_found(name, exported):
    r, doc = case(name)
    data = exported[name]
    text = conclusion_text(doc)
    pos = next(p for p in data["positions"] if str(p["label"]) == str(data["forces"]["position"]))
    d = data["dynamics"]
    assert ru(data["time_ratio"], 3) in text
    out = r.linkage.sheet1.mechanism.output
    if out.kind == "slider":
        assert f"$H$ = {ru(data['stroke_m'] * 1000, 2)}\u00a0мм" in text
    else:
        assert "$ψ$ = " in text
    assert f"$M_\"ур\"$ = {ru(pos['balancing_moment_Nm'], 2)}\u00a0Н·м" in text
    assert f"в положении {pos['label']}" in text
    assert f"$M_\"д\"$ = {_sig(abs(d['drive_moment_Nm']), 4)}\u00a0Н·м" in text
    assert f"$J_\"м\"$ = {_sig(d['mertsalov']['flywheel_kgm2'], 5)}\u00a0кг·м²" in text
    fw = d["flywheel"]
    assert f"$D$ = {ru(fw['diameter_m'] * 1000, 0)}\u00a0мм" in text
    assert f"масса {ru(fw['mass_kg'], 1)}\u00a0кг" in text
    # the Zhukovsky check with the digits it has, never a bare 0,00 %
    assert "рычагу Жуковского расхождение" in text
    assert "расхождение 0,00\u00a0%" not in text and "(0,00\u00a0%)" not in text
    # a requirement of sheet 2 in the list of what is met
    assert "коэффициент неравномерности" in text
    assert text.rstrip().endswith("Все требования задания выполнены.")
    # the spur module is said to be the mesh drawing's
    assert "зацепление вычерчено при модуле курсового проекта $m$ = 20\u00a0мм" in text


def test_without_a_mechanism_the_abstract_and_conclusion_keep_to_sheets_3_and_4():
    r = run_project(get_variant("52"))
    doc = build_note(r, "ru", {})
    a = abstract(doc)
    assert not {"КИНЕТОСТАТИКА", "МАХОВИК"} & {w.upper() for w in a.keywords}
    assert "рычажн" not in conclusion_text(doc)


def test_the_lever_check_gives_the_difference_with_its_digits():
    r, doc = case("shaper")
    text = "\n".join(b.text for b in doc.blocks if isinstance(b, Paragraph))
    assert "Плечи $h$ измерены" not in text
    assert "Плечи $h$ определены" in text
    assert "без округления оно составляет" in text


# --- Russian letters for the groups' kinds ---------------------------------------------------------------


def _dxf_texts(path: Path) -> str:
    import ezdxf

    doc = ezdxf.readfile(path)
    return "\n".join(e.dxf.text if e.dxftype() == "TEXT" else e.text for e in doc.modelspace()
                     if e.dxftype() in ("TEXT", "MTEXT"))


@pytest.mark.parametrize("name", ["shaper", "four_bar", "compressor"])
def test_sheet2_names_the_groups_kinds_in_russian_letters(name, tmp_path):
    res = CliRunner().invoke(cli, ["linkage", str(EXAMPLES / f"{name}.toml"), "--sheets", "--no-plots", "--out",
                                   str(tmp_path), "--lang", "ru"])
    assert res.exit_code == 0, res.output
    for sheet in ("sheet1", "sheet2"):
        text = _dxf_texts(tmp_path / "linkage" / f"{sheet}.dxf")
        assert not re.search(r"\b(RRR|RRP|RPR|RPP|PRP)\b", text), (sheet, re.findall(r".*\bR[RP][RP]\b.*", text))
    text = _dxf_texts(tmp_path / "linkage" / "sheet2.dxf")
    kinds = {"ВВВ", "ВВП", "ВПВ"} & set(re.findall(r"[ВП]{3}", text))
    assert kinds, "no group kind on sheet 2"


def test_the_note_figure_of_forces_names_kinds_in_the_documents_letters():
    from tmm_cli.render.figures.dynamics import forces_figure

    r, _ = case("shaper")
    for lang, want, bad in (("ru", "ВПВ", "RPR"), ("en", "RPR", "ВПВ")):
        fig = forces_figure(r.linkage, lang)
        titles = " ".join(ax.get_title() for ax in fig.axes)
        assert want in titles and bad not in titles, titles


# --- the name's alphabet ----------------------------------------------------------------------------------


def test_a_latin_name_on_a_russian_document_is_warned_about(tmp_path):
    src = (EXAMPLES / "four_bar.toml").read_text(encoding="utf-8")
    latin = tmp_path / "latin.toml"
    latin.write_text(re.sub(r'(?m)^name = ".*"$', 'name = "Four-bar linkage"', src, count=1), encoding="utf-8")
    res = CliRunner().invoke(cli, ["linkage", str(latin), "--no-plots", "--out", str(tmp_path / "o"), "--lang", "ru"])
    assert res.exit_code == 0, res.output
    flat = " ".join(res.output.split())
    assert "«Four-bar linkage»" in flat and "не буквами языка документа" in flat
    res = CliRunner().invoke(cli, ["linkage", str(latin), "--no-plots", "--out", str(tmp_path / "e"), "--lang", "en"])
    assert "letters of the document's language" not in " ".join(res.output.split())
    # the Russian name of the example: no warning in Russian, one in English
    assert name_script_notes("Шарнирный четырёхзвенник", "ru") == ()
    assert [n.code for n in name_script_notes("Шарнирный четырёхзвенник", "en")] == ["mechanism_name_script"]


# --- links named by their roles ---------------------------------------------------------------------------

ALL_EXAMPLES = ["shaper", "four_bar", "compressor", "whitworth"]


def _roles_from_file(name: str) -> dict[str, str]:
    """The roles as a teacher reads them off the file (independently of linkage/roles.py): the crank;
    in an RRR the bar on a frame joint swings (the examples' four-bar passes Grashof's test with the
    crank shortest) and the other joins two moving joints; an RRP's bar joins two moving joints and its
    slider slides on the fixed guide; an RPR's block slides in the slotted link turning about the frame."""
    t = tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))
    frame = set(t["frame"])
    out = {t["crank"]["pivot"] + t["crank"]["joint"]: "кривошип"}
    for g in t["group"]:
        j = g["joints"]
        if g["kind"] == "RRR":
            out[j[0] + j[1]] = "коромысло" if j[0] in frame else "шатун"
            out[j[1] + j[2]] = "коромысло" if j[2] in frame else "шатун"
        elif g["kind"] == "RRP":
            out[j[0] + j[1]] = "шатун"
            out[j[1]] = "ползун"
        elif g["kind"] == "RPR":
            out[j[0]] = "кулисный камень"
            out[j[0] + j[1]] = "кулиса"
    return out


@pytest.mark.parametrize("name", ALL_EXAMPLES)
def test_links_are_named_by_their_roles_in_the_notes_table_and_text(name):
    from tmm_cli.linkage.mechanism_file import parse_mechanism
    from tmm_cli.linkage.sheet1 import analyse_mechanism
    from tmm_cli.render.note.model import Table

    tables = tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))
    want = _roles_from_file(name)
    if "load" not in tables:  # sheet 1 only (the Whitworth example): the terminal's table of links
        from tmm_cli.render.terminal.mechanism import role_words

        got = role_words(analyse_mechanism(parse_mechanism(tables, name)), "ru")
        assert {k: got.get(k, got.get(k[::-1])) for k in want} == want
        return
    r = dataclasses_replace_linkage(analyse_linkage(tables, name))
    doc = build_note(r, "ru", {})
    tab = next(b for b in doc.blocks if isinstance(b, Table) and b.name == "linkage_links")
    got = {row[1]: row[2] for row in tab.rows[1:]}
    # a name in the file order of its joints, either way round
    for link, role in want.items():
        key = link if link in got else link[::-1] if link[::-1] in got else next(
            (k for k in got if sorted(k) == sorted(link)), None)
        assert key is not None and got[key] == role, (link, role, got)
    text = "\n".join(b.text for b in doc.blocks if isinstance(b, Paragraph))
    assert "стержень" not in text and "стержень" not in str(tab.rows)
    for role in set(want.values()):
        assert role in text, role


def dataclasses_replace_linkage(s1):
    import dataclasses

    return dataclasses.replace(run_project(get_variant("17")), linkage=s1)


def test_a_bar_turning_fully_about_the_frame_is_a_crank():
    """A double crank (Grashof: the frame shortest) — its output bar turns fully: кривошип, not коромысло."""
    from tmm_cli.linkage.mechanism_file import parse_mechanism
    from tmm_cli.linkage.roles import link_roles
    from tmm_cli.linkage.sheet1 import analyse_mechanism

    m = parse_mechanism({"frame": {"O": [0, 0], "C": [0.05, 0]}, "crank": {"pivot": "O", "joint": "A", "length": 0.2,
                         "rpm": 60}, "group": [{"kind": "RRR", "joints": ["A", "B", "C"], "lengths": [0.25, 0.22],
                                                "branch": "left"}]})
    assert link_roles(analyse_mechanism(m)) == {"OA": "crank", "AB": "coupler", "BC": "crank"}
