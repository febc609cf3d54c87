"""Answers that differ from the program's design but follow the book: they pass, marked as such.

* a planetary set that meets every condition of §2.1.3 with the ratio within the tolerance — a
  *valid alternative* (:mod:`.reducer`); its ratio and ratio error are then checked against it;
* the book's two-line cam vertex, the book's roller 0.2·r0 (1.28), and for a rocker the smallest
  cam of the other swing (issue 8).
"""

from __future__ import annotations

from dataclasses import replace

from ..notes import Note
from .rows import KEYS_BY_NAME, CheckRow, row_against
from .reducer import STAGE_KEYS, student_reducer


def accept_valid_reducer(rows: tuple[CheckRow, ...], answers: dict, gears, doc: dict,
                         rtol_pct: float) -> tuple[tuple[CheckRow, ...], list[Note], object]:
    """Tooth numbers and planets that differ from the carried reducer but satisfy all five
    conditions of §2.1.3 (ratio within the tolerance, coaxiality, assembly, neighbouring, Table
    2.2) pass as "pass (valid alternative)": the book's hand procedure and the search may rightly
    give different sets (variant 17 at 95 rpm: 18/47/112 by the book, 17/46/109 by the search), and
    any k the set admits fits (35/25/85 with k = 3 at 220 rpm). The set's ratio ``i_kh`` and its
    error ``ratio_error_pct`` are then compared with that set's. A set that breaks a condition
    keeps its failed rows, each told the first condition it breaks; the findings name them all.

    `answers` are by answer key (:func:`~tmm_cli.teacher.check.resolved`). Returns (rows, findings,
    the student's reducer or None when incomplete).
    """
    red = student_reducer(answers, gears.scheme, gears.i_planetary, gears.tolerance_pct)
    if red is None:
        return rows, [], None
    n_stages = len(red.stages)
    used = [k for keys in STAGE_KEYS[:n_stages] for k in keys if k and (k != "z_planet2" or gears.scheme == "2")]
    carried = tuple(gears.planetary.stages)
    same = tuple(red.stages) == carried
    findings: list[Note] = []
    planets_keys = [keys[4] for keys in STAGE_KEYS[:n_stages]]
    out = []
    if red.valid:
        if not same:
            findings.append(Note.make("alt_valid", teeth=red.teeth_text, k="+".join(str(s.planets) for s in red.stages),
                                      err=round(red.ratio_error_pct, 2), tol=float(gears.tolerance_pct)))
        fewer = [(j, s.planets, km) for j, (s, km) in enumerate(zip(red.stages, red.k_max), start=1) if s.planets < km]
        for j, k, km in fewer:
            findings.append(Note.make("alt_fewer_planets" + ("_stage" if n_stages > 1 else ""), stage=j, k=k, k_max=km))
        for r in rows:
            if r.key in used and r.status == "fail":
                cause = None
                if r.key in planets_keys:
                    j = planets_keys.index(r.key)
                    s, km = red.stages[j], red.k_max[j]
                    cause = Note.make("alt_fewer_planets" + ("_stage" if n_stages > 1 else ""), stage=j + 1, k=s.planets,
                                      k_max=km) if s.planets < km else None
                r = replace(r, status="pass (valid alternative)", basis="student_set", cause=cause or
                            Note.make("alt_valid", teeth=red.teeth_text, k="+".join(str(s.planets) for s in red.stages),
                                      err=round(red.ratio_error_pct, 2), tol=float(gears.tolerance_pct)))
            elif r.key in ("i_kh", "ratio_error_pct") and not same and r.status in ("pass", "fail"):
                mine = red.ratio if r.key == "i_kh" else red.ratio_error_pct
                r = replace(row_against(doc, KEYS_BY_NAME[r.key], round(mine, 6), r.given, rtol_pct, basis="student_set",
                                        written=r.written, program=r.expected))
            out.append(r)
        return tuple(out), findings, red
    if not same:
        findings.append(Note.make("set_invalid", teeth=red.teeth_text, k="+".join(str(s.planets) for s in red.stages)))
        findings += list(red.problems)
    for r in rows:
        if r.key in used and r.status == "fail" and r.cause is None:
            r = replace(r, cause=red.problems[0])
        elif r.key in ("i_kh", "ratio_error_pct") and r.status == "fail" and red.ratio is not None:
            mine = red.ratio if r.key == "i_kh" else red.ratio_error_pct
            if row_against(doc, KEYS_BY_NAME[r.key], round(mine, 6), r.given, rtol_pct).passed:
                r = replace(r, cause=Note.make("follows_your_set", teeth=red.teeth_text))
        out.append(r)
    return tuple(out), findings, red


BOOK_ROLLER_KEYS = ("r0_mm", "l_oc_mm", "e_mm", "roller_mm")


def accept_book_cam(rows: tuple[CheckRow, ...], answers: dict, cam, rtol_pct: float) -> tuple[CheckRow, ...]:
    """Cam answers that follow the book where the program carries a safer design (issue 8).

    * ``r0_mm``, ``e_mm``, ``l_oc_mm`` at the book's two-line vertex: "pass (book)" (the project
      document's ``book_vertex``);
    * ``roller_mm`` = 0.2·r0 (1.28) for the carried r0, its book vertex, or the student's own r0
      when that passed: "pass (book roller)" — the program carries min(0.2·r0, 0.8·ρ_min), and
      the report marks when the book's roller undercuts (see the cam's warning);
    * a rocker whose smallest cam (the book's swing choice, METHOD.md) put the pivot inside the
      swept circle, so the program carried the other swing: r0_mm / l_oc_mm of that smallest cam
      or of its book vertex pass as "pass (other swing)", the roller 0.2·r0 of it too.

    A row that passes so is compared with the design it matches (`basis`), the program's own
    value kept beside it (`program`).
    """
    failed = {r.key for r in rows if r.status == "fail"} & set(BOOK_ROLLER_KEYS)
    if not failed:
        return rows
    from ..cam.design import CamChoice, design_cam
    from ..cam.profile import ROLLER_RULE

    z, p = cam.sizing, cam.profile

    def near(given, values, scale=None):
        """The first of `values` within the tolerance of `given`, or None."""
        for v in values:
            if v is None:
                continue
            sc = abs(scale if scale is not None else v)
            if sc > 0 and abs(float(given) - v) <= (rtol_pct + 1e-9) / 100.0 * sc:
                return v
        return None

    other = None
    if cam.source == "program" and cam.pivot_move == "swing" and z.swing in ("same", "opposite"):
        other = design_cam(cam.variant, step_deg=cam.step_deg,
                           choice=CamChoice(swing="same" if z.swing == "opposite" else "opposite"))
    # (r0 [mm], the largest roller without undercut [mm]) of each design a student may have drawn
    designs = [(z.r0_m * 1e3, p.roller_max_m * 1e3), (z.book_r0_m * 1e3, p.roller_max_m * 1e3)]
    if other is not None:
        oz, op = other.sizing, other.profile
        designs += [(oz.r0_m * 1e3, op.roller_max_m * 1e3), (oz.book_r0_m * 1e3, op.roller_max_m * 1e3)]
    out = []
    for r in rows:
        st, basis, expected = r.status, r.basis, r.expected
        if st == "fail" and r.key in ("r0_mm", "e_mm", "l_oc_mm"):
            book = {"r0_mm": z.book_r0_m, "e_mm": getattr(z, "book_e_m", None), "l_oc_mm": z.book_l_oc_m}[r.key]
            scale = z.r0_m * 1e3 if r.key == "e_mm" else None
            hit = near(r.given, (None if book is None else book * 1e3,), scale)
            if hit is not None:
                st, basis, expected = "pass (book)", "book_vertex", hit
        if st == "fail" and other is not None and r.key == "r0_mm":
            hit = near(r.given, (other.sizing.r0_m * 1e3, other.sizing.book_r0_m * 1e3))
            if hit is not None:
                st, basis, expected = "pass (other swing)", "other_swing", hit
        elif st == "fail" and other is not None and r.key == "l_oc_mm":
            hit = near(r.given, (other.sizing.l_oc_m and other.sizing.l_oc_m * 1e3,
                                 other.sizing.book_l_oc_m and other.sizing.book_l_oc_m * 1e3))
            if hit is not None:
                st, basis, expected = "pass (other swing)", "other_swing", hit
        out.append(r if st == r.status else _moved(r, st, basis, expected))
    # the roller: 0.2·r0 of any design above, or of the student's own r0 when that passed
    status = {r.key: r.status for r in out}
    given_r0 = answers.get("r0_mm")
    if isinstance(given_r0, (int, float)) and status.get("r0_mm", "").startswith("pass"):
        designs.append((float(given_r0), (other.profile if status["r0_mm"] == "pass (other swing)" else p).roller_max_m * 1e3))
    final = []
    for r in out:
        if r.status == "fail" and r.key == "roller_mm":
            hits = [(ROLLER_RULE * r0, lim) for r0, lim in designs if near(r.given, (ROLLER_RULE * r0,)) is not None]
            if hits:
                st = "pass (book roller)" if any(float(r.given) < lim for _, lim in hits) else "pass (book roller, undercuts)"
                r = _moved(r, st, "book_roller", hits[0][0])
        final.append(r)
    return tuple(final)


def _moved(r: CheckRow, status: str, basis: str, expected: float) -> CheckRow:
    """The row compared with another design's value `expected` (the program's kept as `program`)."""
    dev = float(r.given) - float(expected)
    pct = None if not expected else 100.0 * dev / abs(float(expected))
    if r.key == "e_mm" and r.tolerance and r.tolerance_pct:  # e's tolerance is a share of r0
        pct = 100.0 * dev / (r.tolerance * 100.0 / r.tolerance_pct)
    return replace(r, status=status, basis=basis, expected=round(float(expected), 4), deviation=dev, deviation_pct=pct,
                   program=r.expected)
