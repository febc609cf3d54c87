"""The translations live in one gettext catalogue (tmm_cli/i18n/locale/ru/LC_MESSAGES/tmm.po, compiled
to tmm.mo): it is current with the code, complete, and no Python module keeps Russian prose of its
own (no parallel dictionaries)."""

from __future__ import annotations

import ast
import re
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
import catalog as build  # noqa: E402

from tmm_cli.i18n import tr, trc  # noqa: E402
from tmm_cli.render.note.sources import SOURCES  # noqa: E402

PACKAGE = Path(__file__).resolve().parents[1] / "tmm_cli"
PROSE = re.compile("[а-яё]{3,}")  # three lower-case Cyrillic letters: a word, not a symbol's subscript (n_кр, φ_дс)
SUBSCRIPT = re.compile(r'_\(?"[^"]*"')  # a typst symbol's quoted subscript: N_"ном", Y_(a "в" max)
# rooms whose text is still written inline; each is to move into the catalogue
PENDING: set[str] = set()
# Russian that is data, not a translation
ALLOWED = {"авто",  # `--shift авто` is read as `--shift auto`
           'name = "Механизм"',  # an example line of a mechanism file, in an error message
           # the drawing's layer names and the ESKD title block's own words (ГОСТ 2.104 form 1), Russian on every sheet
           "Основные", "Тонкие", "Штриховые", "Осевые", "Рабочие", "Размеры", "Текст", "Рамка", "Лист", "Листов 1",
           "Лист 1", "№ докум.", "Подп.", "Дата", "Разраб.", "Пров.", "Т.контр.", "Н.контр.", "Масса", "Масштаб",
           # the Russian headers a teacher's roster or answers file may have (read, not shown), Cyrillic look-alikes
           "студент", "фио", "фамилия", "вариант", "вар", "вар.", "группа", "момент", "механизм", "файл механизма",
           "ключ", "значение", "асеорхукнтвмАСЕОРХУКНТВМ",
           'Student\'s name for the title block and the note, e.g. "Иванов И. И." (or in tmm.toml).'}
# the textbook's bibliographic record: ГОСТ Р 7.0.100-2018 describes a resource in the language of its imprint,
# so the Russian book's record is Russian data, not a translation (render/note/sources.py)
ALLOWED |= {s.record for s in SOURCES.values()}


def test_the_catalogue_is_current_and_complete(capsys):
    """tmm.po holds every msgid the code and the command line use, each translated, and tmm.mo is
    compiled from it: otherwise run `python tools/catalog.py` and translate what it names."""
    status = build.main(["--check"])
    assert status == 0, capsys.readouterr().out


def test_the_extraction_reads_calls_not_names():
    """What Babel 2.19's tokenizer got wrong (issue 35) is no message here: a dict named `t` indexed
    by a string, a local function `t` given a number, two docstrings one after the other; while a
    method call `c.t("…")`, a context and a plural are."""
    source = (
        'def f(t, c, lang, n):\n'
        '    """First docstring."""\n'
        '    x = t["link"] + t["joint"]\n'
        '    y = t(1)\n'
        '    return c.t("Stroke {h}").format(h=1), trc(lang, "column, short", "Scheme"), ntr(lang, "{n} tooth", "{n} teeth", n)\n'
        'def g():\n'
        '    """Second docstring."""\n'
        '    return N_("rise")\n')
    assert [(m, c) for _, m, c in build.calls_in(source)] == [
        ("Stroke {h}", None), ("Scheme", "column, short"), (("{n} tooth", "{n} teeth"), None), ("rise", None)]


def test_the_catalogue_holds_no_name_babel_219_mistook_for_a_message():
    from babel.messages.pofile import read_po

    with open(build.po_path("ru"), "rb") as f:
        ids = {m.id for m in read_po(f) if m.id}
    assert not ids & {"link", "joint", "omega", "start_deg", "1"}
    assert not [i for i in ids if isinstance(i, str) and ("Split markup into" in i or "The synthesis result" in i)]


def test_the_catalogue_translates():
    assert tr("ru", "Value") == "Значение" and tr("en", "Value") == "Value"
    assert trc("ru", "column, short", "Scheme") == "№ сх." and tr("ru", "Scheme") == "Схема"


def _pending(path: Path) -> bool:
    rel = path.relative_to(PACKAGE).as_posix()
    return any(rel == p or rel.startswith(p + "/") for p in PENDING)


REGEX_CALLS = {"compile", "sub", "subn", "match", "fullmatch", "search", "split", "findall", "finditer"}


def _skipped(tree) -> set[int]:
    """ids of the constants that are not user text: docstrings (they cite Russian sources), the
    English error messages (their examples may hold a Russian name; their translation is a
    template in the catalogue) and the patterns of `re` (they recognise words tmm wrote, in both
    languages: the note's «рисунок {fig:…}» and the like)."""
    skip = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr in REGEX_CALLS \
                and getattr(node.func.value, "id", "") == "re" and node.args:
            skip.update(id(n) for n in ast.walk(node.args[0]))
        if isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant):  # a docstring, also of a constant
            skip.add(id(node.value))
        if isinstance(node, ast.Call) and getattr(node.func, "id", getattr(node.func, "attr", "")) in ("TmmError", "fail"):
            skip.update(id(n) for arg in node.args for n in ast.walk(arg))
        if isinstance(node, ast.keyword) and node.arg == "aliases":  # what students write for a key (tmm check)
            skip.update(id(n) for n in ast.walk(node.value))
    return skip


def test_no_module_keeps_russian_prose_of_its_own():
    found = []
    for path in sorted(PACKAGE.rglob("*.py")):
        if _pending(path):
            continue
        tree = ast.parse(path.read_text(encoding="utf-8"))
        skip = _skipped(tree)
        for node in ast.walk(tree):
            if isinstance(node, ast.Constant) and isinstance(node.value, str) \
                    and PROSE.search(SUBSCRIPT.sub("", node.value)) and node.value not in ALLOWED and id(node) not in skip:
                found.append(f"{path.relative_to(PACKAGE)}:{node.lineno}: {node.value[:60]!r}")
    assert not found, "\n".join(found)


def test_no_translation_inside_an_f_string():
    """Babel's extractor does not look inside f-strings (Python 3.11 tokenises one as a single
    string): a tr() there would never reach the catalogue. Translate first, then format. (The
    note's c.t/tc/nt too, when given a literal.)"""
    found = []
    for path in sorted(PACKAGE.rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.JoinedStr):
                for sub in ast.walk(node):
                    if not isinstance(sub, ast.Call):
                        continue
                    name = getattr(sub.func, "id", None) or getattr(sub.func, "attr", None)
                    literal = any(isinstance(a, ast.Constant) and isinstance(a.value, str) for a in sub.args)
                    if name in ("tr", "trc", "ntr", "N_") or (name in ("t", "tc", "nt") and literal):
                        found.append(f"{path.relative_to(PACKAGE)}:{node.lineno}")
    assert not found, found


def _fields(template: str) -> set[str]:
    import string

    return {name.split(".")[0].split("[")[0] for _, name, _, _ in string.Formatter().parse(template) if name}


def _formatted_calls():
    """(path, line, msgid literals, names given) of every tr/trc/ntr/t(…).format(…) in the package."""
    for path in sorted(PACKAGE.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr == "format"
                    and isinstance(node.func.value, ast.Call)):
                continue
            inner = node.func.value
            if getattr(inner.func, "id", getattr(inner.func, "attr", "")) not in ("tr", "trc", "ntr", "t", "tc", "nt"):
                continue
            given = {k.arg for k in node.keywords} | {str(i) for i in range(len(node.args))}
            literals = [a.value for a in inner.args if isinstance(a, ast.Constant) and isinstance(a.value, str)]
            yield path, node.lineno, literals, given


def test_every_formatted_msgid_gets_its_fields():
    """tr(lang, "… {x} …").format(x=…): every field the English template names is given (a field
    nobody gives is a KeyError, or a {cite:…} left unescaped)."""
    missing = [f"{path.relative_to(PACKAGE)}:{line}: {sorted(_fields(lit) - given)}"
               for path, line, literals, given in _formatted_calls() for lit in literals if _fields(lit) - given]
    assert not missing, missing


def test_every_translation_names_only_the_fields_of_its_msgid():
    """A Russian template that is formatted may drop a field but never invent one (it would fail
    only in Russian): the msgids the code formats, and the notes' sentences."""
    from babel.messages.pofile import read_po

    from tmm_cli.i18n.lang import _catalogue

    formatted = {lit for _, _, literals, _ in _formatted_calls() for lit in literals} | set(_catalogue().values())
    with open(build.po_path("ru"), "rb") as f:
        catalogue = read_po(f, locale="ru")
    wrong = []
    for m in catalogue:
        ids = m.id if isinstance(m.id, tuple) else (m.id,)
        if not m.id or m.context in ("click", "error") or not set(ids) & formatted:
            continue
        strings = m.string if isinstance(m.string, tuple) else (m.string,)
        try:
            extra = set().union(*(_fields(s) for s in strings if s)) - set().union(*(_fields(i) for i in ids))
        except ValueError as exc:  # an unbalanced brace
            wrong.append(f"{ids[0][:60]!r}: {exc}")
            continue
        if extra:
            wrong.append(f"{ids[0][:60]!r}: {sorted(extra)}")
    assert not wrong, wrong
