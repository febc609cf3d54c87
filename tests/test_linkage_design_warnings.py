"""A legal but poor lever mechanism is said to be one (review finding B9): the six-link mechanism of
tests/test_note_teacher2.py has a pressure angle of 48,05° in its RRP group (above the usual 45° of a
lever mechanism) and K = 0,918 < 1 (its working stroke is the faster one). `tmm project --mechanism`
puts both in results.json's warnings and on the terminal, and the note's conclusion names them as
requirements not met instead of «Все требования задания выполнены»."""

from __future__ import annotations

import math

import numpy as np

from test_note_teacher2 import SIX_LINK

from tmm_cli.project import analyse_linkage, run_project
from tmm_cli.render.data.project import project_document
from tmm_cli.variants import get_variant


def _six():
    s2 = analyse_linkage(SIX_LINK, "six")
    return s2, run_project(get_variant("52"), linkage=s2, linkage_name="six.toml")


def _independent():
    """The RRP group's pressure angle (the rod DE against the vertical guide) over the turn, and K, from
    the kinematics of the dense curve: K = the crank travel of the working stroke / of the return."""
    s2, _ = _six()
    c = s2.sheet1.cycle
    k = c.curve.kin
    rod = k.z["E"] - k.z["D"]
    worst = float(np.degrees(np.abs(np.arcsin(np.clip(rod.real / np.abs(rod), -1, 1)))).max())
    return worst, c.working / c.returning


def test_the_six_link_is_a_poor_design_by_its_numbers():
    worst, K = _independent()
    assert 48.0 < worst < 48.1 and 0.917 < K < 0.919


def test_results_json_and_the_terminal_warn_of_the_pressure_angle_and_K():
    _, r = _six()
    warnings = project_document(r, "ru")["warnings"]
    assert any("Угол давления в группе 2" in w and "48,1°" in w and "больше 45°" in w for w in warnings), warnings
    assert any("Рабочий ход быстрее холостого" in w and "K = 0,9184 < 1" in w for w in warnings), warnings
    en = project_document(r, "en")["warnings"]
    assert any("pressure angle of group 2" in w for w in en) and any("K = 0.9184 < 1" in w for w in en), en


def test_the_conclusion_names_the_requirements_not_met():
    from tmm_cli.render.note import build_note
    from tmm_cli.render.note.model import _texts

    _, r = _six()
    doc = build_note(r, "ru", {})
    blocks = list(doc.blocks)
    start = next(i for i, b in enumerate(blocks) if getattr(b, "text", None) == "Заключение")
    text = " ".join(t for b in blocks[start:] for t in _texts(b))
    assert "Все требования задания выполнены" not in text
    assert "больше обычно допускаемого для рычажного механизма 45°" in text and "48,05" in text
    assert "$K$ = 0,918 < 1: рабочий ход быстрее холостого" in text
    assert "требования не выполнены" in text or "требования не выполнено" in text or "не выполнен" in text


def test_a_good_mechanism_keeps_its_met_requirements():
    import tomllib
    from pathlib import Path

    from tmm_cli.render.note import build_note
    from tmm_cli.render.note.model import _texts

    path = Path(__file__).resolve().parents[1] / "docs" / "examples" / "shaper.toml"
    s2 = analyse_linkage(tomllib.loads(path.read_text(encoding="utf-8")), "shaper")
    r = run_project(get_variant("17"), linkage=s2, linkage_name="shaper.toml")
    assert not [w for w in project_document(r, "ru")["warnings"] if "Угол давления" in w or "Рабочий ход" in w]
    text = " ".join(t for b in build_note(r, "ru", {}).blocks for t in _texts(b))
    assert "рабочий ход не быстрее холостого: $K$ = " in text
    assert math.isfinite(s2.sheet1.cycle.time_ratio)
