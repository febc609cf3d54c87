"""The A1 drawing sheets 3 and 4: one ezdxf model per sheet, written as DXF and as a vector PDF.

``sheet3(cam_result, lang, title)`` and ``sheet4(gears_result, variant_number, lang, title)``
build the drawing in memory (a :class:`~.paper.Sheet` holding the ezdxf document);
``save_sheet`` writes ``<name>.dxf`` and, from the same document, ``<name>.pdf``;
``write_sheets`` does both sheets of a project into a folder.
ezdxf and matplotlib are imported only when a sheet is built.
"""

from __future__ import annotations

from pathlib import Path


def sheet3(cam, lang: str, title):
    """Sheet 3 «Синтез кулачкового механизма» of a CamResult (a Sheet; nothing written)."""
    from .cam_sheet import sheet3 as build

    return build(cam, lang, title)


def sheet4(gears, variant: int, lang: str, title):
    """Sheet 4 «Синтез и анализ зубчатых механизмов» of a GearsResult (a Sheet; nothing written)."""
    from .gears_sheet import sheet4 as build

    return build(gears, variant, lang, title)


def save_sheet(sheet, folder: Path, name: str, pdf: bool = True) -> list[str]:
    """Write ``name.dxf`` (and ``name.pdf`` from the same document) into `folder`; the file names."""
    folder = Path(folder)
    sheet.finish()  # labels placed, the A1 paper space, unused styles gone (once; the sheets call it)
    sheet.doc.saveas(folder / f"{name}.dxf", encoding="utf-8")
    out = [f"{name}.dxf"]
    if pdf:
        from .pdf import save_pdf

        save_pdf(sheet.doc, folder / f"{name}.pdf")
        out.append(f"{name}.pdf")
    return out


def _fork_ok() -> bool:
    """Draw the two sheets in two processes: on Linux with more than one core, and not inside a
    batch worker (a worker of ``tmm batch`` already keeps every core busy)."""
    import multiprocessing

    from ..figures.kit import can_fork

    return can_fork() and multiprocessing.parent_process() is None


def _warm_up() -> None:
    """Import what both processes need before forking (else each would import it again)."""
    import ezdxf  # noqa: F401
    from ezdxf.addons.drawing import Frontend  # noqa: F401
    from ezdxf.addons.drawing.matplotlib import MatplotlibBackend  # noqa: F401
    from matplotlib.backends import backend_pdf  # noqa: F401

    from . import cam_sheet, gears_sheet, pdf  # noqa: F401


def write_sheets(folder: Path, result, lang: str, title=None) -> list[str]:
    """sheet3.dxf/.pdf and sheet4.dxf/.pdf of a ProjectResult into `folder` (a staging folder).

    On two cores a forked child draws and writes sheet 3 while this process does sheet 4 (the
    PDF rendering is most of the time); if the child fails, sheet 3 is drawn here afterwards, so
    the files are the same either way."""
    import os
    import sys

    from ...inputs.titleblock import TitleFields

    folder = Path(folder)
    title = title or TitleFields()

    def first():
        return save_sheet(sheet3(result.cam, lang, title), folder, "sheet3")

    def second():
        return save_sheet(sheet4(result.gears, result.variant.number, lang, title), folder, "sheet4")

    if not _fork_ok():
        return first() + second()
    _warm_up()
    sys.stdout.flush()
    sys.stderr.flush()
    pid = os.fork()
    if pid == 0:  # the child: sheet 3, then leave without running any exit handler of the parent
        code = 1
        try:
            first()
            code = 0
        finally:
            os._exit(code)
    try:
        mine = second()
        _, status = os.waitpid(pid, 0)
    except BaseException:  # an error or a signal here: the child must not write on into `folder`
        try:
            os.kill(pid, 9)
        except ProcessLookupError:
            pass
        os.waitpid(pid, 0)
        raise
    if status == 0 and all((folder / n).is_file() for n in ("sheet3.dxf", "sheet3.pdf")):
        return ["sheet3.dxf", "sheet3.pdf"] + mine
    return first() + mine  # the child failed: draw sheet 3 here (an error now surfaces normally)
