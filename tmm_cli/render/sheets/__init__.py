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
    sheet.doc.saveas(folder / f"{name}.dxf", encoding="utf-8")
    out = [f"{name}.dxf"]
    if pdf:
        from .pdf import save_pdf

        save_pdf(sheet.doc, folder / f"{name}.pdf")
        out.append(f"{name}.pdf")
    return out


def write_sheets(folder: Path, result, lang: str, title=None) -> list[str]:
    """sheet3.dxf/.pdf and sheet4.dxf/.pdf of a ProjectResult into `folder` (a staging folder)."""
    from ...titleblock import TitleFields

    title = title or TitleFields()
    names = save_sheet(sheet3(result.cam, lang, title), folder, "sheet3")
    names += save_sheet(sheet4(result.gears, result.variant.number, lang, title), folder, "sheet4")
    return names
