"""The DOCX writer: the same :class:`~.model.Document` as note.docx for Word and LibreOffice.

Why python-docx (and OMML written here, :mod:`.omml`): a normcontroller opens the file in Word and
looks for real styles — headings that make a field-based table of contents, captions, Word tables
with a repeated header row, native equations. python-docx writes exactly these parts and nothing
else (no conversion step that guesses), is pure Python on lxml, and reads the file back for the
tests. pandoc (pypandoc-binary) would bring a 100 MB binary and its own idea of the styles.

ГОСТ 7.32 page and text: A4, margins 30/15/20/20 mm, Times New Roman 14 pt (12 pt in tables),
1,5 lines, indent 1,25 cm, justified; page number at the bottom centre from the title page, not
shown on it. Figures: the note's own figures as SVG (Word 2016 and later) with a 300 dpi PNG beside
them for every other reader.
"""

from __future__ import annotations

import re
from pathlib import Path

from ...i18n import tr
from .model import (
    ABSTRACT_COUNTS,
    APPENDIX_COUNT,
    SCI_EXPONENT,
    SUPER_DIGITS,
    Abstract,
    Contents,
    Document,
    Figure,
    Formula,
    Heading,
    ListBlock,
    PageBreak,
    Paragraph,
    ReferenceList,
    Table,
    TaskSheet,
    TitlePage,
    split_math,
    text_runs,
)
from .omml import omath, omath_para

FONT = "Times New Roman"
SVG_EXT = "{96DAC541-7B7A-43D3-8B79-37D633B846F1}"
ASVG = "http://schemas.microsoft.com/office/drawing/2016/SVG/main"
TEXT_CM = 16.5
WORD_JOINER = "\u2060"
_SLASH = re.compile(r"(?<=[^\s/])/(?=[^\s/])")


def no_break_after_slash(text: str) -> str:
    """A unit kept on one line: a word joiner (U+2060) after a slash between two characters, so
    «рад/с» and «(м/с)/мм» never break as «рад/ с» (LibreOffice 7.4 honours U+2060 and breaks at the
    space before the unit instead; a zero-width joiner U+200D it ignores, and U+00A0 would print a
    space). A text with an address (``://``) is left alone: its joiners would go into the link.

    >>> no_break_after_slash("ε, рад/с²") == "ε, рад/" + WORD_JOINER + "с²"
    True
    >>> no_break_after_slash("(м/с)/мм").count(WORD_JOINER), no_break_after_slash("и / или")
    (2, 'и / или')
    >>> no_break_after_slash("https://e.lanbook.com/book/1")
    'https://e.lanbook.com/book/1'
    """
    return text if "://" in text else _SLASH.sub("/" + WORD_JOINER, text)
# the text after an inline formula that goes on with a relation and a number («$n_к$ = 1100 об/мин»):
# LibreOffice may break a line after a formula whatever space follows it (it put «= 1100» on the next
# line of the task, «90 / мм» in another), so the sign, the number and its unit join the formula as upright text
RELATION_AFTER_MATH = re.compile(r'[ \u00a0]([=≈≠<>≤≥])[ \u00a0]([−\-]?\d[\d\u202f]*(?:,\d+)?(?:°|\u00a0[^\s;,.()«»"$\\]+)?)')


class DocxWriter:
    def __init__(self, doc: Document, folder: Path, title, pages: dict | None = None):
        import docx

        self.pages = pages or {}
        self.doc = doc
        self.folder = Path(folder)
        self.title = title
        self.d = docx.Document()
        self.ru = doc.lang == "ru"
        self._setup()

    # -- page and styles -------------------------------------------------------------------------
    def _setup(self) -> None:
        from docx.enum.text import WD_ALIGN_PARAGRAPH, WD_LINE_SPACING
        from docx.shared import Cm, Mm, Pt

        sec = self.d.sections[0]
        sec.page_width, sec.page_height = Mm(210), Mm(297)
        sec.left_margin, sec.right_margin = Mm(30), Mm(15)
        sec.top_margin, sec.bottom_margin = Mm(20), Mm(20)
        sec.footer_distance = Mm(10)
        sec.different_first_page_header_footer = True  # the title page counts, shows no number
        fp = sec.footer.paragraphs[0]
        fp.alignment = WD_ALIGN_PARAGRAPH.CENTER
        fp.paragraph_format.first_line_indent = Cm(0)
        self._field(fp, "PAGE", "1")

        st = self.d.styles
        normal = st["Normal"]
        normal.font.name = FONT
        normal.font.size = Pt(14)
        self._east_asian(normal.element, FONT)
        pf = normal.paragraph_format
        pf.line_spacing_rule = WD_LINE_SPACING.ONE_POINT_FIVE
        pf.first_line_indent = Cm(1.25)
        pf.space_before = Pt(0)
        pf.space_after = Pt(0)
        pf.alignment = WD_ALIGN_PARAGRAPH.JUSTIFY
        pf.widow_control = True
        for name, size, level in (("Heading 1", 14, 0), ("Heading 2", 14, 1)):
            h = st[name]
            h.font.name = FONT
            h.font.size = Pt(size)
            h.font.bold = True
            h.font.italic = False
            h.font.color.rgb = None
            self._east_asian(h.element, FONT)
            f = h.paragraph_format
            f.first_line_indent = Cm(1.25)
            f.left_indent = Cm(0)
            f.space_before = Pt(12)
            f.space_after = Pt(12)
            f.keep_with_next = True
            f.alignment = WD_ALIGN_PARAGRAPH.LEFT
            f.line_spacing_rule = WD_LINE_SPACING.ONE_POINT_FIVE
        st["Heading 1"].paragraph_format.page_break_before = True
        from docx.enum.style import WD_STYLE_TYPE

        for name, outline in (("Structural", True), ("Structural Plain", False)):
            s = st.add_style(name, WD_STYLE_TYPE.PARAGRAPH)
            s.base_style = st["Heading 1"] if outline else st["Normal"]
            s.font.bold = True
            s.font.all_caps = True
            s.font.size = Pt(14)
            f = s.paragraph_format
            f.alignment = WD_ALIGN_PARAGRAPH.CENTER
            f.first_line_indent = Cm(0)
            f.page_break_before = True
            f.space_after = Pt(12)
            f.keep_with_next = True
        cap = st["Caption"]
        cap.font.name = FONT
        cap.font.size = Pt(14)
        cap.font.bold = False
        cap.font.italic = False
        cap.font.color.rgb = None
        cap.paragraph_format.first_line_indent = Cm(0)
        cap.paragraph_format.space_before = Pt(6)
        cap.paragraph_format.space_after = Pt(6)
        cap.paragraph_format.line_spacing_rule = WD_LINE_SPACING.SINGLE
        tab = st.add_style("Table Text", WD_STYLE_TYPE.PARAGRAPH)
        tab.base_style = normal
        tab.font.size = Pt(12)
        tab.paragraph_format.first_line_indent = Cm(0)
        tab.paragraph_format.line_spacing_rule = WD_LINE_SPACING.SINGLE
        tab.paragraph_format.alignment = WD_ALIGN_PARAGRAPH.LEFT
        from docx.oxml.ns import qn

        for fonts in list(self.d.styles.element.iter(qn("w:rFonts"))):  # every style, Times New Roman by name
            self._east_asian(fonts.getparent(), FONT)
        core = self.d.core_properties
        core.title = self.title_text()
        core.author = getattr(self.title, "student", "") or ""
        core.language = "ru-RU" if self.ru else "en-GB"
        self._language()

    def title_text(self) -> str:
        return tr(self.doc.lang, "Explanatory note")

    def _language(self) -> None:
        """The document's language (Word's hyphenation and spelling)."""
        from docx.oxml.ns import qn
        from lxml import etree

        rpr = self.d.styles.element.find(qn("w:docDefaults"))
        if rpr is None:
            return
        rpr_default = rpr.find(qn("w:rPrDefault"))
        rpr_el = rpr_default.find(qn("w:rPr")) if rpr_default is not None else None
        if rpr_el is None:
            return
        lang = rpr_el.find(qn("w:lang"))
        if lang is None:
            lang = etree.SubElement(rpr_el, qn("w:lang"))
        lang.set(qn("w:val"), "ru-RU" if self.ru else "en-GB")
        self._east_asian(rpr_el, FONT)
        settings = self.d.settings.element
        # in the schema's order: autoHyphenation after defaultTabStop, updateFields before the notes and compat
        if settings.find(qn("w:autoHyphenation")) is None:
            e = etree.Element(qn("w:autoHyphenation"))
            e.set(qn("w:val"), "true")
            tab = settings.find(qn("w:defaultTabStop"))
            (tab.addnext(e) if tab is not None else settings.insert(0, e))
        if settings.find(qn("w:updateFields")) is None:  # Word fills the contents and page count on opening
            e = etree.Element(qn("w:updateFields"))
            e.set(qn("w:val"), "true")
            later = next((settings.find(qn(t)) for t in ("w:hdrShapeDefaults", "w:footnotePr", "w:endnotePr", "w:compat",
                                                          "w:docVars", "w:rsids", "m:mathPr", "w:themeFontLang",
                                                          "w:clrSchemeMapping", "w:shapeDefaults", "w:decimalSymbol",
                                                          "w:listSeparator") if settings.find(qn(t)) is not None), None)
            (later.addprevious(e) if later is not None else settings.append(e))
        self._drop_styles_with_effects()

    def _drop_styles_with_effects(self) -> None:
        """python-docx's template carries Word 2010's stylesWithEffects.xml, a copy of the styles that
        no longer matches once styles are added (Word may then offer to repair): it is optional, so
        it goes."""
        part = self.d.part
        for rid, rel in list(part.rels.items()):
            if rel.reltype.endswith("/stylesWithEffects"):
                part.drop_rel(rid) if hasattr(part, "drop_rel") else part.rels.pop(rid)

    @staticmethod
    def _east_asian(style_el, font: str) -> None:
        """The font named outright for every script: a theme font (python-docx's heading styles ask
        for the theme's major font) goes before an explicit name in Word and LibreOffice, and showed
        the headings in a sans-serif."""
        from docx.oxml.ns import qn

        rpr = style_el.get_or_add_rPr() if hasattr(style_el, "get_or_add_rPr") else style_el
        fonts = rpr.find(qn("w:rFonts"))
        if fonts is None:
            from lxml import etree

            fonts = etree.Element(qn("w:rFonts"))
            rpr.insert(0, fonts)
        for k in ("w:ascii", "w:hAnsi", "w:cs", "w:eastAsia"):
            fonts.set(qn(k), font)
        for k in ("w:asciiTheme", "w:hAnsiTheme", "w:cstheme", "w:eastAsiaTheme"):
            fonts.attrib.pop(qn(k), None)

    def _field(self, paragraph, code: str, cached: str = "") -> None:
        """A Word field (PAGE, NUMPAGES, SEQ, TOC) with its cached result."""
        from docx.oxml import OxmlElement
        from docx.oxml.ns import qn

        def char(kind):
            r = OxmlElement("w:r")
            fc = OxmlElement("w:fldChar")
            fc.set(qn("w:fldCharType"), kind)
            r.append(fc)
            return r

        p = paragraph._p
        p.append(char("begin"))
        r = OxmlElement("w:r")
        it = OxmlElement("w:instrText")
        it.set(qn("xml:space"), "preserve")
        it.text = f" {code} "
        r.append(it)
        p.append(r)
        p.append(char("separate"))
        run = paragraph.add_run(cached)
        p.append(run._r)
        p.append(char("end"))

    # -- inline ------------------------------------------------------------------------------------
    def inline(self, paragraph, text: str, bold: bool = False, size: float | None = None, in_table: bool = False,
               joined: bool = True) -> None:
        """`joined`: no break after a unit's slash in the program's text (:func:`no_break_after_slash`);
        off for the list of sources, whose addresses are copied as they are."""
        from docx.shared import Pt

        text = self.doc.resolve(text)
        pieces = [list(x) for x in split_math(text)]
        for k in range(len(pieces) - 1):  # «$n_к$ = 1100 об/мин»: the sign and the number join the formula
            (is_math, src), (_, after) = pieces[k], pieces[k + 1]
            m = RELATION_AFTER_MATH.match(after) if is_math and after else None
            if m:
                pieces[k][1] = f'{src} {m[1]} "{m[2]}"'
                pieces[k + 1][1] = after[m.end():]
        for is_math, piece in pieces:
            if is_math:  # in a table at the table's 12 pt, fractions on the line (no tall rows)
                paragraph._p.append(omath(piece, size=12 if in_table else 14, linear=in_table))
            elif piece:
                for given, run in text_runs(piece):
                    if given:  # a person's text: one plain run, as given
                        r = paragraph.add_run(run)
                        r.bold = bold or None
                        if size:
                            r.font.size = Pt(size)
                    else:
                        self._runs(paragraph, no_break_after_slash(run) if joined else run, bold, size)

    def _runs(self, paragraph, piece: str, bold: bool, size: float | None) -> None:
        """The program's text: a power of ten, "1,458·10⁻⁴", as a superscript run."""
        from docx.shared import Pt

        parts = SCI_EXPONENT.split(piece)
        for k, part in enumerate(parts):
            if not part:
                continue
            run = paragraph.add_run(part.translate(SUPER_DIGITS) if k % 2 else part)
            run.bold = bold or None
            if k % 2:
                run.font.superscript = True
            if size:
                run.font.size = Pt(size)

    STYLE_IDS = {"Structural": "Structural", "Structural Plain": "StructuralPlain", "Caption": "Caption",
                 "Table Text": "TableText", "Heading 1": "Heading1", "Heading 2": "Heading2"}

    def _styled(self, p, style: str | None):
        """Set a paragraph's style by its id (python-docx looks a style up by walking all of them)."""
        if style:
            p._p.get_or_add_pPr().get_or_add_pStyle().val = self.STYLE_IDS[style]
        return p

    def para(self, text: str = "", style: str | None = None, indent: bool = True, align=None, bold: bool = False,
             joined: bool = True):
        from docx.shared import Cm

        p = self._styled(self.d.add_paragraph(), style)
        if not indent:
            p.paragraph_format.first_line_indent = Cm(0)
        if align is not None:
            p.alignment = align
        if text:
            self.inline(p, text, bold=bold, joined=joined)
        return p

    # -- blocks ------------------------------------------------------------------------------------
    def write(self, path: Path) -> None:
        self.doc.number()
        for b in self.doc.blocks:
            self.block(b)
        self.d.save(str(path))

    def block(self, b) -> None:
        if isinstance(b, TitlePage):
            self.title_page(b.fields)
        elif isinstance(b, TaskSheet):
            self.para(b.title.upper(), style="Structural Plain")
            for line in b.lines:
                self.para(line, indent=False)
            self.para(b.contents[0])
            for i, item in enumerate(b.contents[1:], 1):
                self.para(f"{i}) {item}")
        elif isinstance(b, Abstract):
            self.abstract(b)
        elif isinstance(b, Contents):
            self.contents()
        elif isinstance(b, Heading):
            self.heading(b)
        elif isinstance(b, Paragraph):
            self.para(b.text, indent=b.indent)
        elif isinstance(b, Formula):
            self.formula(b)
        elif isinstance(b, ListBlock):
            for i, item in enumerate(b.items, 1):
                self.para((f"{i}) " if b.ordered else "– ") + item)
        elif isinstance(b, Table):
            self.table(b)
        elif isinstance(b, Figure):
            self.figure(b)
        elif isinstance(b, ReferenceList):
            for i, src in enumerate(self.doc.references(), 1):
                self.para(f"{i}. {src.text}", joined=False)
        elif isinstance(b, PageBreak):
            from docx.enum.text import WD_BREAK

            self.d.add_paragraph().add_run().add_break(WD_BREAK.PAGE)
        else:
            raise TypeError(b)

    def title_page(self, f: dict) -> None:
        """The title page on one page in every word processor: no empty paragraphs (five of them
        pushed the year onto page 2 in LibreOffice), the gaps as spacing, single-spaced lines, and the
        city with the year in the title page's own footer, at the bottom of page 1 wherever the
        lines above end."""
        from docx.enum.text import WD_ALIGN_PARAGRAPH as A
        from docx.enum.text import WD_LINE_SPACING
        from docx.shared import Cm, Pt

        def line(text, bold=False, align=A.CENTER, space=0, before=0.0):
            p = self.para("", indent=False, align=align)
            pf = p.paragraph_format
            pf.space_after = Pt(space)
            pf.space_before = Cm(before)
            pf.line_spacing_rule = WD_LINE_SPACING.SINGLE
            run = p.add_run(text)
            run.bold = bold or None
            return p

        if f.get("ministry"):
            line(f["ministry"], space=6)
        if f["org-lines"]:
            for ln in f["org-lines"]:
                line(ln, space=6)
        else:  # the lines to fill in, each with its ГОСТ 7.32 label under it (as the typst title page)
            for key in ("org-label", "dept-label"):
                line("_" * 50, space=0)
                label = line("(" + f.get(key, "") + ")", space=6)
                label.runs[0].font.size = Pt(10)
        line(f["doc-kind"].upper(), bold=True, before=5.0, space=6)
        line(f["discipline"], space=6)
        line(f["topic"], bold=True, space=6)
        line(f["variant-line"], space=6)
        line(f["designation"], space=12)
        date = ("«___» __________ 20__ " + f["date-label"]).strip()
        first = True
        for label, name, extra in ((f["teacher-label"], f["teacher"], date), (f["student-label"], f["student"], date)):
            line(f"{label}  ____________  {name or '____________'}", align=A.RIGHT, before=3.5 if first else 0.0,
                 space=6)
            if not first:  # «студент группы» and the group, or a blank for it (as the typst title page)
                line(f"{f['group-label']}  {f['group'] or '____________'}", align=A.RIGHT, space=6)
            line(extra, align=A.RIGHT, space=12)
            first = False
        line(f"{f['grade-label']} ____________", align=A.RIGHT)
        foot = self.d.sections[0].first_page_footer.paragraphs[0]
        foot.alignment = A.CENTER
        foot.paragraph_format.first_line_indent = Cm(0)
        if f["city"]:
            foot.add_run(f["city"] + " " + f["year"])
        else:  # a blank for the city with its ГОСТ 7.32 label, then the year
            foot.add_run("____________ " + f["year"])
            foot.add_run().add_break()
            label = foot.add_run("(" + f.get("city-label", "") + ")")
            label.font.size = Pt(10)

    def abstract(self, b: Abstract) -> None:
        c = self.doc.counts()
        lang = self.doc.lang
        self.para(tr(lang, "Abstract").upper(), style="Structural Plain")
        p = self.para("")
        head, _, tail = tr(lang, ABSTRACT_COUNTS).partition("{pages}")  # the page count is Word's field
        p.add_run(head)
        self._field(p, "NUMPAGES", str(self.pages.get("total") or ""))
        tail = tail.format(figures=c["figures"], tables=c["tables"], sources=c["sources"])
        if c["appendices"]:
            tail += tr(lang, APPENDIX_COUNT).format(appendices=c["appendices"])
        p.add_run(tail)
        self.para(", ".join(b.keywords).upper())
        for text in b.text:
            self.para(text)

    def toc_entries(self) -> list[tuple[int, str]]:
        """The contents' entries (level, text) as the headings of levels 1–2 will read in Word."""
        out = []
        for b in self.doc.blocks:
            if not isinstance(b, Heading):
                continue
            if b.kind == "structural":
                if b.outlined:
                    out.append((1, b.text.upper()))
            elif b.kind == "appendix":
                word = tr(self.doc.lang, "Appendix").upper()
                out.append((1, word + " " + b.number))
            elif b.level <= 2:
                out.append((b.level, f"{b.number} {b.text}"))
        return out

    def contents(self) -> None:
        """A TOC field with its result written: the entries, each with its page as typst laid the
        note out (when the PDF was made in the same run), a dotted leader to the number. LibreOffice
        shows the result as it is (it ignores updateFields); Word offers to update it on opening;
        either rebuilds it after editing (F9 / Tools ▸ Update)."""
        from docx.enum.text import WD_ALIGN_PARAGRAPH, WD_TAB_ALIGNMENT, WD_TAB_LEADER
        from docx.oxml import OxmlElement
        from docx.oxml.ns import qn
        from docx.shared import Cm

        entries = self.toc_entries()
        pages = self.pages.get("pages") or []
        if len(pages) != len(entries):
            pages = [""] * len(entries)
        if not entries:
            p = self.para("", indent=False)
            self._field(p, 'TOC \\o "1-2" \\h \\z \\u', tr(self.doc.lang, "Update the field (F9) to build the contents."))
            return
        paras = []
        for k, ((level, text), page) in enumerate(zip(entries, pages)):
            p = self.para("", indent=False)
            pf = p.paragraph_format
            pf.left_indent = Cm(0.5 * (level - 1))
            pf.first_line_indent = Cm(0)
            pf.alignment = WD_ALIGN_PARAGRAPH.LEFT
            pf.tab_stops.add_tab_stop(Cm(TEXT_CM), WD_TAB_ALIGNMENT.RIGHT, WD_TAB_LEADER.DOTS)
            if k == 0:
                self._field_start(p, 'TOC \\o "1-2" \\h \\z \\u')
            self.inline(p, text)
            p.add_run("\t" + str(page))
            paras.append(p)
        r = OxmlElement("w:r")
        fc = OxmlElement("w:fldChar")
        fc.set(qn("w:fldCharType"), "end")
        r.append(fc)
        paras[-1]._p.append(r)

    def _field_start(self, paragraph, code: str) -> None:
        """A field's begin, code and separator: its result follows (over several paragraphs)."""
        from docx.oxml import OxmlElement
        from docx.oxml.ns import qn

        for kind, text in (("begin", None), (None, code), ("separate", None)):
            r = OxmlElement("w:r")
            if kind:
                fc = OxmlElement("w:fldChar")
                fc.set(qn("w:fldCharType"), kind)
                r.append(fc)
            else:
                it = OxmlElement("w:instrText")
                it.set(qn("xml:space"), "preserve")
                it.text = f" {text} "
                r.append(it)
            paragraph._p.append(r)

    def heading(self, b: Heading) -> None:
        from docx.enum.text import WD_ALIGN_PARAGRAPH

        if b.kind == "structural":
            style = "Structural" if b.outlined else "Structural Plain"
            self.para(b.text.upper(), style=style)
            return
        if b.kind == "appendix":
            word = tr(self.doc.lang, "Appendix").upper()
            p = self._styled(self.d.add_paragraph(), "Structural")
            p.add_run(f"{word} {b.number}")
            p2 = self.para(f"({b.status})", indent=False, align=WD_ALIGN_PARAGRAPH.CENTER)
            p2.paragraph_format.keep_with_next = True
            p3 = self.para(b.text, indent=False, align=WD_ALIGN_PARAGRAPH.CENTER, bold=True)
            p3.paragraph_format.keep_with_next = True
            return
        p = self._styled(self.d.add_paragraph(), f"Heading {min(b.level, 2)}")
        self.inline(p, f"{b.number} {b.text}")

    def formula(self, b: Formula) -> None:
        from docx.enum.table import WD_TABLE_ALIGNMENT
        from docx.enum.text import WD_ALIGN_PARAGRAPH
        from docx.shared import Cm

        if b.numbered:
            t = self.d.add_table(rows=1, cols=3)
            t.alignment = WD_TABLE_ALIGNMENT.CENTER
            self._grid(t, (1.5, TEXT_CM - 3.0, 1.5))
            mid = t.rows[0].cells[1].paragraphs[0]
            mid.paragraph_format.first_line_indent = Cm(0)
            mid.alignment = WD_ALIGN_PARAGRAPH.CENTER
            mid._p.append(omath_para(b.math))
            num = t.rows[0].cells[2].paragraphs[0]
            num.paragraph_format.first_line_indent = Cm(0)
            num.alignment = WD_ALIGN_PARAGRAPH.RIGHT
            num.add_run(f"({b.number})")
            from docx.enum.table import WD_CELL_VERTICAL_ALIGNMENT

            for cell in t.rows[0].cells:
                cell.vertical_alignment = WD_CELL_VERTICAL_ALIGNMENT.CENTER
            self._no_split(t.rows[0])
        else:
            p = self.para("", indent=False, align=WD_ALIGN_PARAGRAPH.CENTER)
            p._p.append(omath_para(b.math))
        for i, w in enumerate(b.where):
            word = tr(self.doc.lang, "where") + " " if i == 0 else ""
            p = self.para("", indent=False)
            if i:
                p.paragraph_format.left_indent = Cm(1.0)
            p.paragraph_format.keep_with_next = i < len(b.where) - 1
            self.inline(p, f"{word}${w.symbol}$ – {w.meaning}" + (";" if i < len(b.where) - 1 else ""))

    @staticmethod
    def _grid(t, widths_cm) -> None:
        """A table of fixed column widths: the grid (w:gridCol, which LibreOffice lays the columns
        out by — python-docx leaves it at equal thirds of the page, so a formula's middle cell was
        5,5 cm wide and cut the formula), each cell's width and a fixed layout (Word)."""
        from docx.oxml import OxmlElement
        from docx.oxml.ns import qn
        from docx.shared import Cm

        t.autofit = False
        for col, w in zip(t._tbl.tblGrid.findall(qn("w:gridCol")), widths_cm):
            col.set(qn("w:w"), str(int(Cm(w).twips)))
        for row in t.rows:
            for cell, w in zip(row.cells, widths_cm):
                cell.width = Cm(w)
        pr = t._tbl.tblPr
        tw = pr.find(qn("w:tblW"))
        if tw is None:
            tw = OxmlElement("w:tblW")
            pr.append(tw)
        tw.set(qn("w:type"), "dxa")
        tw.set(qn("w:w"), str(int(Cm(sum(widths_cm)).twips)))

    def _no_split(self, row) -> None:
        from docx.oxml import OxmlElement

        trpr = row._tr.get_or_add_trPr()
        trpr.append(OxmlElement("w:cantSplit"))

    def table(self, b: Table) -> None:
        from docx.enum.table import WD_TABLE_ALIGNMENT
        from docx.enum.text import WD_ALIGN_PARAGRAPH
        from docx.oxml import OxmlElement
        from docx.shared import Cm

        cap = self.para("", style="Caption", indent=False, align=WD_ALIGN_PARAGRAPH.LEFT)
        cap.paragraph_format.keep_with_next = True
        word = tr(self.doc.lang, "Table")
        cap.add_run(word + " ")
        self._seq(cap, word, b.number)
        self.inline(cap, " – " + b.caption)
        n = len(b.header)
        t = self.d.add_table(rows=1 + len(b.rows), cols=n)
        t._tbl.tblPr.get_or_add_tblStyle().val = "TableGrid"
        t.alignment = WD_TABLE_ALIGNMENT.CENTER
        self._grid(t, column_widths([b.header, *b.rows], self.doc, b.widths))
        aligns = b.align or ["left"] + ["center"] * (n - 1)
        amap = {"left": WD_ALIGN_PARAGRAPH.LEFT, "center": WD_ALIGN_PARAGRAPH.CENTER, "right": WD_ALIGN_PARAGRAPH.RIGHT}
        for j, h in enumerate(b.header):
            p = self._styled(t.rows[0].cells[j].paragraphs[0], "Table Text")
            p.alignment = WD_ALIGN_PARAGRAPH.CENTER
            self.inline(p, h, in_table=True)
        hdr = t.rows[0]._tr.get_or_add_trPr()
        hdr.append(OxmlElement("w:tblHeader"))  # repeated on every page the table runs over
        for i, row in enumerate(b.rows, 1):
            for j, cell in enumerate(row):
                p = self._styled(t.rows[i].cells[j].paragraphs[0], "Table Text")
                p.alignment = amap.get(aligns[j] if j < len(aligns) else "left")
                self.inline(p, cell, in_table=True)
            self._no_split(t.rows[i])
        self.para("", indent=False)

    def _seq(self, paragraph, name: str, number: str) -> None:
        """A caption number: a SEQ field (Word renumbers after edits) unless it is an appendix's А.1."""
        if "." in number:
            paragraph.add_run(number)
        else:
            self._field(paragraph, f"SEQ {name} \\* ARABIC", number)

    def figure(self, b: Figure) -> None:
        from docx.enum.text import WD_ALIGN_PARAGRAPH
        from docx.shared import Cm

        p = self.para("", indent=False, align=WD_ALIGN_PARAGRAPH.CENTER)
        p.paragraph_format.keep_with_next = True
        png = self.folder / b.raster if b.raster else None
        if png is None or not png.exists():
            return
        run = p.add_run()
        run.add_picture(str(png), width=Cm(min(b.width_cm, TEXT_CM)))
        svg = self.folder / b.file
        if svg.exists() and svg.suffix == ".svg":
            self._svg_beside(run, svg)
        cap = self.para("", style="Caption", indent=False, align=WD_ALIGN_PARAGRAPH.CENTER)
        word = tr(self.doc.lang, "Figure")
        cap.add_run(word + " ")
        self._seq(cap, word, b.number)
        self.inline(cap, " – " + b.caption)

    def _svg_beside(self, run, svg: Path) -> None:
        """The SVG as the picture Word 2016+ shows (asvg:svgBlip), the PNG kept for other readers."""
        from docx.opc.constants import RELATIONSHIP_TYPE as RT
        from docx.opc.packuri import PackURI
        from docx.opc.part import Part
        from docx.oxml.ns import qn
        from lxml import etree

        data = svg.read_bytes().replace(b"font-family: 'Liberation Serif'",
                                        b"font-family: 'Times New Roman', 'Liberation Serif', serif")
        package = self.d.part.package
        n = sum(1 for p in package.iter_parts() if str(p.partname).endswith(".svg")) + 1
        part = Part(PackURI(f"/word/media/tmm_svg{n}.svg"), "image/svg+xml", data, package)
        rid = self.d.part.relate_to(part, RT.IMAGE)
        blip = run._r.findall(".//" + qn("a:blip"))[-1]
        ext_lst = etree.SubElement(blip, qn("a:extLst"))
        ext = etree.SubElement(ext_lst, qn("a:ext"))
        ext.set("uri", SVG_EXT)
        sb = etree.SubElement(ext, f"{{{ASVG}}}svgBlip", nsmap={"asvg": ASVG})
        sb.set(qn("r:embed"), rid)


def write_docx(doc: Document, path: Path, folder: Path, title, pages: dict | None = None) -> Path:
    """note.docx from the document; TmmError if it cannot be written. `pages`: typst's page of each
    heading of the contents and the page count (:func:`.typeset.page_numbers`), the fields' results."""
    from ...errors import TmmError

    try:
        import docx  # noqa: F401
    except ImportError:  # pragma: no cover - a dependency
        raise TmmError("cannot write the note for Word (python-docx is missing; reinstall tmm)") from None
    try:
        DocxWriter(doc, folder, title, pages).write(Path(path))
    except OSError as exc:
        raise TmmError(f"cannot write the note for Word ({exc.strerror})") from None
    return Path(path)


def docx_text(path: Path) -> str:
    """The text of a DOCX (paragraphs, tables, equations as their plain text, without the units' word
    joiners) — for the tests."""
    import docx
    from docx.oxml.ns import qn

    d = docx.Document(str(path))
    body = d.element.body
    out = []
    for p in body.iter(qn("w:p")):
        text = "".join(t.text or "" for t in p.iter() if t.tag in (qn("w:t"), qn("m:t")))
        if text.strip():
            out.append(text)
    return "\n".join(out).replace(WORD_JOINER, "")  # as it reads



def _plain(text: str) -> str:
    """A cell's text as it reads (its math as text), for measuring."""
    from .mathsyntax import parse, to_text

    out = []
    for is_math, piece in split_math(text):
        if is_math:
            try:
                piece = to_text(parse(piece), html=False).replace("_", "").replace("(", "").replace(")", "")
            except ValueError:
                pass
        out.append(piece)
    return "".join(out)


def column_widths(rows: list[list[str]], doc=None, given=None) -> list[float]:
    """Column widths [cm] of a table from its text at 12 pt: every column at least as wide as its
    longest word or number (a number never breaks: «51 312,|7» and «Отклоне|ние» were LibreOffice
    breaking columns of equal width), the rest of the 16,5 cm shared by what the columns' whole
    texts would need beyond that.

    >>> w = column_widths([["№", "Отклонение, %", "Значение"], ["1", "−51 312,7", "3"]])
    >>> round(sum(w), 1), w[0] < w[1]
    (16.5, True)
    """
    char = 0.23  # cm: the mean width of a character of Times New Roman at 12 pt, with room
    pad = 0.4  # the cell's margins
    n = max(len(r) for r in rows)
    lo, hi = [0.6] * n, [0.6] * n
    for r in rows:
        for j, cell in enumerate(r):
            text = _plain(doc.resolve(cell) if doc is not None else cell)
            # a number with its thousands' narrow spaces is one word
            longest = max((len(w) for w in text.replace("\u202f", "0").replace("\u00a0", "0").split()), default=0)
            lo[j] = max(lo[j], longest * char + pad)
            hi[j] = max(hi[j], len(text) * char + pad)
    if sum(lo) >= TEXT_CM:
        return [w * TEXT_CM / sum(lo) for w in lo]
    if given:  # the chapter's proportions, each column widened to its longest word
        want = [TEXT_CM * g / sum(given) for g in given]
        for _ in range(n):
            short = [j for j in range(n) if want[j] < lo[j] - 1e-9]
            if not short:
                break
            need = sum(lo[j] - want[j] for j in short)
            for j in short:
                want[j] = lo[j]
            rest = [j for j in range(n) if j not in short and want[j] > lo[j]]
            room = sum(want[j] - lo[j] for j in rest)
            for j in rest:
                want[j] -= need * (want[j] - lo[j]) / room if room > 0 else 0
        return want
    extra = [h - w for h, w in zip(hi, lo)]
    spare = TEXT_CM - sum(lo)
    if sum(extra) <= spare:  # every text on one line: the rest in proportion to the texts
        return [h + (TEXT_CM - sum(hi)) * h / sum(hi) for h in hi]
    return [w + spare * e / sum(extra) for w, e in zip(lo, extra)]
