"""Sheets 3 and 4 after issues 8 and 12: the shifted spur pair on sheet 4, the carried roller and
the student's r0/e on sheet 3, Russian text (decimal commas, no raw markup) and English headings.

Expected numbers come from the exported JSON (the documents results.json holds), the drawing
from the DXF (field origin and scale from the XDATA on each field's heading).
"""

from __future__ import annotations

import json
import math
import re

import ezdxf
import pytest
from click.testing import CliRunner

from tmm_cli.cam.design import CamChoice, design_cam
from tmm_cli.cli import cli
from tmm_cli.gears.design import design_gears
from tmm_cli.render.sheets import sheet3, sheet4

from test_sheets import TITLE, VARIANTS, all_texts, check_layout, fields, mesh_matches_json, roller_circles_match_json

SHIFTS = {"zero": {}, "0.3,-0.3": {"shift": (0.3, -0.3)}, "auto": {"shift": "auto"}, "aw380": {"a_w_mm": 380.0},
          "0.5,0.2": {"shift": (0.5, 0.2)}}


def texts(doc) -> list[str]:
    return all_texts(doc)


@pytest.mark.parametrize("case", sorted(SHIFTS))
def test_sheet4_draws_the_pair_the_result_carries(case):
    g = design_gears(600.0, 220.0, **SHIFTS[case])
    doc = sheet4(g, 7, "ru", TITLE).doc
    check_layout(doc)
    sp = mesh_matches_json(doc, g)
    if case == "zero":
        assert sp["x1"] == sp["x2"] == 0 and sp["a_w_mm"] == sp["a_mm"]
        return
    # the table and the captions carry x1, x2, a_w, α_w of the shifted pair (Russian numbers)
    t = " ".join(texts(doc))
    from tmm_cli.i18n.numbers import num

    for v in (num(sp["x1"], "ru", sig=4), num(sp["x2"], "ru", sig=4), num(sp["alpha_w_deg"], "ru", sig=5)):
        assert v in t, v
    assert num(sp["a_w_mm"], "ru", sig=6) in t
    if sp["shifted"]["dw_mm"][0] != sp["d_mm"][0]:  # the working circles, the pole P on them
        f = fields(doc)["mesh"]
        k = f["scale"]
        ox, oy = f["origin"]
        rw = sp["shifted"]["dw_mm"][0] / 2 * k
        assert [e for e in doc.modelspace().query("ARC CIRCLE")
                if math.dist((e.dxf.center.x, e.dxf.center.y), (ox, oy)) < 1e-4 and abs(e.dxf.radius - rw) < 1e-4]


def test_project_shift_sheet4_from_the_written_files(tmp_path):
    """`tmm project --shift 0.3,-0.3`: the tip circles in sheet4.dxf have d_a/2 × scale from results.json."""
    run = CliRunner().invoke(cli, ["project", "-v", "17", "--out", str(tmp_path), "--no-plots", "--shift", "0.3,-0.3"])
    assert run.exit_code == 0, run.output
    folder = tmp_path / "variant-17"
    sp = json.loads((folder / "results.json").read_text(encoding="utf-8"))["gears"]["spur"]
    assert (sp["x1"], sp["x2"]) == (0.3, -0.3)
    doc = ezdxf.readfile(folder / "sheet4.dxf")
    f = fields(doc)["mesh"]
    k = f["scale"]
    ox, oy = f["origin"]
    for j, c in enumerate(((ox, oy), (ox, oy + sp["a_w_mm"] * k))):
        ra = sp["da_mm"][j] / 2 * k
        assert [e for e in doc.modelspace().query("ARC CIRCLE")
                if math.dist((e.dxf.center.x, e.dxf.center.y), c) < 1e-4 and abs(e.dxf.radius - ra) < 1e-4]
    # and sheet 3 of the same run draws the roller results.json carries
    cam = json.loads((folder / "results.json").read_text(encoding="utf-8"))["cam"]
    doc3 = ezdxf.readfile(folder / "sheet3.dxf")
    f3 = fields(doc3)["profile"]
    assert [e for e in doc3.modelspace().query("CIRCLE") if abs(e.dxf.radius - cam["roller_mm"] * f3["scale"]) < 1e-3]


def test_sheet3_students_r0_and_offset():
    """Variant 17 with --r0 60 --offset -10: base circle 60, offset circle 10, the carried roller."""
    cam = design_cam(VARIANTS[17], choice=CamChoice(r0_mm=60.0, offset_mm=-10.0))
    doc = sheet3(cam, "ru", TITLE).doc
    check_layout(doc)
    roller_circles_match_json(doc, cam)
    f = fields(doc)["profile"]
    k = f["scale"]
    at_o = [e.dxf.radius / k for e in doc.modelspace().query("CIRCLE")
            if math.dist((e.dxf.center.x, e.dxf.center.y), f["origin"]) < 1e-6]
    assert any(abs(r - 60.0) < 1e-6 for r in at_o), at_o
    assert any(abs(r - 10.0) < 1e-6 for r in at_o), at_o
    t = " ".join(texts(doc))
    assert "60,00 мм" in t and "-10,00 мм" in t or "−10,00 мм" in t


DECIMAL_POINT = re.compile(r"\d\.\d")
DESIGNATION = re.compile(r"ТММ(\.\d\d)+")
SECTION = re.compile(r"(п\.|§)\s?\d+(\.\d+)+")  # the book's section «п. 1.3»: a number of a section, not a decimal


@pytest.mark.parametrize("which", ["sheet3-17", "sheet3-3", "sheet4", "sheet4-shift", "sheet4-two-stage"])
def test_russian_text_has_no_markup_and_decimal_commas(which):
    """Every TEXT/MTEXT entity of the sheet: no '_' (subscripts are real), no '.' between digits."""
    if which.startswith("sheet3"):
        doc = sheet3(design_cam(VARIANTS[int(which.split("-")[1])]), "ru", TITLE).doc
    else:
        kw = {"shift": (0.3, -0.3)} if which == "sheet4-shift" else {}
        crank = 40.0 if which == "sheet4-two-stage" else 220.0
        doc = sheet4(design_gears(600.0, crank, **kw), 7, "ru", TITLE).doc
    # the ESKD designation (ТММ.03.17.00.00) is the one text whose dots are not decimal points
    bad = [t for t in texts(doc) if "_" in t or (DECIMAL_POINT.search(SECTION.sub("", t)) and not DESIGNATION.fullmatch(t))]
    assert not bad, bad[:10]


def test_english_headings():
    """--lang en: English headings and labels everywhere outside the title block (ГОСТ 2.104 form 1
    keeps its standard Russian captions)."""
    tb_x, tb_y = 836.0 - 185.0, 5.0 + 55.0
    for doc, heading in ((sheet3(design_cam(VARIANTS[3]), "en", TITLE).doc, "CAM PROFILE SYNTHESIS"),
                         (sheet4(design_gears(600.0, 40.0, shift=(0.3, -0.3)), 7, "en", TITLE).doc, "SPUR GEAR MESH SYNTHESIS")):
        t = " ".join(texts(doc))
        assert heading in t
        rus = [t for e, t in zip(list(doc.modelspace().query("TEXT")) + list(doc.modelspace().query("MTEXT")), all_texts(doc))
               if not (e.dxf.insert.x >= tb_x - 1e-6 and e.dxf.insert.y <= tb_y) and re.search(r"[А-Яа-яЁё]", t)]
        assert not rus, rus[:10]
        # English numbers: decimal points, also in the scales (М 1:2,5 is M 1:2.5)
        assert not [x for x in texts(doc) if re.search(r"\d,\d", x) and not (x.startswith("ЮУрГУ"))], \
            [x for x in texts(doc) if re.search(r"\d,\d", x)][:10]


def test_write_sheets_forked_or_not_same_files(tmp_path, monkeypatch):
    """Sheet 3 drawn in a forked child (two cores) or here: the same files, the same drawing; a
    child that fails leaves sheet 3 to this process."""
    import os

    import tmm_cli.render.sheets as sheets
    from tmm_cli.project import run_project

    r = run_project(VARIANTS[3], crank_rpm=40.0)
    counts = {}
    parent = os.getpid()
    real = sheets.sheet3

    def failing_in_child(*a, **kw):
        if os.getpid() != parent:
            raise RuntimeError("child fails")
        return real(*a, **kw)

    for mode in ("here", "fork", "child-fails"):
        monkeypatch.setattr(sheets, "_fork_ok", (lambda: False) if mode == "here" else (lambda: True))
        monkeypatch.setattr(sheets, "sheet3", failing_in_child if mode == "child-fails" else real)
        d = tmp_path / mode
        d.mkdir()
        names = sheets.write_sheets(d, r, "ru", TITLE)
        assert sorted(names) == ["sheet3.dxf", "sheet3.pdf", "sheet4.dxf", "sheet4.pdf"]
        assert sorted(p.name for p in d.iterdir()) == sorted(names)
        counts[mode] = [len(ezdxf.readfile(d / n).modelspace()) for n in ("sheet3.dxf", "sheet4.dxf")]
    assert counts["here"] == counts["fork"] == counts["child-fails"]
