"""«14,37 Н· м»: on a justified line typst stretched the gap after the bare product dot of a unit as
after a word (the abstract of variant 17 with the shaper: «движущий момент M_д = 71,62 Н· м;
маховик J_м = 116,73 кг· м²»). Read from the compiled note.pdf as a reader's copy-paste does
(poppler's pdftotext sees the gap as a space), not from the writer: no unit's «·» is followed or
preceded by a gap, and the units are still there."""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest
from click.testing import CliRunner

from tmm_cli.cli import cli

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"


@pytest.mark.skipif(shutil.which("pdftotext") is None, reason="poppler's pdftotext reads the PDF's gaps")
def test_a_units_dot_has_no_gap_in_the_compiled_note(tmp_path):
    res = CliRunner().invoke(cli, ["project", "--variant", "17", "--mechanism", str(EXAMPLES / "shaper.toml"),
                                   "--out", str(tmp_path), "--no-sheets", "--no-plots", "--lang", "ru"])
    assert res.exit_code == 0, res.output
    pdf = next(tmp_path.glob("variant-*")) / "note.pdf"
    text = subprocess.run(["pdftotext", str(pdf), "-"], capture_output=True, text=True, check=True).stdout
    gaps = re.findall(r".{0,30}[^\W\d_]·\s+[^\W\d_].{0,10}|.{0,30}[^\W\d_]\s+·[^\W\d_].{0,10}", text)
    assert not gaps, gaps
    # the abstract's units, whole (the line that had the gap)
    assert re.search(r"движущий момент 𝑀д = [\d,]+\s?Н·м; маховик 𝐽м = [\d,]+\s?кг·м²", text), text[:3000]
    assert len(re.findall(r"[^\W\d_]·[^\W\d_]", text)) >= 20
