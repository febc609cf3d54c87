"""Drawings shared by a batch's workers (render/figures/shared.py): the first to need one draws it,
the others take it from the common folder (the same bytes) or, if it never comes, draw it
themselves; nothing is written into the user's folders but the figures."""

import os

import pytest

from tmm_cli.project import run_project
from tmm_cli.render import project as report
from tmm_cli.render.figures import pipeline
from tmm_cli.render.figures.shared import SharedFigures
from tmm_cli.variants import get_variant

KEY = ("reducer", 220.0, "ru", "png", ())


def test_claim_put_get(tmp_path):
    a, b = SharedFigures(tmp_path), SharedFigures(tmp_path, wait_s=0.2)
    assert a.get(KEY) is None
    assert a.claim(KEY) and not b.claim(KEY)  # one drawer
    assert b.wait(KEY) is None  # not published within wait_s
    a.put(KEY, {"x.png": b"\x89PNG1", "x.svg": b"<svg/>"})
    assert b.get(KEY) == {"x.png": b"\x89PNG1", "x.svg": b"<svg/>"} == b.wait(KEY)
    a.put(KEY, {"x.png": b"other"})  # published once: a second publication changes nothing
    assert b.get(KEY)["x.png"] == b"\x89PNG1"
    assert sorted(p.name for p in tmp_path.iterdir() if not p.name.endswith(".claim")) == [a._name(KEY)]


def test_a_gone_folder_means_drawing_here(tmp_path):
    gone = SharedFigures(tmp_path / "gone", wait_s=0.1)
    assert gone.get(KEY) is None and gone.claim(KEY)
    gone.put(KEY, {"x.png": b"1"})  # quietly nothing
    assert not (tmp_path / "gone").exists()


@pytest.fixture(scope="module")
def rows():
    a, b = run_project(get_variant(17)), run_project(get_variant(4))
    assert pipeline._reducer_key(a.gears, "ru", "png") == pipeline._reducer_key(b.gears, "ru", "png")
    return a, b


def _pngs(folder):
    return {p.name: p.read_bytes() for p in folder.iterdir() if p.suffix == ".png"}


def test_a_second_worker_takes_the_first_ones_drawings(tmp_path, rows, monkeypatch):
    a, b = rows
    shared = SharedFigures(tmp_path / "shared")
    (tmp_path / "shared").mkdir()
    report.write_project_folder(a, tmp_path / "a", "ru", figure_cache={}, shared_figures=shared)
    drawn = []
    real = pipeline._draw_and_save
    monkeypatch.setattr(pipeline, "_draw_and_save", lambda tmp, r, lang, fmt, names, svg: (drawn.extend(names), real(tmp, r, lang, fmt, names, svg)))
    report.write_project_folder(b, tmp_path / "b", "ru", figure_cache={}, shared_figures=shared)  # another worker: own memory
    assert not set(pipeline.REDUCER_FIGURES) & set(drawn)  # taken from the folder, not drawn
    alone = tmp_path / "alone"
    monkeypatch.setattr(pipeline, "_draw_and_save", real)
    report.write_project_folder(b, alone, "ru", figure_cache={})
    assert _pngs(tmp_path / "b") == _pngs(alone)  # the very bytes a worker of its own writes
    assert sorted(os.listdir(tmp_path / "b")) == sorted(os.listdir(alone))


def test_a_drawing_claimed_but_never_published_is_drawn_here(tmp_path, rows):
    a, _ = rows
    shared = SharedFigures(tmp_path / "shared", wait_s=0.2)
    (tmp_path / "shared").mkdir()
    for group, key in ((pipeline.REDUCER_FIGURES, pipeline._reducer_key(a.gears, "ru", "png")),
                       (("gears_mesh",), pipeline._mesh_key(a.gears, "ru", "png"))):
        assert shared.claim((*key, ()))  # "another worker" claimed them all, then died
    report.write_project_folder(a, tmp_path / "a", "ru", figure_cache={}, shared_figures=shared)
    alone = tmp_path / "alone"
    report.write_project_folder(a, alone, "ru", figure_cache={})
    assert _pngs(tmp_path / "a") == _pngs(alone) and len(_pngs(alone)) == len(pipeline.ALL_FIGURES)
