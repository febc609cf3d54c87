"""The DXF sheets as a CAD program without osifont prints them (issue 31).

LibreCAD 2.2 draws every text in its own stroke font (OpenGost Type B), about 30 % wider than
osifont. The sheets lay every text out with that room (``paper.ROOM``); here the real program
prints the sheet (``librecad dxf2pdf``), and the same sheet without its texts, and the difference
— the ink of the texts as LibreCAD sets them — is looked at: none outside the frame, none touching
a cell's side border in the title block (a name running over «Лит.», «Масштаб» crossing its
cell's line).
Also read from the DXF: no MTEXT code LibreCAD prints as text (``\\W``, ``\\H``, ``\\f`` …), the
zone of centres one HATCH of ANSI31.

Skipped, with the reason, where LibreCAD or poppler's pdftoppm is not installed
(``apt-get install librecad poppler-utils``); where it is absent the layout test
(tests/test_sheets_layout.py: ``problems(doc, room=ROOM)``) still measures every text 1.3× wide.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess

import numpy as np
import math

import pytest

from tmm_cli.inputs.titleblock import TitleFields
from tmm_cli.render.sheets import sheet3, sheet4
from tmm_cli.render.sheets.paper import FRAME, SHEET_H, SHEET_W, TB_BOX
from tmm_cli.variants import load_table

LIBRECAD = shutil.which("librecad")
PDFTOPPM = shutil.which("pdftoppm")
DPI = 100
MM = DPI / 25.4  # pixels per mm
# a title block with long fields: the surname must stay in its cell, the name wrap
TITLE = TitleFields(student="Константинопольский-Щербаковский К. К.", group="П-243", teacher="Петров П. П.",
                    org="ЮУрГУ, кафедра теории механизмов и машин")
UNREAD = re.compile(r"\\[WHQTACfFp]")  # MTEXT codes LibreCAD 2.2 prints as text


def _sheets():
    table = load_table()
    from tmm_cli.project import run_project

    r = run_project(table[23], crank_rpm=None, torque_nm=None)
    return {"sheet3": sheet3(r.cam, "ru", TITLE), "sheet4": sheet4(r.gears, 23, "ru", TITLE)}


def _print(dxf, folder) -> np.ndarray:
    """LibreCAD's print of `dxf` at 1:1 on A1 as a boolean ink raster (True: ink)."""
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
    subprocess.run([LIBRECAD, "dxf2pdf", "-s", "1", "-p", "841x594", dxf.name], cwd=folder, env=env, check=True,
                   capture_output=True, timeout=120)
    pdf = folder / (dxf.stem + ".pdf")
    stem = folder / dxf.stem
    subprocess.run([PDFTOPPM, "-r", str(DPI), "-gray", "-singlefile", str(pdf), str(stem)], check=True, timeout=120)
    from matplotlib.image import imread

    img = imread(str(stem) + ".pgm") if (folder / (dxf.stem + ".pgm")).exists() else None
    if img is None:
        raise AssertionError("pdftoppm wrote no raster")
    img = np.asarray(img, dtype=float)
    if img.max() > 1.0:
        img = img / 255.0
    return img < 0.6


def _px(x_mm, y_mm):
    """(column, row) of a sheet point [mm] in the raster."""
    return int(round(x_mm * MM)), int(round((SHEET_H - y_mm) * MM))


@pytest.fixture(scope="module")
def sheets():
    return _sheets()


@pytest.mark.parametrize("name", ["sheet3", "sheet4"])
def test_no_mtext_code_a_cad_program_prints_as_text(sheets, name):
    doc = sheets[name].doc
    bad = [e.text for e in doc.modelspace().query("MTEXT") if UNREAD.search(e.text)]
    assert not bad, bad[:5]


def test_the_zone_of_centres_is_one_hatch(sheets):
    hatches = sheets["sheet3"].doc.modelspace().query("HATCH")
    assert len(hatches) == 1
    h = hatches[0]
    assert h.dxf.layer == "Тонкие"
    # one family of parallel lines at the drawn spacing, 3 mm on paper: ANSI31 (3.175 mm apart at scale
    # 1) scaled, or — where the zone's line must pass through the cam's centre O (issue 32) — the same
    # family laid through O in the entity's own pattern definition, which every CAD program reads
    lines = h.pattern.lines
    assert len(lines) == 1
    offset = lines[0].offset
    spacing = abs(float(offset[0]) * -math.sin(math.radians(lines[0].angle))
                  + float(offset[1]) * math.cos(math.radians(lines[0].angle)))
    assert abs(spacing - 3.0) < 0.5, (h.dxf.pattern_name, spacing)
    assert not lines[0].dash_length_items  # solid lines, as ANSI31's


@pytest.mark.skipif(LIBRECAD is None or PDFTOPPM is None,
                    reason="LibreCAD or pdftoppm is not installed: apt-get install librecad poppler-utils")
@pytest.mark.parametrize("name", ["sheet3", "sheet4"])
def test_librecad_keeps_every_text_in_the_frame_and_off_the_title_block_lines(sheets, name, tmp_path):
    sh = sheets[name]
    full = tmp_path / f"{name}.dxf"
    sh.doc.saveas(full)
    import ezdxf

    bare_doc = ezdxf.readfile(full)
    msp = bare_doc.modelspace()
    for e in list(msp.query("TEXT MTEXT")):
        msp.delete_entity(e)
    bare = tmp_path / f"{name}-bare.dxf"
    bare_doc.saveas(bare)
    ink, lines = _print(full, tmp_path), _print(bare, tmp_path)
    assert ink.shape == lines.shape
    assert abs(ink.shape[1] - SHEET_W * MM) < 3 and abs(ink.shape[0] - SHEET_H * MM) < 3, ink.shape
    text = ink & ~lines  # the texts as LibreCAD draws them
    assert text.sum() > 5000  # it drew the texts
    # nothing outside the frame (0.5 mm inside its line)
    (c0, r1), (c1, r0) = _px(FRAME[0] + 0.5, FRAME[1] + 0.5), _px(FRAME[2] - 0.5, FRAME[3] - 0.5)
    outside = text.copy()
    outside[r0:r1, c0:c1] = False
    assert not outside.any(), f"{outside.sum()} text pixels outside the frame"
    # none running into a cell's side border in the title block: text ink within 0.45 mm of the
    # middle of a vertical grid line (a thick line is 0.7 mm wide: ink beside it touches it)
    rows, cols = np.nonzero(text)
    xs, ys = cols / MM, SHEET_H - rows / MM
    near_tb = (xs >= TB_BOX[0] - 1) & (ys <= TB_BOX[3] + 1)
    xs, ys = xs[near_tb], ys[near_tb]
    touching = []
    for e in msp.query("LINE LWPOLYLINE"):
        if e.dxftype() == "LINE":
            pts = np.array([[e.dxf.start.x, e.dxf.start.y], [e.dxf.end.x, e.dxf.end.y]])
        else:
            pts = np.array([p[:2] for p in e.get_points("xy")])
            pts = np.vstack([pts, pts[:1]]) if e.closed else pts
        if not ((pts[:, 0] >= TB_BOX[0] - 0.1).all() and (pts[:, 1] <= TB_BOX[3] + 0.1).all()):
            continue
        for a, b in zip(pts[:-1], pts[1:]):
            if abs(a[0] - b[0]) > 1e-6:  # the cells' side borders: a text runs over them sideways
                continue
            d = b - a
            t = np.clip(((xs - a[0]) * d[0] + (ys - a[1]) * d[1]) / max(d @ d, 1e-9), 0, 1)
            dist = np.hypot(xs - (a[0] + t * d[0]), ys - (a[1] + t * d[1]))
            if (dist < 0.45).any():
                touching.append(((round(a[0], 1), round(a[1], 1)), (round(b[0], 1), round(b[1], 1))))
    assert not touching, touching[:6]
