"""Every module's errors reach a Russian user in Russian: one line `tmm: ошибка: …`, exit 2, no
English sentence left in it; the same input under --lang en keeps its English line."""

import re

import pytest
from click.testing import CliRunner

from tmm_cli.cli import cli

CYRILLIC = re.compile("[А-Яа-яЁё]")
ENGLISH = re.compile(r"\b[A-Za-z]{2,} [A-Za-z]{2,} [A-Za-z]{2,}\b")  # three English words in a row


def run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args])


def _files(tmp_path):
    (tmp_path / "dup.csv").write_text("r0_mm,41\nr0_mm,42\n", encoding="utf-8")
    (tmp_path / "empty_roster.csv").write_text("student,variant\n", encoding="utf-8")
    (tmp_path / "nul_roster.csv").write_bytes(b"student,variant\nA\x00,17\n")
    table = (tmp_path / "table.csv")
    header = "variant,scheme,law,nu_max_deg,n_cam_rpm,l_bc_m,s_max_m,gamma_max_deg,phi_rise_deg,phi_far_dwell_deg,phi_return_deg"
    table.write_text(header + "\n1,7,1,30,1000,,0.05,,120,30,120\n", encoding="utf-8")
    (tmp_path / "link.toml").write_text("r1 = 0.1\nwheel = 3\n", encoding="utf-8")
    (tmp_path / "a_file").write_text("mine\n", encoding="utf-8")
    (tmp_path / "task.toml").write_text('type = "slotted-link"\nstroke = 0.4\ntime_ratio = 1.0\nframe = 0.3\n',
                                        encoding="utf-8")


# module → (arguments, a Russian fragment of the translated line); {t} is the test's folder
CASES = {
    "limits (option range)": (["gears", "-v", 17, "--crank-rpm", "abc"], "'abc' — не число; задайте число от 1 до 3000"),
    "limits (whole number)": (["gears", "-v", 17, "--planets", 0], "0 вне допустимого диапазона; задайте целое число"),
    "check": (["check", "-v", 17, "--answers", "{t}/dup.csv"], "ключ r0_mm встречается дважды"),
    "batch": (["batch", "--roster", "{t}/empty_roster.csv", "--out", "{t}/o"], "есть заголовок, но нет студентов"),
    "batch (--variants)": (["batch", "--variants", "5-2", "--out", "{t}/o"], "записан в обратном порядке"),
    "tabular": (["batch", "--roster", "{t}/nul_roster.csv", "--out", "{t}/o"], "не текстовый файл (в нём нулевые байты)"),
    "variants": (["cam", "-v", 1, "--variants-file", "{t}/table.csv", "--out", "{t}/o"], "схема 7; допустимы 1, 2, 3 или 4"),
    "files": (["cam", "-v", 17, "--out", "{t}/a_file/sub"], "— не папка); укажите папку в --out"),
    "click's Path": (["cam", "-v", 17, "--out", "{t}/a_file"], "/a_file' — это файл, а нужна папка"),
    "gears/shifted": (["gears", "-v", 17, "--shift", "x", "--out", "{t}/o"], "не удалось прочитать --shift"),
    "gears/shifted (a_w)": (["gears", "-v", 17, "--aw", 200, "--out", "{t}/o"], "межосевое расстояние a_w = 200 мм недостижимо"),
    "gears/aa_bar": (["planetary", "--ratio", "1/10", "--c", "3/2", "--out", "{t}/o"], "вне области существования"),
    "linkage/inputs": (["linkage", "--input", "{t}/link.toml", "--out", "{t}/o"], "неизвестный ключ 'wheel'"),
    "linkage/geometry": (["linkage", "--r1", -0.1, "--h", 0.04, "--r2", 0.08, "--r3", 0.3, "--b", -0.04, "--rpm", 60,
                          "--out", "{t}/o"], "длины должны быть положительными (кривошип O21A)"),
    "linkage/synthesis": (["synth", "{t}/task.toml", "--out", "{t}/o"], "кулисному механизму нужен K > 1"),
    "commands/linkage": (["linkage", "--r1", 0.1, "--out", "{t}/o"], "задайте --h M, --r2 M, --r3 M, --b M"),
    "render/note": (["project", "-v", 17, "--no-plots", "--note-template", "{t}/nope.typ", "--out", "{t}/o"],
                    "файл стиля записки"),
}


@pytest.mark.parametrize("case", list(CASES))
def test_error_in_russian_one_line_exit_2(case, tmp_path):
    _files(tmp_path)
    args, fragment = CASES[case]
    args = [str(a).replace("{t}", str(tmp_path)) for a in args]
    ru = run(*args, "--lang", "ru")
    assert ru.exit_code == 2, (case, ru.output)
    lines = ru.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("tmm: ошибка: "), (case, ru.stderr)
    line = lines[0].replace(str(tmp_path), "")
    assert fragment in line, (case, line)
    assert CYRILLIC.search(line[len("tmm: ошибка: "):]) and not ENGLISH.search(line), (case, line)
    en = run(*args, "--lang", "en")
    assert en.exit_code == 2 and en.stderr.startswith("tmm: error: ") and not CYRILLIC.search(
        en.stderr.replace("ошибка", "")), (case, en.stderr)
    assert not (tmp_path / "o").exists() or not [p for p in (tmp_path / "o").rglob("*") if p.is_file()]


def test_title_fields_file_error_in_russian(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "tmm.toml").write_text("student = 5\n", encoding="utf-8")
    ru = run("cam", "-v", 17, "--no-plots", "--out", tmp_path / "o", "--lang", "ru")
    assert ru.exit_code == 2
    assert ru.stderr.strip() == ("tmm: ошибка: tmm.toml: 'student' должно быть текстом в кавычках, например "
                                 "student = \"...\""), ru.stderr


def test_a_roster_rows_error_is_translated_inside_its_frame():
    from tmm_cli.i18n.errors import translate_error

    assert translate_error("roster line 3: the variant column is empty") == "список группы, строка 3: столбец варианта пуст"


# every message these modules raise, rebuilt from their source with each field set to 7 -------------
MODULES = ("limits", "teacher/check", "teacher/batch", "teacher/roster", "teacher/summary", "inputs/tables", "inputs/names", "variants", "inputs/titleblock",
           "output/folder", "output/lock", "inputs/files", "inputs/mechanism", "render/note/typeset", "teacher/workers",
           "gears/shifted", "gears/aa_bar", "linkage/inputs", "linkage/geometry", "linkage/analysis",
           "linkage/synthesis", "linkage/synthesis_task", "commands/synth",
           "render/note/__init__", "render/sheets/__init__",
           "commands/linkage", "commands/planetary", "commands/options", "commands/batch", "commands/check", "cli",
           "accuracy/card", "accuracy/carrier", "accuracy/chain_input", "accuracy/chain", "commands/carrier",
           "commands/chain", "commands/project", "project")


# modules whose messages reach the user behind the file's name ("task.toml: …", as _Reader.fail and
# synthesis_task.synthesise put it)
SOURCED = ("linkage/synthesis", "linkage/synthesis_task")


def _sample(node):
    import ast

    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    if isinstance(node, ast.JoinedStr):
        return "".join(v.value if isinstance(v, ast.Constant) else "7" for v in node.values)
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
        left, right = _sample(node.left), _sample(node.right)
        return None if left is None or right is None else left + right
    if isinstance(node, ast.IfExp):
        return _sample(node.body)
    return "7"


def _messages():
    import ast
    from pathlib import Path

    import tmm_cli

    root = Path(tmm_cli.__file__).parent
    for mod in MODULES:
        path = root / f"{mod}.py"
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Call) and node.args and (
                    (isinstance(node.func, ast.Name) and node.func.id == "TmmError")
                    or (isinstance(node.func, ast.Attribute) and node.func.attr == "fail")):
                text = _sample(node.args[0])
                if text and text.strip("7: "):  # not a frame of fields alone ("{source}: {exc}")
                    yield f"{mod}:{node.lineno}", (f"task.toml: {text}" if mod in SOURCED else text)


MESSAGES = list(_messages())


def test_the_scan_finds_the_messages():
    assert len(MESSAGES) > 100


@pytest.mark.parametrize("where,text", MESSAGES, ids=[w for w, _ in MESSAGES])
def test_every_message_has_a_russian_template(where, text):
    from tmm_cli.i18n.errors import translate_error

    ru = translate_error(text)
    assert ru != text and CYRILLIC.search(ru), f"{where}: no Russian for {text!r}; add its template to tmm.po (msgctxt \"error\")"
