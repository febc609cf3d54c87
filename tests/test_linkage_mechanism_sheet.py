"""The A1 sheet 1 of a mechanism file, read back from the DXF: the frame and the title block, the
fields apart and inside, a ГОСТ scale for the scheme equal to the core's μ_l, the plans at their
μ_v, μ_a, every text inside the frame; `--sheets` writes sheet1.dxf and .pdf."""

import tomllib
from pathlib import Path

import ezdxf
import pytest
from click.testing import CliRunner

from test_sheets import FRAME, TITLE, check_layout, reopen

from tmm_cli.cli import cli
from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.sheet1 import analyse_mechanism
from tmm_cli.render.sheets.linkage_sheet import sheet1

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"


def analysed(name):
    path = EXAMPLES / f"{name}.toml"
    return analyse_mechanism(parse_mechanism(tomllib.loads(path.read_text(encoding="utf-8")), path.name))


@pytest.mark.parametrize("name", ["compressor", "four_bar", "shaper", "whitworth"])
def test_sheet1_layout_scales_and_texts(name, tmp_path):
    s = analysed(name)
    doc = reopen(sheet1(s, "ru", TITLE), tmp_path, "sheet1")
    fl = check_layout(doc)
    assert fl["scheme"]["scale"] == pytest.approx(1.0 / (s.scheme_scale * 1000.0))
    for pl in s.plans:
        label = pl.position.label.replace("′", "'")
        assert fl[f"velocity_plan_{label}"]["scale"] == pytest.approx(1.0 / pl.velocity.scale)
        assert fl[f"acceleration_plan_{label}"]["scale"] == pytest.approx(1.0 / pl.acceleration.scale)
    for e in doc.modelspace().query("TEXT"):
        x, y = e.dxf.insert[0], e.dxf.insert[1]
        assert FRAME[0] <= x <= FRAME[2] and FRAME[1] <= y <= FRAME[3], e.dxf.text
    texts = " ".join(e.dxf.text for e in doc.modelspace().query("TEXT"))
    assert "ПЛАН ПОЛОЖЕНИЙ МЕХАНИЗМА" in texts and "ТММ.01.00.00.00" in texts


def test_linkage_sheets_flag(tmp_path):
    r = CliRunner().invoke(cli, ["linkage", str(EXAMPLES / "shaper.toml"), "--sheets", "--no-plots", "--out",
                                 str(tmp_path), "--lang", "en"])
    assert r.exit_code == 0, r.output
    folder = tmp_path / "linkage"
    assert (folder / "sheet1.dxf").is_file() and (folder / "sheet1.pdf").read_bytes().startswith(b"%PDF")
    assert "KINEMATIC ANALYSIS" in " ".join(e.dxf.text for e in ezdxf.readfile(folder / "sheet1.dxf").modelspace()
                                            .query("TEXT")).upper()
    r = CliRunner().invoke(cli, ["linkage", "--r1", "0.1", "--h", "0.04", "--r2", "0.08", "--r3", "0.3", "--b", "-0.04",
                                 "--rpm", "60", "--sheets", "--out", str(tmp_path / "w")])
    assert r.exit_code == 2 and "needs a mechanism file" in r.stderr
