"""Issue 19: nothing of the user's is lost, nothing outside its folder is read or written.

The output folder (manifest with hashes and writers, the user's edits kept, commands sharing a
folder, a batch never taking over), temporaries and links, the note's typst root and process, the
files a user gives (FIFOs, sizes, blank lines), and output failures in the shell. Each test fails
on the code before issue 19.
"""

import errno
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from cli_helpers import group_gone, wait_for
from click.testing import CliRunner

from tmm_cli.cli import cli

MANIFEST = ".tmm-files.json"
POSIX = pytest.mark.skipif(sys.platform == "win32", reason="POSIX files and signals")


def run(*args, **kw):
    return CliRunner().invoke(cli, [str(a) for a in args], **kw)


def one_line_error(res, *words, code=2):
    assert res.exit_code == code, (res.exit_code, res.output)
    err = res.stderr.strip()
    assert "Traceback" not in res.output and len(err.splitlines()) == 1 and err.startswith("tmm: error:"), err
    for w in words:
        assert w in err, (w, err)
    return err


def tmm(*args, cwd=None, env=None, **kw):
    """`tmm ARGS` as a real process (its own standard streams)."""
    full = dict(os.environ, MPLBACKEND="Agg", LANG="en_US.UTF-8", LC_ALL="", **(env or {}))
    return subprocess.run([sys.executable, "-m", "tmm_cli", *map(str, args)], cwd=cwd, env=full, capture_output=True,
                          **kw)


def no_temporaries(path: Path) -> bool:
    return not [p for p in path.rglob("*") if ".tmp-" in p.name or p.name.startswith(".out-")]


# the user's edits ------------------------------------------------------------------------------


def test_an_edited_note_is_kept_and_the_new_one_written_beside_it(tmp_path):
    folder = tmp_path / "variant-17"
    assert run("project", "--variant", 17, "--no-plots", "--no-sheets", "--out", tmp_path, "--lang", "en").exit_code == 0
    note = folder / "note.typ"
    note.write_text(note.read_text(encoding="utf-8") + "// my own paragraph\n", encoding="utf-8")
    mine = note.read_bytes()
    res = run("project", "--variant", 17, "--no-plots", "--no-sheets", "--out", tmp_path, "--lang", "en")
    assert res.exit_code == 0, res.stderr
    assert note.read_bytes() == mine  # the student's note stays
    assert (folder / "note.new.typ").is_file() and b"my own paragraph" not in (folder / "note.new.typ").read_bytes()
    said = " ".join(res.stdout.split())
    assert "note.typ was changed since tmm wrote it: kept as it is; the new version is note.new.typ" in said
    # once more: still kept, the new version replaced (it is ours and unchanged)
    assert run("project", "--variant", 17, "--no-plots", "--no-sheets", "--out", tmp_path).exit_code == 0
    assert note.read_bytes() == mine and not (folder / "note.new2.typ").exists()
    # --force: the edit goes to a backup, the file is tmm's again, the new version beside it goes
    res = run("project", "--variant", 17, "--no-plots", "--no-sheets", "--out", tmp_path, "--force", "--lang", "en")
    assert res.exit_code == 0 and "kept as note.typ.bak, then replaced (--force)" in " ".join(res.stdout.split())
    assert (folder / "note.typ.bak").read_bytes() == mine and b"my own paragraph" not in note.read_bytes()
    assert not (folder / "note.new.typ").exists()
    assert "note.typ.bak" not in json.loads((folder / MANIFEST).read_text())["files"]


def test_manifest_records_the_hash_and_the_writer_of_every_file(tmp_path):
    import hashlib

    assert run("gears", "--variant", 17, "--no-plots", "--out", tmp_path).exit_code == 0
    files = json.loads((tmp_path / "variant-17" / MANIFEST).read_text())["files"]
    assert set(files) == {"gears.json"}
    data = (tmp_path / "variant-17" / "gears.json").read_bytes()
    assert files["gears.json"] == {"sha256": hashlib.sha256(data).hexdigest(), "by": ["gears"]}


def test_cam_into_a_project_folder_takes_nothing_of_the_project_and_the_note_still_compiles(tmp_path):
    folder = tmp_path / "variant-17"
    assert run("project", "--variant", 17, "--out", tmp_path, "--lang", "en").exit_code == 0
    before = {p.name: p.read_bytes() for p in folder.iterdir() if p.name.startswith(("sheet3", "cam_"))}
    for extra in (("--no-plots",), ()):  # no figures, no --sheets: the project's stay
        res = run("cam", "--variant", 17, "--out", tmp_path, *extra)
        assert res.exit_code == 0, res.stderr
    after = {p.name for p in folder.iterdir()}
    assert set(before) <= after and {"sheet3.dxf", "sheet3.pdf", "note_cam_motion.svg"} <= after
    assert run("note", folder).exit_code == 0  # the note's figures are all there


def test_a_batch_never_takes_over_a_project_folder(tmp_path):
    assert run("project", "--variant", 17, "--no-plots", "--no-sheets", "--out", tmp_path, "--report", "md").exit_code == 0
    before = {p.name: p.read_bytes() for p in (tmp_path / "variant-17").iterdir()}
    res = run("batch", "--variants", "16-17", "--out", tmp_path, "--no-plots", "--lang", "en")
    one_line_error(res, "variant-17 holds the results of tmm project, not of a batch")
    assert {p.name: p.read_bytes() for p in (tmp_path / "variant-17").iterdir()} == before
    assert not (tmp_path / "variant-16").exists() and not (tmp_path / "summary.csv").exists()


def test_a_batch_selecting_nothing_removes_nothing(tmp_path):
    out = tmp_path / "o"
    roster = tmp_path / "r.csv"
    roster.write_text("student,variant\nIvanov,17\n", encoding="utf-8")
    assert run("batch", "--roster", roster, "--out", out, "--no-plots", "--report", "none").exit_code == 0
    before = sorted(str(p.relative_to(out)) for p in out.rglob("*"))
    summary = (out / "summary.csv").read_bytes()
    roster.write_text("student,variant\nIvanov,99\nPetrov,\n", encoding="utf-8")
    res = run("batch", "--roster", roster, "--out", out, "--no-plots", "--lang", "en")
    assert res.exit_code == 1 and "nothing was run" in res.stdout, res.output
    assert sorted(str(p.relative_to(out)) for p in out.rglob("*")) == before
    assert (out / "summary.csv").read_bytes() == summary


def test_a_summary_the_teacher_edited_is_kept(tmp_path):
    out = tmp_path / "o"
    assert run("batch", "--variants", "17", "--out", out, "--no-plots", "--report", "none").exit_code == 0
    (out / "summary.csv").write_text("my grades\n", encoding="utf-8")
    res = run("batch", "--variants", "16", "--out", out, "--no-plots", "--report", "none", "--lang", "en")
    assert res.exit_code == 0, res.output
    assert (out / "summary.csv").read_text(encoding="utf-8") == "my grades\n"
    assert "16" in (out / "summary.new.csv").read_text(encoding="utf-8-sig")
    assert "summary.new.csv" in " ".join(res.stdout.split())


def test_a_changed_file_is_never_deleted_as_stale(tmp_path):
    from tmm_cli.output.folder import remove_written_tree

    folder = tmp_path / "variant-17"
    assert run("project", "--variant", 17, "--out", tmp_path, "--report", "md", "--no-sheets").exit_code == 0
    (folder / "cam_motion.png").write_bytes(b"my retouched figure")
    assert run("project", "--variant", 17, "--out", tmp_path, "--report", "md", "--no-sheets", "--no-plots").exit_code == 0
    assert (folder / "cam_motion.png").read_bytes() == b"my retouched figure"  # no longer written, but the user's
    assert not (folder / "cam_zone.png").exists()  # ours, unchanged: gone
    assert remove_written_tree(tmp_path, "variant-17", "project") is False
    assert sorted(p.name for p in folder.iterdir()) == [MANIFEST, "cam_motion.png"]


# links and temporary names ---------------------------------------------------------------------


@POSIX
def test_planted_links_at_temporary_names_are_never_written_through(tmp_path):
    """The temporary names were predictable (``..tmm-files.json.tmp-PID``, ``.summary.csv.tmp-PID``):
    a link planted there sent the write elsewhere."""
    from tmm_cli.output.folder import write_manifest, write_owned

    victim = tmp_path / "victim.txt"
    victim.write_text("keep")
    folder = tmp_path / "f"
    folder.mkdir()
    pid = os.getpid()
    for name in (f".{MANIFEST}.tmp-{pid}", f".summary.csv.tmp-{pid}"):  # ..tmm-files.json.tmp-PID
        (folder / name).symlink_to(victim)
    write_manifest(folder, ["a.png"])
    write_owned(folder, "summary.csv", b"x,y\n")
    assert victim.read_text() == "keep"
    assert (folder / "summary.csv").read_bytes() == b"x,y\n"


def test_a_temporary_name_taken_by_a_link_is_skipped(tmp_path, monkeypatch):
    from tmm_cli.output import atomic

    victim = tmp_path / "victim.txt"
    victim.write_text("keep")
    planted = tmp_path / ".x.tmp-1-00000000"
    planted.symlink_to(victim)
    names = iter([planted])
    real = atomic.temp_name
    monkeypatch.setattr(atomic, "temp_name", lambda folder, name: next(names, None) or real(folder, name))
    atomic.atomic_write(tmp_path, "x", b"new")
    assert victim.read_text() == "keep" and (tmp_path / "x").read_bytes() == b"new" and planted.is_symlink()


@POSIX
def test_a_link_at_a_final_name_is_replaced_never_written_through(tmp_path):
    victim = tmp_path / "victim.json"
    victim.write_text("keep")
    folder = tmp_path / "variant-17"
    assert run("project", "--variant", 17, "--no-plots", "--no-sheets", "--out", tmp_path, "--report", "md").exit_code == 0
    (folder / "results.json").unlink()
    (folder / "results.json").symlink_to(victim)
    res = run("project", "--variant", 17, "--no-plots", "--no-sheets", "--out", tmp_path, "--report", "md")
    assert res.exit_code == 0 and victim.read_text() == "keep"
    assert (folder / "results.json").is_symlink() and (folder / "results.new.json").is_file()
    res = run("project", "--variant", 17, "--no-plots", "--no-sheets", "--out", tmp_path, "--report", "md", "--force")
    assert res.exit_code == 0 and victim.read_text() == "keep"
    assert (folder / "results.json.bak").is_symlink() and not (folder / "results.json").is_symlink()


@POSIX
def test_a_batch_never_follows_a_student_folder_linked_out_of_its_out(tmp_path):
    out, elsewhere = tmp_path / "o", tmp_path / "elsewhere"
    out.mkdir()
    elsewhere.mkdir()
    (out / "Ivanov").symlink_to(elsewhere, target_is_directory=True)
    roster = tmp_path / "r.csv"
    roster.write_text("student,variant\nIvanov,17\nPetrov,16\n", encoding="utf-8")
    res = run("batch", "--roster", roster, "--out", out, "--no-plots", "--report", "none", "--lang", "en")
    assert res.exit_code == 1, res.output
    assert list(elsewhere.iterdir()) == []
    assert "symbolic link" in " ".join(res.stdout.split())
    assert (out / "Petrov" / "variant-16" / "results.json").is_file()


# the note: typst's root, its process -----------------------------------------------------------


@pytest.fixture
def note_folder(tmp_path):
    assert run("project", "--variant", 17, "--out", tmp_path, "--no-sheets", "--no-plots").exit_code == 0
    return tmp_path / "variant-17"


@POSIX
def test_tmm_note_reads_no_link_and_echoes_no_content(note_folder, tmp_path):
    secret = tmp_path / "secret.txt"
    secret.write_text("hunter2-password")
    (note_folder / "data.txt").symlink_to(secret)
    note = note_folder / "note.typ"
    note.write_text(note.read_text(encoding="utf-8") + '\n#eval(read("data.txt"))\n', encoding="utf-8")
    res = run("--lang", "en", "note", note_folder)
    one_line_error(res, "could not be typeset", "data.txt")
    assert "hunter2" not in res.output
    assert no_temporaries(note_folder)
    (note_folder / "data.txt").unlink()
    (note_folder / "data.txt").write_text("1 + 1")  # a regular file of the folder is the note's to use
    assert run("note", note_folder).exit_code == 0


@POSIX
def test_a_hostile_note_meets_the_memory_limit_with_one_line(note_folder, monkeypatch):
    from tmm_cli import limits

    monkeypatch.setattr(limits, "TYPST_MEMORY_BYTES", 256 << 20)
    note = note_folder / "note.typ"
    note.write_text("#let a = range(60000000)\n#a.map(x => x + 1).len()\n", encoding="utf-8")
    t0 = time.monotonic()
    res = run("--lang", "en", "note", note_folder)
    one_line_error(res, "could not be typeset", "memory", "256 MiB")
    assert time.monotonic() - t0 < 30
    assert "backtrace" not in res.output and no_temporaries(note_folder)


@POSIX
def test_ctrl_c_ends_a_long_compile_within_a_second(note_folder):
    note = note_folder / "note.typ"
    note.write_text("#let x = 0\n#for i in range(200000000) { x += 1 }\n#x\n", encoding="utf-8")
    p = subprocess.Popen([sys.executable, "-m", "tmm_cli", "--lang", "en", "note", str(note_folder)],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True,
                         env=dict(os.environ, LANG="en_US.UTF-8"))
    # typst is compiling once the private root holds the note
    assert wait_for(lambda: any(p.name.startswith(".note.tmp-") for p in note_folder.iterdir()) or p.poll() is not None)
    time.sleep(0.5)
    assert p.poll() is None
    t0 = time.monotonic()
    os.killpg(p.pid, signal.SIGINT)  # Ctrl-C in a terminal signals the whole group
    _, err = p.communicate(timeout=30)
    assert time.monotonic() - t0 < 1.5, time.monotonic() - t0
    assert p.returncode == 130 and err.decode().strip() == "tmm: interrupted"
    assert wait_for(lambda: group_gone(p.pid), 5) and no_temporaries(note_folder)




# files the user gives --------------------------------------------------------------------------


@POSIX
@pytest.mark.parametrize("what", ["answers", "roster", "toml"])
def test_a_fifo_is_refused_at_once(tmp_path, what):
    fifo = tmp_path / ("tmm.toml" if what == "toml" else "x.csv")
    os.mkfifo(fifo)
    args = {"answers": ["check", "--variant", 17, "--answers", fifo],
            "roster": ["batch", "--roster", fifo, "--out", tmp_path / "o"],
            "toml": ["cam", "--variant", 17, "--no-plots", "--out", tmp_path / "o"]}[what]
    res = tmm("--lang", "en", *args, cwd=tmp_path, timeout=20)  # it hung, waiting for a writer
    assert res.returncode == 2 and b"not a regular file" in res.stderr, res.stderr
    assert len(res.stderr.decode().strip().splitlines()) == 1


def test_sixty_four_kib_of_blank_lines_read_in_linear_time(tmp_path):
    from tmm_cli.inputs.tables import rows

    text = "r0_mm,41\n" + "\n" * (64 * 1024 - 10)
    t0 = time.perf_counter()
    got = rows(text, 200, "answers file a.csv")
    assert time.perf_counter() - t0 < 1.0  # 24 s before: each row counted all rows before it
    assert got[0] == ["r0_mm", "41"] and len(got) > 60000


def test_tmm_toml_size_is_checked_before_reading(tmp_path, monkeypatch):
    import tracemalloc

    from tmm_cli.errors import TmmError
    from tmm_cli.inputs.titleblock import load_settings

    with open(tmp_path / "tmm.toml", "wb") as fh:  # 200 MB, sparse: nothing to read but its size
        fh.truncate(200 << 20)
    tracemalloc.start()
    with pytest.raises(TmmError, match="64 KiB"):
        load_settings(tmp_path)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert peak < 1 << 20, peak  # it was read whole first


@pytest.mark.parametrize("content", ["year = " + "2" * 5000, "year = 20260"])
def test_tmm_toml_absurd_year_is_one_line(tmp_path, monkeypatch, content):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "tmm.toml").write_text(content + "\n", encoding="utf-8")
    one_line_error(run("cam", "--variant", 17, "--no-plots", "--out", tmp_path / "o", "--lang", "en"), "tmm.toml")
    assert not (tmp_path / "o").exists()


@pytest.mark.parametrize("name", ["COM¹", "LPT²", "com³.txt", "CONIN$", "Lpt1"])
def test_windows_device_names_get_a_safe_folder_name(name):
    from tmm_cli.inputs.names import file_name

    assert file_name(name).startswith("student-")


# output failures in the shell ------------------------------------------------------------------


@POSIX
def test_closed_stdout_is_one_line(tmp_path):
    res = subprocess.run([sys.executable, "-m", "tmm_cli", "--lang", "en", "project", "--variant", "17", "--no-plots",
                          "--out", str(tmp_path / "o")], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                         preexec_fn=lambda: os.close(1), env=dict(os.environ, MPLBACKEND="Agg"))
    err = res.stderr.decode().strip()
    assert res.returncode == 2 and len(err.splitlines()) == 1 and "standard output is closed" in err, err
    assert not (tmp_path / "o").exists()


def test_a_narrow_encoding_prints_what_it_can_hold(tmp_path):
    res = tmm("--lang", "ru", "gears", "--variant", 17, "--no-plots", "--out", tmp_path / "o",
              env={"PYTHONIOENCODING": "cp1251"})
    assert res.returncode == 0, res.stderr.decode("cp1251", "replace")
    text = res.stdout.decode("cp1251")
    assert "Двигатель" in text and "e_a = g_a/p_b" in text and "n_д >= 3" in text  # ε_α, ≥ as near as cp1251 goes
    assert res.stderr == b""


def test_markup_in_a_path_is_printed_as_it_is(tmp_path):
    out = tmp_path / "o[/]x[bold]"
    res = run("gears", "--variant", 17, "--no-plots", "--out", out, "--lang", "en")
    assert res.exit_code == 0, res.output
    assert f"{out / 'variant-17'}" in " ".join(res.stdout.replace("\n", "").split())


@POSIX
@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="/dev/full")
def test_stdout_on_a_full_device_is_one_line(tmp_path):
    with open("/dev/full", "w") as full:
        res = subprocess.run([sys.executable, "-m", "tmm_cli", "--lang", "en", "gears", "--variant", "17", "--no-plots",
                              "--out", str(tmp_path / "o")], stdout=full, stderr=subprocess.PIPE,
                             env=dict(os.environ, MPLBACKEND="Agg"))
    assert res.returncode == 2 and res.stderr.decode().strip() == (
        "tmm: error: cannot write standard output (No space left on device)")


@POSIX
def test_a_closed_pipe_is_silent(tmp_path):
    p = subprocess.Popen([sys.executable, "-m", "tmm_cli", "--lang", "en", "gears", "--variant", "17", "--no-plots",
                          "--out", str(tmp_path / "o")], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         env=dict(os.environ, MPLBACKEND="Agg"))
    p.stdout.readline()
    p.stdout.close()  # `| head -1`
    err = p.stderr.read()
    assert p.wait(timeout=60) == 1 and err == b"", err


def test_a_full_disk_while_writing_is_one_line_and_no_file(tmp_path, monkeypatch):
    import tmm_cli.render.data.jsontext as jsontext

    def full(path, doc):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(jsontext, "write_json", full)
    res = run("gears", "--variant", 17, "--no-plots", "--out", tmp_path / "o", "--lang", "en")
    one_line_error(res, "No space left on device")
    assert not (tmp_path / "o").exists() or not [p for p in (tmp_path / "o").rglob("*") if p.is_file()]


def test_a_path_too_long_is_one_line(tmp_path):
    deep = tmp_path.joinpath(*["d" * 200] * 25)
    one_line_error(run("gears", "--variant", 17, "--no-plots", "--out", deep, "--lang", "en"), "too long")
    one_line_error(run("gears", "--variant", 17, "--no-plots", "--out", tmp_path / ("x" * 300), "--lang", "en"),
                   "too long")
    assert list(tmp_path.iterdir()) == []


# absurd numbers ----------------------------------------------------------------------------------


LINKAGE = ["linkage", "--r1", 0.10, "--h", 0.04, "--c", 0, "--r2", 0.08, "--r3", 0.30, "--b", -0.04]


@pytest.mark.parametrize("args, words", [
    (["--rpm", "1e160"], ["--rpm", "10000"]),
    (["--omega", "1e308"], ["--omega", "1100"]),
    (["--rpm", "60", "--eps-crank", "1e300"], ["--eps-crank"]),
    (["--rpm", "60", "--r1", "1e-320"], ["--r1", "shortest length"]),
])
def test_absurd_linkage_numbers_are_refused(tmp_path, args, words):
    base = list(LINKAGE)
    if "--r1" in args:
        del base[1:3]
    one_line_error(run(*base, *args, "--out", tmp_path / "o", "--json", "--lang", "en"), *words)
    assert not (tmp_path / "o").exists()


def test_linkage_results_are_finite_or_an_error(tmp_path):
    """Validated after too: whatever passes the ranges gives numbers, never nulls."""
    from hypothesis import given, settings
    from hypothesis import strategies as st

    from tmm_cli.errors import TmmError
    from tmm_cli.linkage.analysis import analyse, finite_everywhere
    from tmm_cli.linkage.geometry import make_geometry

    lengths = st.floats(1e-4, 100.0)

    @settings(max_examples=60, deadline=None)
    @given(lengths, lengths, st.floats(-100, 100), lengths, lengths, st.floats(-100, 100), st.floats(0.01, 1100),
           st.floats(-1e6, 1e6))
    def prop(r1, h, c, r2, r3, b, omega, eps):
        try:
            result = analyse(make_geometry(r1, h, c, r2, r3, b), omega, eps, 12, 45.0)
        except TmmError:
            return
        assert finite_everywhere(result)

    prop()


@pytest.mark.parametrize("shift, words", [("5,5", ["root circle", "d_a", "d_f"]), ("10,-10", ["--shift", "x1 = 10"]),
                                          ("1.5,1.5", ["ε_α", "< 1"])])
def test_absurd_shifts_are_errors_with_the_reason(tmp_path, shift, words):
    one_line_error(run("gears", "--variant", 17, "--shift", shift, "--no-plots", "--out", tmp_path / "o", "--lang", "en"),
                   *words)
    assert not (tmp_path / "o").exists()


def test_the_pair_geometry_never_leaves_the_involute_s_domain():
    from tmm_cli.errors import TmmError
    from tmm_cli.gears.shifted import pair_geometry

    with pytest.raises(TmmError, match="base circle"):
        pair_geometry(24, 17, 20, 10, -10)  # math domain error before


@pytest.mark.parametrize("z_max", ["10000000", "1e7", "401"])
def test_planetary_tooth_limit_is_bounded(tmp_path, z_max):
    t0 = time.monotonic()
    one_line_error(run("planetary", "--ratio", "1/10", "--c", "26/25", "--z-max", z_max, "--out", tmp_path / "o",
                       "--no-plots", "--lang", "en"), "--z-max", "400")
    assert time.monotonic() - t0 < 5
