"""The command line, driven through click's CliRunner: exit codes, files, one-line errors."""

import csv
import json
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from tmm_cli.cli import cli
from tmm_cli.variants import COLUMNS
from cli_helpers import assert_one_line_error


def run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args])




def files_under(path: Path):
    return sorted(p.relative_to(path) for p in path.rglob("*")) if path.exists() else []


def test_help_is_instant_no_heavy_imports():
    code = "import sys, tmm_cli.cli; tmm_cli.cli.cli(['--help'], standalone_mode=False); " \
           "print(sorted(m for m in ('numpy', 'scipy', 'matplotlib', 'rich') if m in sys.modules))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip().splitlines()[-1] == "[]"


def test_variants_list_and_show():
    res = run("variants", "--lang", "en")
    assert res.exit_code == 0
    assert "Table 1.2" in res.output and "68" in res.output
    res = run("variants", "show", "17", "--lang", "ru")
    assert res.exit_code == 0
    assert "по часовой стрелке" in res.output and "φ_бс" in res.output and "150°" in res.output


@pytest.mark.parametrize("number, words", [("0", ["variant 0", "1 to 68"]), ("69", ["variant 69"]), ("abc", ["'abc'", "not a number"])])
@pytest.mark.parametrize("command", ["cam", "gears", "project"])
def test_unknown_variant(tmp_path, command, number, words):
    res = run(command, "--variant", number, "--out", tmp_path / "o")
    assert_one_line_error(res, *words)
    assert files_under(tmp_path / "o") == []


def _table(tmp_path, **over):
    row = dict(variant="1", scheme="1", l_bc_m="", nu_max_deg="25", n_cam_rpm="800", s_max_m="0.05",
               gamma_max_deg="", law="1", phi_rise_deg="100", phi_far_dwell_deg="20", phi_return_deg="100")
    row.update(over)
    cols = [c for c in COLUMNS if c in row]
    p = tmp_path / "table.csv"
    with open(p, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(cols)
        w.writerow([row[c] for c in cols])
    return p


@pytest.mark.parametrize(
    "over, words",
    [
        (dict(phi_rise_deg="200", phi_return_deg="150"), ["over 360"]),
        (dict(s_max_m="-0.05"), ["s_max_m", "positive"]),
        (dict(nu_max_deg="95"), ["nu_max_deg"]),
    ],
)
def test_bad_variants_file_rows(tmp_path, over, words):
    res = run("cam", "--variant", 1, "--variants-file", _table(tmp_path, **over), "--out", tmp_path / "o")
    assert_one_line_error(res, *words)
    assert files_under(tmp_path / "o") == []


def test_variants_file_missing_column(tmp_path):
    p = _table(tmp_path)
    text = p.read_text().splitlines()
    cells = [line.split(",") for line in text]
    idx = cells[0].index("law")
    p.write_text("\n".join(",".join(c[:idx] + c[idx + 1:]) for c in cells) + "\n")
    res = run("cam", "--variant", 1, "--variants-file", p, "--out", tmp_path / "o")
    assert_one_line_error(res, "missing column", "law")


def test_variants_file_not_found(tmp_path):
    res = run("variants", "--variants-file", tmp_path / "nope.csv")
    assert_one_line_error(res, "does not exist")


def test_unwritable_out(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("x")  # a file where a folder should be: unwritable even for root
    for command in ("cam", "gears", "project"):
        res = run(command, "--variant", 17, "--out", blocker / "sub", "--no-plots")
        assert_one_line_error(res, "cannot write", "--out")
    assert blocker.read_text() == "x"


def test_missing_option_is_one_line():
    res = run("cam")
    assert_one_line_error(res, "--variant")


@pytest.mark.parametrize("env, word", [({"LANG": "ru_RU.UTF-8"}, "Вариант"), ({"LANG": "en_US.UTF-8"}, "Variant")])
def test_language_defaults_to_the_locale(env, word):
    clean = {"LC_ALL": None, "LC_MESSAGES": None, "LANGUAGE": None, **env}
    res = CliRunner().invoke(cli, ["variants", "show", "17"], env=clean)
    assert res.exit_code == 0 and word in res.output


def test_json_output_is_only_json(tmp_path):
    res = run("cam", "--variant", 4, "--json", "--no-plots", "--out", tmp_path, "--lang", "ru")
    assert res.exit_code == 0
    doc = json.loads(res.output)  # nothing but JSON on stdout
    assert doc["variant"] == 4 and doc["cam"]["follower"] == "rocker" and doc["cam"]["e_mm"] is None
    assert json.loads((tmp_path / "variant-04" / "cam.json").read_text()) == doc


def test_rerun_never_mixes_two_runs(tmp_path):
    folder = tmp_path / "variant-02"
    assert run("cam", "--variant", 2, "--out", tmp_path).exit_code == 0
    assert run("gears", "--variant", 2, "--out", tmp_path, "--crank-rpm", 100).exit_code == 0
    names = {p.name for p in folder.iterdir()}
    assert {"cam.json", "gears.json", "cam_profile.png", "gears_mesh.png"} <= names
    assert run("cam", "--variant", 2, "--out", tmp_path, "--no-plots").exit_code == 0
    names = {p.name for p in folder.iterdir()}
    assert not any(n.startswith("cam_") and n.endswith(".png") for n in names)
    assert "gears_mesh.png" in names  # another command's files stay
    before = names - {"cam_profile.csv"}
    assert run("project", "--variant", 2, "--out", tmp_path, "--no-plots", "--no-sheets").exit_code == 0
    # commands sharing a folder own only their own files (issue 19): the project's are exactly its
    # own, and `tmm gears`'s and `tmm cam`'s stay until those commands drop them
    names = {p.name for p in folder.iterdir()}
    assert names - before == {"cam_profile.csv", "note-style.typ", "note.pdf", "note.typ", "results.json"}
    assert before <= names and "gears.json" in names
    assert run("gears", "--variant", 2, "--out", tmp_path, "--crank-rpm", 100, "--no-plots").exit_code == 0
    assert not any(n.startswith("gears_") for n in {p.name for p in folder.iterdir()})
