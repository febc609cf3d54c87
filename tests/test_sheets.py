"""The A1 sheets 3 and 4 (issue 10), checked from the written files.

Everything is read back from the DXF (ezdxf), the PDF (pypdf) and the exported CSV/JSON: the
field origin and scale are the XDATA the sheet stores on each field's heading, not numbers taken
from the code under test.
"""

from __future__ import annotations

import csv
import io
import json
import math
import re

import ezdxf
import numpy as np
import pytest
from click.testing import CliRunner
from sheet_check import all_texts  # noqa: E402  (re-exported: the other sheet tests import it from here)

from tmm_cli.cam.design import design_cam
from tmm_cli.cli import cli
from tmm_cli.gears.design import design_gears
from tmm_cli.render.data.cam import profile_csv
from tmm_cli.render.data.project import cam_document, gears_document
from tmm_cli.render.sheets import save_sheet, sheet3, sheet4
from tmm_cli.inputs.titleblock import TitleFields
from tmm_cli.variants import load_table

# ГОСТ 2.302 (written out here, independently of the code)
GOST = {"1:1", "1:2", "1:2,5", "1:4", "1:5", "1:10", "1:15", "1:20", "1:25", "1:40", "1:50", "1:75", "1:100",
        "2:1", "2,5:1", "4:1", "5:1", "10:1", "20:1", "40:1", "50:1", "100:1"}
FRAME = (20.0, 5.0, 836.0, 589.0)
VARIANTS = load_table()
TITLE = TitleFields(student="Иванов И. И.", group="П-243", teacher="Петров П. П.", org="ЮУрГУ, кафедра ТММ")
GEAR_CASES = {"1": 220.0, "2": 60.0, "1+1": 40.0}




def fields(doc) -> dict:
    """name -> dict(box, origin, scale, label) from the XDATA of the field headings."""
    out = {}
    for e in doc.modelspace():
        if e.has_xdata("TMM_FIELD"):
            tags = [t.value for t in e.get_xdata("TMM_FIELD")]
            out[tags[0]] = {"box": tuple(tags[1:5]), "origin": tuple(tags[5:7]), "scale": tags[7], "label": tags[8]}
    return out


def reopen(sheet, tmp_path, name):
    save_sheet(sheet, tmp_path, name, pdf=False)
    return ezdxf.readfile(tmp_path / f"{name}.dxf")


def check_layout(doc):
    """Frame, title block 185 × 55 at its lower right corner, fields inside and apart, ГОСТ scales."""
    msp = doc.modelspace()
    rects = []
    for e in msp.query("LWPOLYLINE[layer=='Рамка']"):
        pts = np.array([p[:2] for p in e.get_points()])
        if e.closed and len(pts) == 4:
            rects.append((pts[:, 0].min(), pts[:, 1].min(), pts[:, 0].max(), pts[:, 1].max()))
    assert any(np.allclose(r, FRAME) for r in rects), rects
    tb = (FRAME[2] - 185.0, FRAME[1], FRAME[2], FRAME[1] + 55.0)
    assert any(np.allclose(r, tb) for r in rects), rects
    fl = fields(doc)
    boxes = [f["box"] for f in fl.values()]
    assert len(boxes) >= 4
    for b in boxes:
        assert FRAME[0] <= b[0] < b[2] <= FRAME[2] and FRAME[1] <= b[1] < b[3] <= FRAME[3]
        # no field under the title block
        assert not (b[2] > tb[0] and b[0] < tb[2] and b[1] < tb[3] and b[3] > tb[1])
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            assert a[2] <= b[0] or b[2] <= a[0] or a[3] <= b[1] or b[3] <= a[1], (a, b)
    for f in fl.values():
        if f["label"]:
            assert f["label"] in GOST
    texts = " ".join(all_texts(doc))
    for lab in re.findall(r"М (\d+(?:,\d+)?:\d+(?:,\d+)?)", texts):
        assert lab in GOST, lab
    assert not doc.audit().has_errors
    return fl


def profile_matches_csv(doc, cam) -> None:
    f = fields(doc)["profile"]
    ox, oy = f["origin"]
    k = f["scale"]
    rows = list(csv.DictReader(io.StringIO(profile_csv(cam))))
    want = {"inner": np.array([[float(r["inner_x_mm"]), float(r["inner_y_mm"])] for r in rows])}
    if "outer_x_mm" in rows[0]:
        want["outer"] = np.array([[float(r["outer_x_mm"]), float(r["outer_y_mm"])] for r in rows])
    polys = [e for e in doc.modelspace().query("LWPOLYLINE[layer=='Основные']") if len(e) == len(rows)]
    for name, ref in want.items():
        ok = False
        for e in polys:
            pts = np.array([p[:2] for p in e.get_points()])
            if len(pts) == len(ref):
                back = (pts - np.array([ox, oy])) / k
                if np.abs(back - ref).max() < 0.01:
                    ok = True
                    break
        assert ok, f"{name} profile not found at the field's scale"


def test_sheet3_variant_1_file(tmp_path):
    cam = design_cam(VARIANTS[1])
    doc = reopen(sheet3(cam, "ru", TITLE), tmp_path, "sheet3")
    fl = check_layout(doc)
    assert set(fl) >= {"motion", "zone", "profile", "pressure"}
    profile_matches_csv(doc, cam)
    texts = all_texts(doc)
    assert "ТММ.03.01.00.00" in texts and "Иванов И. И." in texts
    # the linetypes are the standard ones, the lineweights 0.7 / 0.25
    assert doc.layers.get("Осевые").dxf.linetype == "CENTER"
    assert doc.layers.get("Основные").dxf.lineweight == 70 and doc.layers.get("Тонкие").dxf.lineweight == 25


@pytest.mark.parametrize("number", sorted(VARIANTS))
def test_sheet3_every_variant(number):
    cam = design_cam(VARIANTS[number])
    doc = sheet3(cam, "ru", TITLE).doc
    fl = check_layout(doc)
    profile_matches_csv(doc, cam)
    f = fl["profile"]
    x0, y0, x1, y1 = f["box"]
    ox, oy = f["origin"]
    k = f["scale"]
    # the whole working profile and (rocker) the pivot circle lie inside the profile field
    pts = [cam.profile.inner * 1000.0 * k + (ox, oy)]
    if cam.sizing.l_oc_m is not None:
        R = cam.sizing.l_oc_m * 1000.0 * k
        pts.append(np.array([[ox - R, oy - R], [ox + R, oy + R]]))
    pts = np.vstack(pts)
    assert x0 <= pts[:, 0].min() and pts[:, 0].max() <= x1 and y0 <= pts[:, 1].min() and pts[:, 1].max() <= y1
    # drawn at the core's scale (CamResult.drawing: the note states the same)
    assert f["label"] == cam.drawing.scale and abs(k - 0.001 / cam.drawing.k_sk) < 1e-12
    roller_circles_match_json(doc, cam)


def roller_circles_match_json(doc, cam, lang="ru"):
    """The roller circles in the profile field have the radius the exported JSON carries
    (roller_mm: 0.2·r0, 0.8·ρ_min or the student's) × the field's scale; the book's 0.2·r0 is not
    drawn as a roller when another rule gave the roller; the table names the rule."""
    js = json.loads(json.dumps(cam_document(cam.variant, cam, lang)))["cam"]
    roller, book, rule = js["roller_mm"], js["roller_book_mm"], js["roller_rule_applied"]
    f = fields(doc)["profile"]
    x0, y0, x1, y1 = f["box"]
    k = f["scale"]
    inside = [e for e in doc.modelspace().query("CIRCLE")
              if x0 < e.dxf.center.x < x1 and y0 < e.dxf.center.y < y1
              and math.dist((e.dxf.center.x, e.dxf.center.y), f["origin"]) > 1e-6]
    rollers = [e for e in inside if abs(e.dxf.radius - roller * k) < 1e-3 * k]
    assert len(rollers) >= 4, (roller, sorted({round(e.dxf.radius / k, 3) for e in inside}))
    if abs(book - roller) > 0.05:
        assert not [e for e in inside if abs(e.dxf.radius - book * k) < 1e-3 * k]
    texts = "".join(all_texts(doc))
    want = {"book": "0,2·r", "limited": "0,8·ρ", "student": "задан"}[rule]
    assert want in texts


@pytest.mark.parametrize("scheme", sorted(GEAR_CASES))
def test_sheet4_schemes(scheme, tmp_path):
    g = design_gears(600.0, GEAR_CASES[scheme])
    assert g.scheme == scheme
    doc = reopen(sheet4(g, 7, "ru", TITLE), tmp_path, "sheet4")
    fl = check_layout(doc)
    assert set(fl) >= {"scheme", "angular", "assembly", "mesh", "table"}  # linear velocities beside the scheme
    mesh_matches_json(doc, g)
    texts = all_texts(doc)
    assert "ТММ.04.07.00.00" in texts


def mesh_matches_json(doc, g, variant=None):
    """The tip circles of both wheels in the mesh field have the radius d_a/2 × scale, with d_a read
    from the exported JSON (gears.spur.da_mm: the real, shifted tip circles), centred on O1 (the
    field's origin) and O2 at a_w × scale above it (gears.spur.a_w_mm)."""
    v = variant or VARIANTS[7]
    sp = json.loads(json.dumps(gears_document(v, g, "ru")))["gears"]["spur"]
    f = fields(doc)["mesh"]
    k = f["scale"]
    ox, oy = f["origin"]
    centres = ((ox, oy), (ox, oy + sp["a_w_mm"] * k))  # the line of centres is vertical, O1 below
    for j, c in enumerate(centres):
        ra = sp["da_mm"][j] / 2 * k
        found = [e for e in doc.modelspace().query("ARC CIRCLE")
                 if math.dist((e.dxf.center.x, e.dxf.center.y), c) < 1e-4 and abs(e.dxf.radius - ra) < 1e-4]
        assert found, f"tip circle of gear {j + 1} (d_a = {sp['da_mm'][j]}) not drawn at a_w × scale"
    return sp


def test_long_title_text_is_fitted():
    long = TitleFields(student="Константинопольский-Старобогатырёв Вениамин Вениаминович", org="Южно-Уральский государственный университет (национальный исследовательский университет), кафедра теоретической механики и основ проектирования машин")
    sh = sheet3(design_cam(VARIANTS[2]), "ru", long)
    doc = sh.doc
    # every text of the title block stays inside the block; the long ones inside their cells — with
    # the room of a CAD program's 30 % wider font (paper.ROOM), about the text's DXF alignment
    from tmm_cli.render.sheets.paper import ROOM

    X, Y = 836.0 - 185.0, 5.0
    for e in doc.modelspace().query("TEXT"):
        k = {1: 0.5, 2: 1.0}.get(e.dxf.halign, 0.0)
        w = sh.text_width(e.dxf.text, e.dxf.height, e.dxf.width) * ROOM
        x = (e.dxf.align_point.x if k else e.dxf.insert.x) - k * w
        y = e.dxf.insert.y
        if x >= X and y <= Y + 55.0:
            assert x + w <= X + 185.0 + 1e-6
            assert Y <= y and y + e.dxf.height <= Y + 55.0 + 1e-6
        if e.dxf.text.startswith("Константинопольский"):  # column "Фамилия", x 17…40, row 25…30
            assert X + 17.0 < x and x + w < X + 40.0 and Y + 25.0 < y and y + e.dxf.height < Y + 30.0
        if "Южно-Уральский" in e.dxf.text or "кафедра" in e.dxf.text:  # organisation cell 135…185 × 0…15
            assert X + 135.0 < x and x + w < X + 185.0 and Y < y and y + e.dxf.height < Y + 15.0


def test_pdf_page_is_a1(tmp_path):
    from pypdf import PdfReader

    g = design_gears(600.0, 40.0)
    names = save_sheet(sheet4(g, 3, "ru", TITLE), tmp_path, "sheet4")
    assert names == ["sheet4.dxf", "sheet4.pdf"]
    page = PdfReader(tmp_path / "sheet4.pdf").pages[0]
    w = float(page.mediabox.width) * 25.4 / 72
    h = float(page.mediabox.height) * 25.4 / 72
    assert abs(w - 841.0) <= 0.5 and abs(h - 594.0) <= 0.5


def test_project_writes_sheets_and_no_sheets_skips(tmp_path):
    from pypdf import PdfReader

    run = CliRunner().invoke(cli, ["project", "-v", "4", "--out", str(tmp_path), "--no-plots", "--lang", "ru",
                                   "--student", "Петров П. П."])
    assert run.exit_code == 0, run.output
    folder = tmp_path / "variant-04"
    for n in ("sheet3.dxf", "sheet3.pdf", "sheet4.dxf", "sheet4.pdf"):
        assert (folder / n).is_file()
    page = PdfReader(folder / "sheet3.pdf").pages[0]
    assert abs(float(page.mediabox.width) * 25.4 / 72 - 841.0) <= 0.5
    doc = ezdxf.readfile(folder / "sheet3.dxf")
    assert not doc.audit().has_errors
    # the written profile equals the written CSV (form closure: both walls of the groove)
    cam_csv = (folder / "cam_profile.csv").read_text(encoding="utf-8")
    cam = design_cam(VARIANTS[4])
    assert cam_csv == profile_csv(cam)
    profile_matches_csv(doc, cam)
    assert json.loads((folder / "results.json").read_text(encoding="utf-8"))["variant"] == 4
    run = CliRunner().invoke(cli, ["project", "-v", "4", "--out", str(tmp_path), "--no-plots", "--no-sheets"])
    assert run.exit_code == 0, run.output
    assert not list(folder.glob("sheet*"))  # a run without sheets leaves no stale ones


def test_cam_and_gears_sheets_flag(tmp_path):
    run = CliRunner().invoke(cli, ["cam", "-v", "3", "--out", str(tmp_path), "--no-plots", "--sheets"])
    assert run.exit_code == 0, run.output
    run = CliRunner().invoke(cli, ["gears", "-v", "3", "--out", str(tmp_path), "--no-plots", "--sheets", "--crank-rpm", "60"])
    assert run.exit_code == 0, run.output
    names = {p.name for p in (tmp_path / "variant-03").iterdir()}
    assert {"sheet3.dxf", "sheet3.pdf", "sheet4.dxf", "sheet4.pdf"} <= names
    run = CliRunner().invoke(cli, ["cam", "-v", "3", "--out", str(tmp_path), "--no-plots"])
    assert run.exit_code == 0
    assert not (tmp_path / "variant-03" / "sheet3.dxf").exists()


def test_batch_sheets_only_on_request(tmp_path):
    base = ["batch", "--variants", "3", "--jobs", "1", "--no-plots", "--report", "none"]
    run = CliRunner().invoke(cli, base + ["--out", str(tmp_path / "a")])
    assert run.exit_code == 0, run.output
    assert not list((tmp_path / "a").rglob("sheet*"))
    run = CliRunner().invoke(cli, base + ["--out", str(tmp_path / "b"), "--sheets"])
    assert run.exit_code == 0, run.output
    assert {p.name for p in (tmp_path / "b").rglob("sheet*")} == {"sheet3.dxf", "sheet3.pdf", "sheet4.dxf", "sheet4.pdf"}
