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
import math
import re
import tomllib
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from tmm_cli.cli import cli
from tmm_cli.i18n.lang import name_script_notes
from tmm_cli.project import analyse_linkage, run_project
from tmm_cli.render.note import build_note
from tmm_cli.render.note.model import Abstract, Formula, Heading, ListBlock, Paragraph, plain
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
    return plain("\n".join(out))


@pytest.mark.parametrize("name", WITH_SHEET2)
def test_the_abstract_tells_sheets_1_and_2(name, exported):
    r, doc = case(name)
    a = abstract(doc)
    words = [w.upper() for w in a.keywords]
    assert {"КИНЕТОСТАТИКА", "РЫЧАГ ЖУКОВСКОГО", "МАХОВИК", "РЫЧАЖНЫЙ МЕХАНИЗМ"} <= set(words), words
    assert 5 <= len(words) <= 15, len(words)  # ГОСТ 7.32-2017 §5.4: from five to fifteen key words
    from tmm_cli.render.note.model import text_runs

    text = "".join(t for _, t in text_runs("\n".join(a.text)))  # the mechanism's name as the reader sees it
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
    assert "зацепление вычерчено при модуле чертежа $m$ = 20\u00a0мм, заданном пособием в п. 2.1.1" in text


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
    delta = next(b.math for b in doc.blocks if isinstance(b, Formula) and b.math.startswith("Δ ="))
    assert "0,00" not in delta  # the difference to its digits (1,2·10⁻¹⁴ %), or 0 when it is exactly 0


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

ALL_EXAMPLES = ["shaper", "four_bar", "compressor", "whitworth", "rocking_block", "shaper_offset"]


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
            out[j[0] + j[1]] = "коромысло" if j[0] in frame else "шатун"
            moving = isinstance(g.get("guide"), dict) and "link" in g["guide"]
            out[j[1]] = "кулисный камень" if moving else "ползун"  # on a moving guide: a block in a кулиса
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


# --- point 3: the note's form ----------------------------------------------------------------------------

ALL_VARIANTS = list(range(1, 69))
_VCACHE: dict = {}


def variant_doc(number: int, lang: str = "ru"):
    key = (number, lang)
    if key not in _VCACHE:
        r = run_project(get_variant(str(number)))
        _VCACHE[key] = (r, build_note(r, lang, {}))
    return _VCACHE[key]


def _all_texts(doc) -> list[str]:
    from tmm_cli.render.note.model import _texts

    return [t for b in doc.blocks for t in _texts(b)]


@pytest.mark.parametrize("number", ALL_VARIANTS)
def test_a_unit_after_an_inline_formula_never_breaks_from_it(number):
    """«$b = 240$ мм»: the space between a formula and its unit is a no-break one (as between a number
    and its unit), in every text of the note; and the book's symbols: n_к (the cam), ranges 3…8."""
    from tmm_cli.render.note.model import all_math, split_math

    _, doc = variant_doc(number)
    units = re.compile(r"^ (мм|м|Н|об/мин|рад|кг|кВт|Вт|Дж|°|%)(?![^\W\d_])")
    for text in _all_texts(doc):
        pieces = split_math(text)
        for (m1, _), (m2, after) in zip(pieces, pieces[1:]):
            if m1 and not m2:
                assert not units.match(after), (text, after[:20])
    for kind, src in all_math(doc):
        assert not re.search(r"\bn_k\b", src), src  # the cam's speed is n_к, beside n_кр
    body = "\n".join(_all_texts(doc))
    assert not re.search(r"\d …\s?\d", body), re.findall(r".{20}\d … ?\d.{5}", body)[:3]
    assert "tmm" not in doc.resolve(body)  # the program is named in Russian


def test_the_spur_module_is_the_mesh_drawings_and_the_sources_are_cited():
    _, doc = variant_doc(52)
    body = "\n".join(_all_texts(doc))
    assert "модуль чертежа, а не результат расчёта на прочность" in body
    assert "ГОСТ 16532-70" in body
    cited = set(doc.cited)
    assert {"book", "gost16532", "gost2104", "gost2302", "gost732"} <= cited, cited
    a = abstract(doc)
    assert "зацепление вычерчено при модуле чертежа $m$ = 20\u00a0мм, заданном пособием в п. 2.1.1" in "\n".join(a.text)


@pytest.mark.parametrize("name", WITH_SHEET2)
def test_the_force_polygons_equations_are_vector_equations(name):
    from tmm_cli.render.note.model import Formula

    _, doc = case(name)
    polys = [b.math for b in doc.blocks if isinstance(b, Formula) and (b.label or "").startswith("dyn_poly_")]
    assert len(polys) == len(case(name)[0].linkage.sheet1.mechanism.groups)  # one numbered polygon a group
    for m in polys:
        # every force of a vector equation carries its arrow: no bare R_ or Σ F
        assert not re.search(r"(?<!arrow\()\bR_", m.replace("arrow(R)_", "")), m
        assert "Σ F^" not in m, m


# --- the compiled notes: a figure stays with its caption, an equation's number with room --------------------


@pytest.fixture(scope="module")
def compiled(tmp_path_factory):
    """note.pdf of variant 52 and of variant 8 with the shaper, as `tmm project` writes them."""
    out = {}
    for key, extra in (("v52", ["--variant", "52"]),
                       ("v8-shaper", ["--variant", "8", "--mechanism", str(EXAMPLES / "shaper.toml")])):
        folder = tmp_path_factory.mktemp(key)
        res = CliRunner().invoke(cli, ["project", *extra, "--out", str(folder), "--no-sheets",
                                       "--lang", "ru", "--city", "Челябинск"])
        assert res.exit_code == 0, res.output
        out[key] = next(folder.glob("variant-*"))
    return out


def _pages(pdf: Path) -> list[str]:
    import logging

    pypdf = pytest.importorskip("pypdf")
    logging.getLogger("pypdf").setLevel(logging.ERROR)
    return [p.extract_text().replace("\xa0", " ").replace("\u202f", " ") for p in pypdf.PdfReader(pdf).pages]


@pytest.mark.parametrize("key", ["v52", "v8-shaper"])
def test_a_figure_never_parts_from_its_caption(key, compiled):
    """ГОСТ 7.32 §6.5: the picture and «Рисунок N – …» on one page. The figures keep their text as text
    (SVG), so the words of each picture are found on the page of its caption, not only on the page
    before it."""
    folder = compiled[key]
    pages = _pages(folder / "note.pdf")
    typ = (folder / "note.typ").read_text(encoding="utf-8")
    files = re.findall(r'#figure\(image\("([^"]+)"', typ)
    assert files
    for number, name in enumerate(files, 1):
        svg = (folder / name).read_text(encoding="utf-8")
        words = {w for w in re.findall(r"<text[^>]*>([^<]{4,})</text>", svg) if not re.fullmatch(r"[−\-\d, .]+", w)}
        at = [k for k, p in enumerate(pages) if re.search(rf"Рисунок {number} –", p)]
        assert at, number
        k = at[-1]
        here = sum(w in pages[k] for w in words)
        before = sum(w in pages[k - 1] for w in words) if k else 0
        assert here >= before and (here > 0 or not words), (number, name, here, before)


@pytest.mark.parametrize("key", ["v52", "v8-shaper"])
def test_an_equations_number_keeps_its_distance(key, compiled):
    """«= 2211 Н(28)»: a numbered formula never reaches its number (read in the PDF's layout)."""
    import logging

    pypdf = pytest.importorskip("pypdf")
    logging.getLogger("pypdf").setLevel(logging.ERROR)
    for k, page in enumerate(pypdf.PdfReader(compiled[key] / "note.pdf").pages):
        lines = page.extract_text(extraction_mode="layout").splitlines()
        right = max((len(line.rstrip()) for line in lines), default=0)
        for line in lines:
            m = re.search(r"(\S)( *)\((\d+)\)\s*$", line)
            if m and len(line.rstrip()) >= right - 3:
                assert len(m.group(2)) >= 2, (k + 1, line.strip()[-60:])


def test_the_title_page_takes_the_city_or_labels_the_blanks(compiled, tmp_path):
    typ = (compiled["v52"] / "note.typ").read_text(encoding="utf-8")
    assert '"city": "Челябинск"' in typ or "Челябинск" in typ
    text = _pages(compiled["v52"] / "note.pdf")[0]
    assert "Челябинск" in text and "(город)" not in text
    assert "(наименование организации)" in text  # no --org: the ГОСТ 7.32 label under the blank line
    # city in tmm.toml, org given: no labels
    (tmp_path / "tmm.toml").write_text('city = "Екатеринбург"\norg = "УрФУ, кафедра ТММ"\n', encoding="utf-8")
    from tmm_cli.inputs.titleblock import title_fields

    f = title_fields({}, tmp_path)
    assert f.city == "Екатеринбург" and f.org == "УрФУ, кафедра ТММ"
    assert title_fields({"city": "Омск"}, tmp_path).city == "Омск"  # an option beats the file


# --- point 4: the sheets ---------------------------------------------------------------------------------


def test_the_sheets_font_draws_a_small_soft_sign():
    """ГОСТ 2.304: «ь» is a small letter. The bundled osifont's «ь» was its capital «Ь»; measured as the
    sheets draw it (matplotlib's text path of the font file): as high as «в» and «ы», lower than «Ь»
    by the ratio of the font's x-height to its cap height, and as wide as the soft sign inside «ы»."""
    from matplotlib.font_manager import FontProperties
    from matplotlib.textpath import TextPath

    from tmm_cli.render.sheets.paper import FONT_DIR

    prop = FontProperties(fname=str(FONT_DIR / "osifont.ttf"))

    def box(ch):
        b = TextPath((0, 0), ch, size=10, prop=prop).get_extents()
        return b.width, b.height

    small = box("ь")[1]
    assert abs(small - box("в")[1]) < 0.03 * box("в")[1]
    assert abs(small - box("ы")[1]) < 0.03 * box("ы")[1]
    assert small < 0.75 * box("Ь")[1]
    assert box("Ь")[1] > 1.3 * box("в")[1]  # the capital stays a capital
    # the other letters the font patch made are still there
    for ch in "ЭэЁё":
        assert box(ch)[1] > 0.5 * box("в")[1]


SIX_LINK = {  # crank, RRR, RRP on a vertical guide hung at D, a joint of the rocker BC off its axis (a plate)
    "name": "Шестизвенный механизм", "positions": 12, "gravity": True,
    "frame": {"O": [0.0, 0.0], "C": [0.30, 0.0]},
    "crank": {"pivot": "O", "joint": "A", "length": 0.08, "rpm": 95, "sense": "cw"},
    "group": [{"kind": "RRR", "joints": ["A", "B", "C"], "lengths": [0.28, 0.20], "branch": "left"},
              {"kind": "RRP", "joints": ["D", "E"], "length": 0.45,
               "guide": {"through": [0.40, 0.0], "angle_deg": 90.0}, "branch": "ahead"}],
    "point": [{"name": "D", "link": ["C", "B"], "along": 0.26, "across": 0.06},
              {"name": "S2", "link": ["A", "B"], "along": 0.14}, {"name": "S3", "link": ["C", "B"], "along": 0.10},
              {"name": "S4", "link": ["D", "E"], "along": 0.2}],
    "mass": [{"link": ["O", "A"], "m": 0.8, "J": 0.0006, "centre": "O"},
             {"link": ["A", "B"], "m": 2.2, "J": 0.0145, "centre": "S2"},
             {"link": ["B", "C"], "m": 1.6, "J": 0.0054, "centre": "S3"},
             {"link": ["D", "E"], "m": 2.0, "J": 0.01, "centre": "S4"}, {"joint": "E", "m": 10.0, "J": 0.0}],
    "load": {"on": "E", "stroke": [0.0, 0.1, 0.1, 0.9, 0.9, 1.0], "force": [0.0, 0.0, 800.0, 800.0, 0.0, 0.0],
             "working": "towards"},
    "dynamics": {"delta": 0.05, "J_rotor": 0.5},
}


def test_a_link_of_three_joints_is_one_hatched_body():
    """The rocker BC carries the joint D off its axis: it is drawn as one plate B–C–D, hatched, and
    its line is not run on past C to the foot of D (the extra arm the teacher saw in all 12 positions)."""
    from tmm_cli.linkage.mechanism_file import parse_mechanism
    from tmm_cli.linkage.sheet1 import analyse_mechanism
    from tmm_cli.render.sheets.lever_parts import link_segments

    s1 = analyse_mechanism(parse_mechanism(SIX_LINK, "six"))
    kin = s1.cycle.kin
    for p in s1.cycle.positions:
        z = {n: complex(kin.z[n][p.index]) * 1000.0 for n in ("B", "C", "D")}
        segs = [sg for sg in link_segments(s1.mechanism, kin, p.index, names={"BC"}, unit=0.5)]
        line = next(sg for sg in segs if sg[0] == "line")
        ends = sorted((line[1], line[2]), key=lambda q: abs(q - z["B"]))
        assert abs(ends[0] - z["B"]) < 1e-6 and abs(ends[1] - z["C"]) < 1e-6, (p.label, line[1:3])
        outline = next(sg[1] for sg in segs if sg[0] == "poly")
        for n in "BCD":
            assert min(abs(q - z[n]) for q in outline) < 1e-9
        hatch = next(sg[1] for sg in segs if sg[0] == "hatch")
        assert len(hatch) >= 5
        # every hatch line inside the triangle (barycentric test of its midpoint)
        b, c, d = z["B"], z["C"], z["D"]

        def inside(q):
            def side(p0, p1):
                return ((p1 - p0).conjugate() * (q - p0)).imag
            s = [side(b, c), side(c, d), side(d, b)]
            return all(x >= -1e-6 for x in s) or all(x <= 1e-6 for x in s)
        assert all(inside((q0 + q1) / 2) for q0, q1 in hatch)


def test_the_six_link_sheets_pass_the_normcontrollers_check(tmp_path):
    """Sheets 1 and 2 of the six-link mechanism through the same check as the examples'."""
    from sheet_check import problems

    from tmm_cli.inputs.titleblock import TitleFields
    from tmm_cli.render.sheets.dynamics_sheet import sheet2
    from tmm_cli.render.sheets.linkage_sheet import sheet1

    s2 = analyse_linkage(SIX_LINK, "six")
    for sh in (sheet1(s2.sheet1, "ru", TitleFields()), sheet2(s2, "ru", TitleFields())):
        assert sh.unplaced == [], sh.unplaced
        assert problems(sh.doc) == []
        text = "\n".join(e.dxf.text if e.dxftype() == "TEXT" else e.text for e in sh.doc.modelspace()
                         if e.dxftype() in ("TEXT", "MTEXT"))
        assert not re.search(r"\bR[RP][RP]\b", text)


@pytest.mark.parametrize("name", ["shaper", "four_bar", "compressor", "six"])
def test_every_force_of_a_polygons_equation_is_named_on_sheet2(name):
    """A force plan a teacher can check: every vector of the polygon's equation is a side of it; the ones
    long enough carry their names (no label left unplaced), the short ones are named with their values
    in the note beside the polygon, under a heading that says why."""
    from sheet_check import all_texts

    from tmm_cli.i18n.numbers import num
    from tmm_cli.inputs.titleblock import TitleFields
    from tmm_cli.render.sheets.dynamics_sheet import SHORT_MM, sheet2

    tables = SIX_LINK if name == "six" else tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))
    s2 = analyse_linkage(tables, name)
    sh = sheet2(s2, "ru", TitleFields())
    assert sh.unplaced == []
    text = "\n".join(all_texts(sh.doc))
    for pg in s2.polygons:
        assert len(pg.vectors) >= 3, pg.group  # the applied forces and the reactions, not one line
        short = [v for v in pg.vectors if v.kind != "unknown" and abs(v.value) / pg.scale < SHORT_MM]
        if short:
            assert "не подписаны" in text
        for v in short + [v for v in pg.vectors if v.kind == "unknown"]:
            assert f"= {num(abs(v.value), 'ru', decimals=1)}" in text, (pg.group, v.symbol)


@pytest.mark.parametrize("number", ALL_VARIANTS)
def test_sheet3s_centre_stands_on_the_hatched_zone(number):
    """The chosen centre O is a corner of the feasible zone; a hatch line runs from it into the zone
    (the hatching used to begin up to 2,4 mm from O, which looked outside it), on every variant's
    own zone polygon cut to a window round O as the sheet cuts it."""
    from tmm_cli.render.sheets.cam_sheet import _clip_half, _hatch_direction, hatch_chords

    r, _ = variant_doc(number)
    z = r.cam.sizing
    poly = np.asarray(z.zone.polygon, float) * 1000.0
    O = np.asarray(z.centre, float) * 1000.0
    for a, c in (((-1.0, 0.0), -(O[0] - 60.0)), ((1.0, 0.0), O[0] + 60.0), ((0.0, -1.0), -(O[1] - 60.0)),
                 ((0.0, 1.0), O[1] + 60.0)):
        poly = _clip_half(poly, np.array(a), c)
    d = _hatch_direction(poly, O, np.array([1.0, 1.0]) / np.sqrt(2.0))
    lines = hatch_chords(poly, d, 3.0, float(O @ np.array([-d[1], d[0]])))
    assert lines

    def dist(p, a, b):
        t = np.clip(np.dot(p - a, b - a) / max(np.dot(b - a, b - a), 1e-30), 0.0, 1.0)
        return float(np.hypot(*(a + t * (b - a) - p)))

    assert min(dist(O, a, b) for a, b in lines) < 0.05, number
    from matplotlib.path import Path as MPath

    zone = MPath(poly)
    assert all(zone.contains_point((a + b) / 2, radius=1e-6) or zone.contains_point((a + b) / 2, radius=-1e-6)
               for a, b in lines)


def test_sheet3s_hatch_is_one_hatch_entity_from_o():
    """The hatching stays one HATCH entity a CAD user can edit (i31), its pattern's base point O."""
    from tmm_cli.inputs.titleblock import TitleFields
    from tmm_cli.render.sheets import sheet3

    r, _ = variant_doc(8)
    sh = sheet3(r.cam, "ru", TitleFields())
    hatches = [e for e in sh.doc.modelspace() if e.dxftype() == "HATCH" and e.dxf.pattern_name == "TMM_ZONE"]
    assert len(hatches) == 1
    line = hatches[0].pattern.lines[0]
    field = {}
    for e in sh.doc.modelspace():
        if e.has_xdata("TMM_FIELD"):
            tags = [t.value for t in e.get_xdata("TMM_FIELD")]
            field[tags[0]] = tags
    tags = next(v for k, v in field.items() if "zone" in k)
    ox, oy, scale = float(tags[5]), float(tags[6]), float(tags[7])
    O = np.asarray(r.cam.sizing.centre, float) * 1000.0
    assert np.hypot(line.base_point[0] - (ox + scale * O[0]), line.base_point[1] - (oy + scale * O[1])) < 1e-6


@pytest.mark.parametrize("number", ALL_VARIANTS[::3])
def test_sheet4_draws_the_reducer_with_a_chosen_module(number):
    """Sheet 4's reducer: the module is chosen as the drawing needs — the largest standard module at
    which the scheme fits its field at 1:1 — and k_l, the scale label and the drawn size follow from it
    (no more «M 2:1, m = 1 мм»)."""
    from sheet_check import all_texts, field_boxes

    from tmm_cli.inputs.titleblock import TitleFields
    from tmm_cli.render.sheets import sheet4
    from tmm_cli.render.sheets.gears_sheet import MODULES

    r, _ = variant_doc(number)
    sh = sheet4(r.gears, number, "ru", TitleFields())
    text = "\n".join(all_texts(sh.doc))
    m = re.search(r"kl = ([\d,]+) м/мм \(М (\d+(?:,\d+)?):(\d+(?:,\d+)?), m = ([\d,]+) мм", text)
    assert m, text[:400]
    k_l, a, b, mod = (float(x.replace(",", ".")) for x in m.groups())
    assert mod in MODULES
    assert abs(k_l - 0.001 * b / a) < 1e-9 * k_l  # k_l [m/mm]: the stated scale of the true (module) size
    if mod > 1.0:
        assert (a, b) == (1.0, 1.0) and "наибольший стандартный модуль" in text
    d = r.gears.planetary
    z_max = max(max(s.z_ring, s.z_sun + 2 * s.z_planet) for s in d.stages)
    box = field_boxes(sh.doc)["scheme"]
    assert z_max * mod * a / b <= box[3] - box[1]  # the reducer's largest diameter, drawn, fits the field's height


@pytest.mark.parametrize("name", WITH_SHEET2)
def test_the_crank_speed_of_the_analysis_and_of_the_drive_are_both_said(name):
    """v8 of the issue: the reducer turns the crank at 97,1 об/мин while sheets 1–2 use the file's speed —
    the assumptions say which is which whenever the two differ."""
    r, doc = case(name)
    g = r.gears
    items = [plain(i) for b in doc.blocks if isinstance(b, ListBlock) for i in b.items]
    said = [i for i in items if "листы 1 и 2" in i and "привод вращает кривошип" in i]
    if abs(g.crank_rpm_actual - r.linkage.sheet1.mechanism.crank.rpm) > 1e-9:
        assert said and ru(g.crank_rpm_actual, 1) in said[0], items
    else:
        assert not said


def test_the_docx_title_page_labels_the_blanks_as_the_pdf_does(tmp_path):
    """No --org, no --city: note.docx prints the ГОСТ 7.32 labels under the blank lines (organisation,
    department, city) as the typst title page does; given, the labels go."""
    import docx

    from tmm_cli.inputs.titleblock import TitleFields
    from tmm_cli.render.note import write_note

    r, _ = variant_doc(52)

    def title_texts(folder, title):
        folder.mkdir()
        write_note(folder, r, "ru", title, {}, docx=True, pdf=False)
        d = docx.Document(str(folder / "note.docx"))
        body = "\n".join(p.text for p in d.paragraphs[:12]).replace("\u2060", "")
        foot = "\n".join(p.text for p in d.sections[0].first_page_footer.paragraphs)
        return body, foot

    body, foot = title_texts(tmp_path / "blank", TitleFields())
    assert "(наименование организации)" in body and "(наименование кафедры)" in body, body
    assert "(город)" in foot and "____" in foot, foot
    body, foot = title_texts(tmp_path / "given", TitleFields(org="УрФУ, кафедра ТММ", city="Челябинск"))
    assert "(наименование организации)" not in body and "УрФУ" in body, body
    assert "(город)" not in foot and "Челябинск" in foot, foot


@pytest.mark.parametrize("name", WITH_SHEET2)
def test_phi_means_one_thing_in_the_notes_tables(name):
    """The kinematics table gives $φ$, the crank angle from the axis x (position 0 at φ_0); the table of
    the reduced quantities counts the turn from position 0, so its column is $Δ φ$ (0 at position 0),
    never the same heading for the two meanings."""
    from tmm_cli.render.note.model import Table

    r, doc = case(name)
    tables = {b.name: b for b in doc.blocks if isinstance(b, Table)}
    kin, dyn = tables["linkage_positions"], tables["dyn_reduced"]
    assert kin.header[1] == "$φ$, °" and dyn.header[1] == "$Δ φ$, °"
    phi0 = math.degrees(r.linkage.sheet1.cycle.positions[0].phi) % 360.0
    assert dyn.rows[0][0] == kin.rows[0][0] == "0"
    assert float(dyn.rows[0][1].replace(",", ".")) == 0.0
    assert abs(float(kin.rows[0][1].replace(",", ".").replace("−", "-")) % 360.0 - phi0) < 0.01
    said = [t for t in _all_texts(doc) if "$Δ φ$" in t and "{tab:dyn_reduced}" in t]
    assert said and "$φ$" in said[0], said  # the text says which angle each table gives


@pytest.mark.parametrize("name", WITH_SHEET2)
def test_a_tables_header_keeps_its_unit_on_one_line(name):
    """«рад/ с» split in a narrow column: a header's unit has no break after its slash (a word joiner
    in the typst source); the math of a header and the text of a body cell are left alone."""
    from tmm_cli.render.note.model import Table
    from tmm_cli.render.note.typst import TypstWriter

    _, doc = case(name)
    w = TypstWriter(doc)
    seen = 0
    for b in doc.blocks:
        if not isinstance(b, Table):
            continue
        src = "\n".join(w.block(b))
        header = src.split("\n")[0]
        cells = re.findall(r"\[([^\[\]]*)\]", header[header.rindex("(["):])
        assert len(cells) >= len(b.header)
        for cell in cells:
            text = re.sub(r"\$[^$]*\$", "", cell)
            for m in re.finditer("/", text):
                assert text[m.end():m.end() + 1] == "\u2060", (b.name, cell)
                seen += 1
    assert seen  # the units «рад/с», «м/с» are in the headers


@pytest.mark.parametrize("name", WITH_SHEET2)
def test_the_plans_figure_is_drawn_at_the_texts_scales(name, tmp_path):
    """Figure «Планы скоростей и ускорений»: the μ_v, μ_a written on it are those of the text and of the
    table of vectors (sheet 1's, which the segment lengths use), read from the SVG the note embeds."""
    from tmm_cli.render.figures.note import save_note_figure
    from tmm_cli.render.note.model import Table

    r, doc = case(name)
    plan = r.linkage.sheet1.plans[0]
    save_note_figure(tmp_path, r, "ru", "linkage_plans")
    svg = next(tmp_path.glob("*linkage_plans*.svg")).read_text(encoding="utf-8")
    written = re.findall(r"<!-- \$μ_\\text\{([va])\}\$ = ([\d,]+) ", svg)  # matplotlib's comment of each text
    assert sorted(written) == [("a", ru(plan.acceleration.scale, 4).rstrip("0").rstrip(",")),
                               ("v", ru(plan.velocity.scale, 4).rstrip("0").rstrip(","))], written
    table = next(b for b in doc.blocks if isinstance(b, Table) and b.name == "linkage_plans")
    assert f'$μ_v = {ru(plan.velocity.scale, 4).rstrip("0").rstrip(",")}$' in table.caption.replace('"', ""), \
        table.caption
    body = "\n".join(_all_texts(doc))
    assert "каждый в своём масштабе" not in doc.resolve(body)
