"""The command line in Russian: every help text translated, click's own errors and ours in Russian
under --lang ru or a Russian locale, English again afterwards (one process runs both)."""

import re

import click
import pytest
from click.testing import CliRunner

from tmm_cli.cli import cli
import inspect

from tmm_cli.i18n import tr
from tmm_cli.i18n.errors import _mo_entries, translate_error

CYRILLIC = re.compile("[А-Яа-яЁё]")


def _commands(cmd=cli, path="tmm"):
    yield path, cmd
    if isinstance(cmd, click.Group):
        for name, sub in cmd.commands.items():
            yield from _commands(sub, f"{path} {name}")


ALL = list(_commands())


def run(*args, env=None):
    runner = CliRunner()
    return runner.invoke(cli, [str(a) for a in args], env=env or {})


@pytest.mark.parametrize("path,cmd", ALL, ids=[p for p, _ in ALL])
def test_every_option_has_a_russian_help(path, cmd):
    """A new option or command without a Russian help in the catalogue fails here: run
    `python tools/catalog.py` and translate the new msgids in tmm.po."""
    missing = [p.name for p in cmd.params if getattr(p, "help", None) and not CYRILLIC.search(tr("ru", p.help))]
    assert not missing, f"{path}: no Russian help for {missing} in tmm_cli/i18n/locale/ru/LC_MESSAGES/tmm.po"
    assert CYRILLIC.search(tr("ru", inspect.cleandoc(cmd.help or ""))), f"{path}: no Russian help text in tmm.po"


@pytest.mark.parametrize("path,cmd", ALL, ids=[p for p, _ in ALL])
def test_help_of_every_command_in_russian(path, cmd):
    args = path.split()[1:] + ["--help"]
    res = run("--lang", "ru", *args)  # before the command: the stubs have no --lang of their own
    assert res.exit_code == 0, res.output
    out = res.output
    assert out.startswith("Использование:")
    assert "Параметры:" in out and "Показать эту справку и выйти." in out
    assert "Options:" not in out and "Show this message" not in out
    for p in cmd.params:
        if getattr(p, "help", None) and not getattr(p, "hidden", False):
            first = " ".join(tr("ru", p.help).split()[:2])
            assert first in " ".join(out.split()), (path, p.name)


def test_defaults_in_russian_help_take_a_decimal_comma():
    ru = " ".join(run("--lang", "ru", "project", "--help").output.split())
    assert "[по умолчанию: 5,0]" in ru and "5.0]" not in ru  # --tolerance
    assert "[по умолчанию: png]" in ru and "./tmm-out" in ru  # words and paths untouched
    en = " ".join(run("--lang", "en", "project", "--help").output.split())
    assert "[default: 5.0]" in en


def test_help_language_from_the_locale_then_english_again():
    ru = run("project", "--help", env={"LC_ALL": None, "LC_MESSAGES": None, "LANG": "ru_RU.UTF-8"})
    assert "Номер варианта по табл. 1.2" in ru.output
    en = run("project", "--help", env={"LC_ALL": None, "LC_MESSAGES": None, "LANG": "en_US.UTF-8"})
    assert "Variant number from Table 1.2" in en.output and "Номер" not in en.output
    assert "Show this message and exit." in en.output  # click's cached help option is English again
    # --lang on the command line wins over the locale
    en2 = run("project", "--help", "--lang", "en", env={"LANG": "ru_RU.UTF-8", "LC_ALL": None})
    assert "Usage:" in en2.output and "Variant number" in en2.output


@pytest.mark.parametrize("args,expected", [
    (["project"], "Не задан параметр '--variant'"),
    (["project", "--variant", 17, "--format", "jpg"], "Недопустимое значение '--format'"),
    # click < 8.4 says "No such option: --bogus", 8.4 "No such option '--bogus'.": both are in tmm.po
    (["project", "--variant", 17, "--bogus"], re.compile(r"Нет такого параметра:? '?--bogus")),
    (["project", "--variant", 17, "extra"], "Лишний аргумент (extra)"),
    (["gears", "--variant", 17, "--crank-rpm", "abc"], "'abc' — не число"),
    (["frobnicate"], "Нет такой команды 'frobnicate'"),
])
def test_click_errors_in_russian(args, expected, tmp_path):
    res = run(*args, "--out", tmp_path, "--lang", "ru") if args[0] != "frobnicate" else run("--lang", "ru", *args)
    assert res.exit_code == 2
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("tmm: ошибка: "), res.stderr
    assert (expected.search(lines[0]) if isinstance(expected, re.Pattern) else expected in lines[0]), lines[0]
    assert not list(tmp_path.iterdir())


def test_our_errors_in_russian_and_english(tmp_path):
    ru = run("project", "--variant", 99, "--out", tmp_path, "--lang", "ru")
    assert ru.exit_code == 2
    assert ru.stderr.strip() == "tmm: ошибка: варианта 99 нет в таблице; выберите вариант от 1 до 68"
    en = run("project", "--variant", 99, "--out", tmp_path, "--lang", "en")
    assert en.stderr.strip() == "tmm: error: variant 99 is not in the table; choose a variant from 1 to 68"
    # since the option limits (docs/limits.md) click refuses -5 before the core sees it: its range, in Russian
    ru = run("gears", "--variant", 17, "--crank-rpm", -5, "--out", tmp_path, "--lang", "ru")
    assert ru.exit_code == 2
    assert ru.stderr.strip() == ("tmm: ошибка: Недопустимое значение '--crank-rpm': -5 вне допустимого диапазона; "
                                 "задайте число от 1 до 3000 (docs/limits.md)")
    en = run("gears", "--variant", 17, "--crank-rpm", -5, "--out", tmp_path, "--lang", "en")
    assert en.stderr.strip() == ("tmm: error: Invalid value for '--crank-rpm': -5 is out of range; give a number "
                                 "from 1 to 3000 (docs/limits.md)")


def test_lang_before_the_command_reaches_it(tmp_path):
    res = run("--lang", "ru", "variants", "show", 3)
    assert res.exit_code == 0 and "Вариант 3" in res.output


def test_error_catalogue_entries_are_russian_and_unknown_text_passes_through():
    errors = [(m.partition("\x04")[2], s) for m, s in _mo_entries("ru") if m.startswith("error\x04")]
    assert len(errors) > 150
    for template, russian in errors:
        assert CYRILLIC.search(russian), template
    assert translate_error("something new went wrong") == "something new went wrong"
    assert translate_error("--jobs is 0; give 1 or more worker processes") == "--jobs = 0; задайте 1 или больше процессов"


def test_version_in_both_languages():
    assert run("--version", "--lang", "ru").output.startswith("tmm, версия ")
    assert run("--version", "--lang", "en").output.startswith("tmm, version ")
