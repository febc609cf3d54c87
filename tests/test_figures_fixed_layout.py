"""What keeps the figures and the JSON path cheap, checked without timing anything (timings live in
bench/bench.py): fixed layouts (one draw per save), our PNG writer, the two sheets drawn side
by side with the same files as one after the other, and `project --json --no-plots` neither lays out
terminal tables nor imports matplotlib."""

import json
import subprocess
import sys

import numpy as np
import pytest
from matplotlib.figure import Figure

from tmm_cli.project import run_project
from tmm_cli.render.figures import agg
from tmm_cli.render.figures import kit as figure_kit
from tmm_cli.render.figures.cam import cam_figures
from tmm_cli.render.figures.gears import gears_figures
from tmm_cli.variants import get_variant


@pytest.fixture(scope="module")
def project17():
    return run_project(get_variant("17", None))


def test_every_figure_has_a_fixed_layout_and_is_drawn_once_per_save(project17, tmp_path, monkeypatch):
    figs = {**gears_figures(project17.gears, "ru"), **cam_figures(project17.cam, "ru")}
    assert len(figs) == 8
    draws = []
    original = Figure.draw
    monkeypatch.setattr(Figure, "draw", lambda self, renderer: (draws.append(self), original(self, renderer))[1])
    for name, fig in figs.items():
        assert fig.get_layout_engine() is None, name
        draws.clear()
        fig.savefig(tmp_path / f"{name}.png", format="png", dpi=40)
        assert draws == [fig], name  # the constrained layout drew every figure twice


def test_png_has_the_drawn_pixels_as_rgb_with_its_resolution(tmp_path):
    """Our PNG writer (rows unfiltered, zlib) read back by Pillow: RGB, the very pixels Agg drew, the dpi."""
    from PIL import Image

    fig = figure_kit.new_figure(2, 1.5)
    ax = fig.add_axes((0.1, 0.1, 0.8, 0.8))
    ax.plot([0, 1, 2], [0, 1, 0.5], color="tab:red")
    ax.set_title(figure_kit.mt("i_пл = 3,26"))
    fig.savefig(tmp_path / "a.png", dpi=50)
    drawn = np.asarray(fig.canvas.buffer_rgba())[..., :3]
    with Image.open(tmp_path / "a.png") as back:
        assert back.mode == "RGB" and back.size == (100, 75)
        assert round(back.info["dpi"][0]) == 50
        assert "Matplotlib" in back.info["Software"]
        assert np.array_equal(np.asarray(back), drawn)
    assert len(np.unique(drawn.reshape(-1, 3), axis=0)) > 10  # a real drawing, not a blank page
    fig.savefig(tmp_path / "a.svg", format="svg")
    assert (tmp_path / "a.svg").read_text(encoding="utf-8").lstrip().startswith("<?xml")


def test_a_transparent_figure_keeps_matplotlibs_rgba_png(tmp_path):
    from PIL import Image

    fig = figure_kit.new_figure(1, 1)
    fig.patch.set_alpha(0.0)
    fig.savefig(tmp_path / "t.png", dpi=20)
    with Image.open(tmp_path / "t.png") as back:
        assert back.mode == "RGBA"


def _json_run(tmp_path, *extra):
    code = (
        "import sys\n"
        "from tmm_cli.cli import main\n"
        "try:\n"
        f"    main(['project', '--variant', '17', '--json', '--no-plots', '--out', {str(tmp_path)!r}, *{list(extra)!r}])\n"
        "except SystemExit:\n"
        "    pass\n"
        "sys.stderr.write(repr(sorted(m for m in ('rich.table', 'rich.console', 'matplotlib') if m in sys.modules)))\n"
    )
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert json.loads(res.stdout)["variant"] == 17
    return res.stderr.strip()


def test_json_path_lays_out_no_table_and_imports_no_matplotlib(tmp_path):
    """--json changes only what goes to stdout; the folder is written as without it. With --no-plots and
    no drawing sheets (they are drawn by matplotlib, so --no-sheets) nothing imports matplotlib or lays
    out a rich table, whether the report is Markdown or the typeset note (typst)."""
    assert _json_run(tmp_path / "md", "--report", "md", "--no-sheets") == "[]"
    report = (tmp_path / "md" / "variant-17" / "report.md").read_text(encoding="utf-8")
    assert "| Quantity | Symbol, unit | Value |" in report or "| Величина | Обозначение, единица | Значение |" in report  # Markdown tables
    assert _json_run(tmp_path / "note", "--no-sheets") == "[]"
    assert (tmp_path / "note" / "variant-17" / "note.pdf").is_file()


def test_project_folder_has_every_figure_once(tmp_path):
    """The default project: each figure once as PNG; the note embeds its own figures (drawn for the
    page, note_<name>.svg), each once; the only hidden file is tmm's manifest of the files it wrote."""
    from click.testing import CliRunner

    from tmm_cli.cli import cli
    from tmm_cli.render.note import NOTE_FIGURES

    res = CliRunner().invoke(cli, ["project", "--variant", "17", "--out", str(tmp_path), "--lang", "ru", "--no-sheets"])
    assert res.exit_code == 0, res.output
    folder = tmp_path / "variant-17"
    names = sorted(p.name for p in folder.iterdir())
    pngs = [n for n in names if n.endswith(".png")]
    assert len(pngs) == 8 and [n for n in names if n.startswith(".")] == [".tmm-files.json"]
    svgs = [n for n in names if n.endswith(".svg")]
    assert sorted(svgs) == sorted(f"note_{n}.svg" for n in NOTE_FIGURES)
    assert all(f"{n[5:-4]}.png" in pngs for n in svgs)
    note = (folder / "note.typ").read_text(encoding="utf-8")
    assert all(note.count(f'image("{n}"') == 1 for n in svgs)
    assert ".png" not in note


def test_markdown_report_shows_the_notes_figures_once_in_its_order(tmp_path):
    from click.testing import CliRunner

    from tmm_cli.cli import cli
    from tmm_cli.render.note import NOTE_FIGURES

    res = CliRunner().invoke(cli, ["project", "--variant", "17", "--out", str(tmp_path), "--lang", "ru", "--no-sheets",
                                   "--report", "md"])
    assert res.exit_code == 0, res.output
    folder = tmp_path / "variant-17"
    pngs = sorted(p.name for p in folder.glob("*.png"))
    assert len(pngs) == 8 and not list(folder.glob("*.svg"))
    report = (folder / "report.md").read_text(encoding="utf-8")
    # report.md is the note as Markdown (issue 11): the note's figures, each once; the profile at its
    # standard scale is a file to print at 100 %, not a figure of the note
    assert all(report.count(f"({n}.png)") == 1 for n in NOTE_FIGURES)
    assert "cam_profile_scaled.png" in pngs and "cam_profile_scaled" not in report
    # in the note's order (issue 11): the cam's section (sheet 3), then the gears' (sheet 4)
    assert [n for n in NOTE_FIGURES if f"({n}.png)" in report] == sorted(NOTE_FIGURES, key=lambda n: report.index(f"({n}.png)"))


def test_opaque_figures_go_to_png_as_rgb_transparent_ones_keep_alpha(tmp_path):
    from PIL import Image

    fig = figure_kit.new_figure(1, 1)
    fig.add_subplot().plot([0, 1])
    fig.savefig(tmp_path / "opaque.png", dpi=30)
    fig.savefig(tmp_path / "clear.png", dpi=30, transparent=True)
    opaque = Image.open(tmp_path / "opaque.png")
    assert opaque.mode == "RGB" and opaque.size == (30, 30) and "Matplotlib" in opaque.info["Software"]
    assert Image.open(tmp_path / "clear.png").mode == "RGBA"


@pytest.mark.skipif("text_bitmaps" not in agg.hooks(), reason="no text bitmaps on this matplotlib")
def test_plain_text_lands_where_matplotlib_puts_it_and_a_second_draw_is_the_same(tmp_path):
    """Texts go through our renderer (one bitmap per text, kept): each text's ink stays within a
    pixel of matplotlib 3.11's own rendering, at any angle, and the kept bitmaps draw it again
    identically."""
    from matplotlib.backends.backend_agg import RendererAgg

    fig = figure_kit.new_figure(3, 2)
    texts = [fig.text(0.05, 0.8, "Зона зацепления, мм", fontsize=11), fig.text(0.6, 0.3, "−1000 об/мин", fontsize=8),
             fig.text(0.02, 0.1, "S, мм", rotation=90, fontsize=10), fig.text(0.4, 0.55, "30", fontsize=9)]
    fig.savefig(tmp_path / "a.png", dpi=100)
    ours = np.asarray(fig.canvas.buffer_rgba())[..., :3].copy()
    assert type(fig.canvas.get_renderer()) is not RendererAgg  # ours, not the stock one
    theirs_r = RendererAgg(*fig.canvas.get_width_height(physical=True), fig.dpi)
    fig.draw(theirs_r)
    theirs = np.asarray(theirs_r.buffer_rgba())[..., :3]
    for t in texts:  # compare ink boxes text by text (each in its own window)
        bb = t.get_window_extent(fig.canvas.get_renderer())
        h = ours.shape[0]
        y0, y1, x0, x1 = max(0, int(h - bb.y1) - 3), int(h - bb.y0) + 3, max(0, int(bb.x0) - 3), int(bb.x1) + 3
        boxes = []
        for img in (ours, theirs):
            ink = np.argwhere(img[y0:y1, x0:x1].min(axis=2) < 128)
            assert len(ink) > 10, t.get_text()
            boxes.append((*ink.min(axis=0), *ink.max(axis=0)))
        assert np.abs(np.subtract(*boxes)).max() <= 1, (t.get_text(), boxes)
    fig.savefig(tmp_path / "b.png", dpi=100)
    assert np.array_equal(np.asarray(fig.canvas.buffer_rgba())[..., :3], ours)
