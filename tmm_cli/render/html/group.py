"""group.html: the group at a glance, one self-contained static page.

A row per student (status, key numbers, deviations coloured, warnings in words, links to the
student's note, sheets and feedback), sorting and filtering by a few lines of vanilla JavaScript,
the group's statistics (how many passed each check) and small inline SVG histograms, and a print
stylesheet for A4 landscape. Nothing is fetched: no network, no external script, font or image.

The page is described by plain records (:class:`GroupPage`), built by teacher/group.py from a
batch's summary rows and a check's reports; this module only writes HTML.
"""

from __future__ import annotations

import html
import math
from urllib.parse import quote

from ...i18n import tr
from ...i18n.numbers import num
from ...records import record


@record
class PageCell:
    text: str
    level: str = ""  # "good", "bad", "warn" or "" (the colour of the cell)
    sort: object = None  # the value rows are sorted by (a number, or the text)
    title: str = ""  # shown on hover: the detail (expected value, deviation, cause)


@record
class PageLink:
    label: str
    href: str  # relative to the page's folder, with '/' separators


@record
class PageRow:
    status: str  # a filter value: "ok", "failed", "not run", "passed", "not passed", "error"
    cells: tuple  # PageCell per column
    links: tuple = ()  # PageLink
    detail: str = ""  # a line under the row: the error, the warnings in words


@record
class Stat:
    label: str
    passed: int
    total: int


@record
class Chart:
    title: str
    values: tuple  # the numbers to bin
    unit: str = ""
    band: float | None = None  # ± this value is shaded (the tolerance)


@record
class GroupPage:
    lang: str
    title: str
    subtitle: str
    columns: tuple  # (label, numeric: bool)
    rows: tuple  # PageRow
    statuses: tuple  # (value, label) for the status filter
    stats: tuple = ()  # Stat
    charts: tuple = ()  # Chart
    remarks: tuple = ()  # lines under the table (files that matched no student …)


_CSS = """
:root { --good: #1b7a32; --good-bg: #e3f4e6; --bad: #b3261e; --bad-bg: #fbe4e2; --warn: #8a5a00; --warn-bg: #fdf1d6;
        --line: #c8c8c8; --muted: #5f6368; }
* { box-sizing: border-box; }
body { font-family: "Liberation Sans", "DejaVu Sans", Arial, sans-serif; font-size: 14px; margin: 16px 20px; color: #202124; }
h1 { font-size: 20px; margin: 0 0 4px; } h2 { font-size: 15px; margin: 18px 0 6px; }
.sub { color: var(--muted); margin: 0 0 12px; }
.top { display: flex; flex-wrap: wrap; gap: 24px; align-items: flex-start; }
table.stats { border-collapse: collapse; } table.stats td { padding: 2px 8px 2px 0; }
.meter { display: inline-block; width: 120px; height: 10px; background: var(--bad-bg); vertical-align: middle; }
.meter > span { display: block; height: 100%; background: var(--good); }
figure { margin: 0; } figcaption { font-size: 12px; color: var(--muted); }
svg text { font-family: inherit; font-size: 10px; fill: #202124; }
.controls { margin: 14px 0 8px; display: flex; gap: 12px; align-items: center; }
.controls input { font: inherit; padding: 3px 6px; width: 18em; } .controls select { font: inherit; padding: 2px; }
table.group { border-collapse: collapse; width: 100%; }
table.group th, table.group td { border: 1px solid var(--line); padding: 3px 6px; vertical-align: top; }
table.group th { background: #f1f3f4; cursor: pointer; user-select: none; white-space: nowrap; text-align: left; }
table.group th.num, table.group td.num { text-align: right; }
table.group th[aria-sort="ascending"]::after { content: " ▲"; } table.group th[aria-sort="descending"]::after { content: " ▼"; }
td.good { background: var(--good-bg); color: var(--good); } td.bad { background: var(--bad-bg); color: var(--bad); font-weight: bold; }
td.warn { background: var(--warn-bg); color: var(--warn); }
td.links a { margin-right: 6px; white-space: nowrap; }
tr.detail td { border-top: none; color: var(--muted); font-size: 12px; padding-top: 0; }
.count { color: var(--muted); }
ul.remarks { color: var(--warn); }
@page { size: A4 landscape; margin: 8mm; }
@media print {
  body { margin: 0; font-size: 9pt; } .controls, .noprint { display: none !important; }
  table.group th, table.group td { padding: 1px 3px; } table.group th { cursor: auto; }
  table.group th[aria-sort]::after { content: ""; }
  tr { break-inside: avoid; } thead { display: table-header-group; }
  a { color: inherit; text-decoration: none; } td.links { font-size: 8pt; }
  td.good, td.bad, td.warn { -webkit-print-color-adjust: exact; print-color-adjust: exact; }
}
"""

# sorting (a click on a column head) and filtering (text, status): no library, no network
_JS = """
(function () {
  var table = document.getElementById("group"), body = table.tBodies[0];
  function groups() {  // a student's row and its detail line move together
    var out = [], rows = body.rows;
    for (var i = 0; i < rows.length; i++) {
      if (rows[i].classList.contains("detail")) { out[out.length - 1].push(rows[i]); } else { out.push([rows[i]]); }
    }
    return out;
  }
  function key(row, col) {
    var cell = row.cells[col], v = cell ? cell.getAttribute("data-sort") : "";
    var n = parseFloat(v);
    return (v !== null && v !== "" && !isNaN(n) && isFinite(v)) ? [0, n] : [1, (v || (cell ? cell.textContent : "")).toLowerCase()];
  }
  var heads = table.tHead.rows[0].cells;
  for (var c = 0; c < heads.length; c++) {
    (function (col) {
      heads[col].addEventListener("click", function () {
        var asc = heads[col].getAttribute("aria-sort") !== "ascending";
        for (var h = 0; h < heads.length; h++) { heads[h].removeAttribute("aria-sort"); }
        heads[col].setAttribute("aria-sort", asc ? "ascending" : "descending");
        var gs = groups();
        gs.sort(function (a, b) {
          var x = key(a[0], col), y = key(b[0], col);
          var r = x[0] - y[0] || (x[1] < y[1] ? -1 : x[1] > y[1] ? 1 : 0);
          return asc ? r : -r;
        });
        gs.forEach(function (g) { g.forEach(function (r) { body.appendChild(r); }); });
      });
    })(c);
  }
  var text = document.getElementById("filter"), status = document.getElementById("status");
  function filter() {
    var q = text.value.trim().toLowerCase(), s = status.value;
    groups().forEach(function (g) {
      var show = (!s || g[0].getAttribute("data-status") === s) &&
                 (!q || g.map(function (r) { return r.textContent; }).join(" ").toLowerCase().indexOf(q) >= 0);
      g.forEach(function (r) { r.hidden = !show; });
    });
  }
  text.addEventListener("input", filter);
  status.addEventListener("change", filter);
})();
"""


def _e(text) -> str:
    """Text for the page: HTML escaped, control characters shown as codes (inputs/names.visible)."""
    from ...inputs.names import visible

    return html.escape(visible("" if text is None else str(text)), quote=True)


def _href(path: str) -> str:
    """A relative link: each path component percent-encoded (names may hold spaces and Cyrillic)."""
    return "/".join(quote(part, safe="") for part in path.split("/"))


def histogram(values, lo: float | None = None, hi: float | None = None, bins: int = 10) -> tuple[list[int], float, float]:
    """(counts, lower edge, upper edge) of `values` in `bins` equal bins.

    >>> histogram([0.0, 0.5, 1.0, 1.0], bins=2)
    ([1, 3], 0.0, 1.0)
    """
    vals = [float(v) for v in values if v is not None and math.isfinite(float(v))]
    if not vals:
        return [0] * bins, 0.0, 1.0
    lo = min(vals) if lo is None else lo
    hi = max(vals) if hi is None else hi
    if hi - lo < 1e-12:
        lo, hi = lo - 0.5, hi + 0.5
    counts = [0] * bins
    for v in vals:
        i = int((v - lo) / (hi - lo) * bins)
        counts[min(max(i, 0), bins - 1)] += 1
    return counts, lo, hi


def chart_svg(chart: Chart, lang: str, width: int = 300, height: int = 130) -> str:
    """A small histogram as inline SVG (bars with their counts, the range below, the tolerance band
    shaded)."""
    vals = [float(v) for v in chart.values if v is not None and math.isfinite(float(v))]
    if chart.band is not None and vals:
        reach = max(max(abs(v) for v in vals), chart.band * 1.5)
        counts, lo, hi = histogram(vals, -reach, reach, bins=12)
    else:
        counts, lo, hi = histogram(vals, bins=10)
    left, right, top, bottom = 6, 6, 14, 28
    w, h = width - left - right, height - top - bottom
    peak = max(counts) or 1
    parts = [f'<svg width="{width}" height="{height}" viewBox="0 0 {width} {height}" '
             f'role="img" aria-label="{_e(chart.title)}">']
    x_of = lambda v: left + (v - lo) / (hi - lo) * w  # noqa: E731
    if chart.band is not None and vals:
        a, b = x_of(max(lo, -chart.band)), x_of(min(hi, chart.band))
        parts.append(f'<rect x="{a:.1f}" y="{top}" width="{b - a:.1f}" height="{h}" fill="#e3f4e6"/>')
    bw = w / len(counts)
    for i, c in enumerate(counts):
        if not c:
            continue
        bh = c / peak * (h - 10)
        x = left + i * bw
        centre = lo + (i + 0.5) * (hi - lo) / len(counts)
        inside = chart.band is None or abs(centre) <= chart.band
        colour = "#5b8def" if chart.band is None else ("#1b7a32" if inside else "#b3261e")
        parts.append(f'<rect x="{x + 1:.1f}" y="{top + h - bh:.1f}" width="{bw - 2:.1f}" height="{bh:.1f}" fill="{colour}"/>')
        parts.append(f'<text x="{x + bw / 2:.1f}" y="{top + h - bh - 2:.1f}" text-anchor="middle">{c}</text>')
    parts.append(f'<line x1="{left}" y1="{top + h}" x2="{left + w}" y2="{top + h}" stroke="#5f6368"/>')
    fmt = lambda v: num(v, lang, sig=3, sci=False)  # noqa: E731
    parts.append(f'<text x="{left}" y="{top + h + 12}">{_e(fmt(lo))}</text>')
    parts.append(f'<text x="{left + w}" y="{top + h + 12}" text-anchor="end">{_e(fmt(hi))}</text>')
    if chart.band is not None and vals and lo < 0 < hi:
        parts.append(f'<text x="{x_of(0):.1f}" y="{top + h + 12}" text-anchor="middle">0</text>')
    caption = tr(lang, '{n} values').format(n=len(vals)) + (f", {chart.unit}" if chart.unit else "")
    parts.append(f'<text x="{left + w / 2:.1f}" y="{height - 3}" text-anchor="middle">{_e(caption)}</text>')
    if not vals:
        parts.append(f'<text x="{left + w / 2:.1f}" y="{top + h / 2:.1f}" text-anchor="middle">'
                     + _e(tr(lang, "no data")) + "</text>")
    parts.append("</svg>")
    return "".join(parts)


def group_html(page: GroupPage) -> str:
    """The page as one HTML document (UTF-8 text)."""
    lang = page.lang
    out = ["<!DOCTYPE html>", f'<html lang="{"ru" if lang == "ru" else "en"}">', "<head>", '<meta charset="utf-8">',
           '<meta name="viewport" content="width=device-width, initial-scale=1">',
           f"<title>{_e(page.title)}</title>", f"<style>{_CSS}</style>", "</head>", "<body>",
           f"<h1>{_e(page.title)}</h1>", f'<p class="sub">{_e(page.subtitle)}</p>', '<div class="top">']
    if page.stats:
        out.append('<section><h2>' + _e(tr(lang, 'How many passed each check'))
                   + '</h2><table class="stats"><tbody>')
        for s in page.stats:
            share = 0 if not s.total else round(100 * s.passed / s.total)
            out.append(f'<tr><td>{_e(s.label)}</td><td><span class="meter"><span style="width:{share}%"></span></span></td>'
                       f'<td class="count">{s.passed} / {s.total}</td></tr>')
        out.append("</tbody></table></section>")
    for ch in page.charts:
        out.append(f"<section><h2>{_e(ch.title)}</h2><figure>{chart_svg(ch, lang)}</figure></section>")
    out.append("</div>")
    placeholder, filter_label = _e(tr(lang, "Filter: a name, a number…")), _e(tr(lang, "Filter"))
    status_label, every = _e(tr(lang, "Status")), _e(tr(lang, "every status"))
    sort_hint = _e(tr(lang, "click a column head to sort"))
    out.append('<div class="controls noprint">'
               f'<input id="filter" type="search" placeholder="{placeholder}" aria-label="{filter_label}">'
               f'<select id="status" aria-label="{status_label}"><option value="">{every}</option>'
               + "".join(f'<option value="{_e(v)}">{_e(label)}</option>' for v, label in page.statuses)
               + f'</select><span class="count">{sort_hint}</span></div>')
    out.append('<table class="group" id="group"><thead><tr>')
    for label, numeric in page.columns:
        out.append(f'<th scope="col"{" class=num" if numeric else ""}>{_e(label)}</th>')
    out.append('<th scope="col">' + _e(tr(lang, "Files")) + "</th></tr></thead><tbody>")
    numeric_cols = [numeric for _, numeric in page.columns]
    for row in page.rows:
        out.append(f'<tr data-status="{_e(row.status)}">')
        for cell, numeric in zip(row.cells, numeric_cols):
            cls = " ".join(c for c in (cell.level, "num" if numeric else "") if c)
            attrs = (f' class="{cls}"' if cls else "") + (f' data-sort="{_e(cell.sort)}"' if cell.sort is not None else "") \
                + (f' title="{_e(cell.title)}"' if cell.title else "")
            out.append(f"<td{attrs}>{_e(cell.text)}</td>")
        links = " ".join(f'<a href="{_href(link.href)}">{_e(link.label)}</a>' for link in row.links)
        out.append(f'<td class="links">{links}</td></tr>')
        if row.detail:
            out.append(f'<tr class="detail" data-status="{_e(row.status)}"><td colspan="{len(page.columns) + 1}">'
                       f"{_e(row.detail)}</td></tr>")
    out.append("</tbody></table>")
    if page.remarks:
        out.append("<ul class=remarks>" + "".join(f"<li>{_e(r)}</li>" for r in page.remarks) + "</ul>")
    out.append(f"<script>{_JS}</script>")
    out.append("</body></html>")
    return "\n".join(out) + "\n"
