"""The chapter on the gear drive (sheet 4, book section 2), from a GearsResult.

Every choice is told from the decision the core took — the motor speed, the scheme, the simple
fraction of the book's procedure, the row of its tables, the tooth set carried by the search rule,
the number of planets, the rated power — with what was compared and by how much, and recorded as
a claim (:meth:`~.model.Document.claim`) that the tests check against the numbers.
"""

from __future__ import annotations

import math
import re
from fractions import Fraction

from ...gears.design import design_teeth_text
from ...gears.drive import RATED_POWER_KW
from ...gears.planetary.search import SELECT_SLACK, STAGE_RANGE_1
from .ctx import Ctx, V
from .model import Heading


def _fr(f: Fraction) -> str:
    """A fraction inside typst math."""
    return f"{f.numerator}/{f.denominator}" if f.denominator != 1 else f"{f.numerator}"


def _frt(f: Fraction) -> str:
    """A fraction in the text."""
    return f"{f.numerator}/{f.denominator}" if f.denominator != 1 else f"{f.numerator}"


INEXACT_PCT = 1.0  # a carried ratio this far off, with closer sets larger, is explained


def _teeth(design) -> str:
    return design_teeth_text(design)


def gears_chapter(c: Ctx) -> None:
    t = c.t
    c.doc.add(Heading(1, t("Synthesis of the gear mechanisms"), "chapter", "gears"))
    _motor(c)
    _scheme(c)
    _book(c)
    _search(c)
    _conditions(c)
    _ratio_checks(c)
    _spur(c)
    _power(c)


# --------------------------------------------------------------------------------------------------
def _motor(c: Ctx) -> None:
    g = c.r.gears
    t, n, q = c.t, c.n, c.q
    rpm = t("rpm")
    c.doc.add(Heading(2, t("Motor speed and gear ratios")))
    if g.crank_rpm_assumed:
        c.p(t("The crank speed of the linkage is not part of Table 1.2; it is taken as in the example of §2.4 {{cite:book}}, $n_\"кр\" = {crank_rpm}$ rpm (see the assumptions).").format(crank_rpm=q(g.crank_rpm)))
    else:
        c.p(t("The crank of the linkage turns at $n_\"кр\" = {crank_rpm}$ rpm.").format(crank_rpm=q(g.crank_rpm)))
    cands = ", ".join(str(x) for x in g.motor_candidates)
    low = [x for x in g.motor_candidates if x < 3 * g.crank_rpm]
    rejected = ""
    if low:
        rejected = c.nt(" ({speeds} rpm is below this)", " ({speeds} rpm are below this)", len(low)).format(
            speeds=", ".join(map(str, low)))
    c.p(t("The motor speed is the smallest of the standard speeds ({cands} rpm) that is at least three times the crank speed (§2.2 {{cite:book}}), so that the planetary reducer has a ratio of at least 3{rejected}:").format(cands=cands, rejected=rejected))
    c.formula(c.calc('n_"д" >= 3 n_"кр"', "3 dot {0}", [V(g.crank_rpm, exact=True)], V(3 * g.crank_rpm, exact=True), rpm)
              + f'; quad n_"д" = {g.motor_rpm} {c.u(rpm)}', where=['n_"д"', 'n_"кр"'])
    c.doc.claim(kind="motor_speed", chosen=g.motor_rpm, candidates=tuple(g.motor_candidates), crank=g.crank_rpm)
    c.p(t("The required ratios of the spur pair (motor to cam) and of the planetary reducer (motor to crank):"))
    c.formula(c.calc('i_"д" = n_"д"/(|n_"к"|)', "{0}/{1}", [V(g.motor_rpm, exact=True), V(abs(g.cam_rpm), exact=True)],
                     V(g.i_spur, sig=4)),
              c.calc('i_"пл" = n_"д"/n_"кр"', "{0}/{1}", [V(g.motor_rpm, exact=True), V(g.crank_rpm, exact=True)],
                     V(g.i_planetary, sig=5)), where=['i_"д"', 'i_"пл"'])
    rot = {"cw": t("clockwise"), "ccw": t("counter-clockwise")}
    d = g.directions
    c.p(t("The cam turns {rot}; the spur pair is an external mesh and reverses the sense, so the motor turns {rot2}; the planetary reducer keeps the sense, and the crank turns {rot3}.").format(rot=rot[d.cam], rot2=rot[d.motor], rot3=rot[d.crank]))


# --------------------------------------------------------------------------------------------------
def _scheme_math(text: str) -> str:
    """The formulas of drive.SCHEMES ("i = 1 + z_n/z_k") as typst math."""
    out = text.replace("·", " dot ").replace("′", "'")
    out = out.replace("z_c'", "z'_c").replace("z_k'", "z'_k")
    return re.sub(r"z_([a-z])(\d)", r"z_(\1 \2)", out)


def _scheme(c: Ctx) -> None:
    g = c.r.gears
    t, n = c.t, c.n
    c.doc.add(Heading(2, t("Scheme of the planetary reducer")))
    rows = []
    for s in g.schemes:
        rows.append([str(s.number), f"{n(s.i_min)}…{n(s.i_max)}", f"{n(s.eta_max)}…{n(s.eta_min)}",
                     "$" + _scheme_math(s.formula) + "$"])
    i = c.q(g.i_planetary, sig=4)
    why = {
        "le8": t("Since $i_\"пл\" = {i} <= 8$, the single-row reducer of scheme 1 is taken: of the schemes that give this ratio it has the highest efficiency and the simplest design.").format(i=i),
        "8to16": t("Since $8 < i_\"пл\" = {i} <= 16$, the double-row reducer of scheme 2 is taken: a single row gives at most 8, schemes 4 and 5 have a low efficiency.").format(i=i),
        "gt16": t("Since $i_\"пл\" = {i} > 16$, two single-row stages in series are taken (scheme 3), each with a ratio near $sqrt(i_\"пл\") = {i_planetary}$ (§2.2 {{cite:book}}); schemes 4 and 5 would give the ratio only with a low efficiency.").format(i=i, i_planetary=c.q(math.sqrt(g.i_planetary), sig=3)),
    }[g.scheme_reason]
    c.p(t("The schemes of planetary reducers of Figure 2.4 {cite:book} are compared in Table {tab:schemes}. ") + why)
    c.table("schemes", t("Schemes of planetary reducers"),
            ["№", t("Range of $i$"), t("Efficiency"), t("Ratio")],
            rows, align=["center", "center", "center", "left"], widths=[0.5, 1.2, 1.2, 4])
    c.doc.claim(kind="scheme", chosen=g.scheme, i_pl=g.i_planetary)


# --------------------------------------------------------------------------------------------------
def _book(c: Ctx) -> None:
    g = c.r.gears
    t, n = c.t, c.n
    c.doc.add(Heading(2, t("Tooth numbers by the textbook's procedure")))
    der = g.derivation
    if der is None:
        c.p(t("The textbook's procedure gives no tooth numbers for any simple fraction within the tolerance; the tooth numbers are found by the search below."))
        return
    sec = {"1": "2.4", "2": "2.5", "1+1": "2.4"}[der.scheme]
    tol = n(g.tolerance_pct)
    first = der.stages[0]
    if der.scheme == "1+1":
        _book_pair(c, der)
    elif der.fraction_rule == "forced":
        f = der.ratio_fraction
        err = (float(f) / g.i_planetary - 1) * 100
        c.p(t("The ratio is given as the simple fraction $i = {f} = {f2}$ (deviation {err}); the procedure of §{sec} {{cite:book}} follows.").format(f=_fr(f), f2=c.q(float(f), sig=5), err=c.pct(err, sign=True), sec=sec))
    elif der.fraction_rule == "exact":
        f = der.ratio_fraction
        c.p(t("The required ratio is itself a simple fraction, $i_\"пл\" = {motor_rpm}/{crank_rpm} = {f}$; the procedure of §{sec} {{cite:book}} starts from it.").format(motor_rpm=g.motor_rpm, crank_rpm=n(g.crank_rpm), f=_fr(f), sec=sec))
    elif der.fraction_rule in ("convergent", "nearest"):
        f = first.fraction
        err = (float(f) / g.i_planetary - 1) * 100
        conv = "; ".join(f"${_fr(x)}$" for x in der.convergents)
        last = der.convergents[-1] if der.convergents else None
        intro = t("By §{sec} {{cite:book}} the required ratio is replaced by a simple fraction within ±{tol} %. The best approximations of $i_\"пл\" = {i_planetary}$ by simple fractions are the convergents of its continued fraction with a denominator up to 10: {conv}. ").format(sec=sec, tol=tol, i_planetary=c.q(g.i_planetary, sig=5), conv=conv)
        if der.fraction_rule == "convergent":
            tail = t("The last of them is taken, $i = {f} = {f2}$ (deviation {err}).").format(f=_fr(f), f2=c.q(float(f), sig=5), err=c.pct(err, sign=True))
        else:
            why = (t("the last of them, ${last}$, is outside the tolerance or gives no tooth numbers").format(last=_fr(last)) if last is not None
                   else t("none of them is within the tolerance"))
            tail = t("Since {why}, the nearest simple fraction that gives tooth numbers is taken: $i = {f} = {f2}$ (deviation {err}).").format(why=why, f=_fr(f), f2=c.q(float(f), sig=5), err=c.pct(err, sign=True))
        c.p(intro + tail)
        c.doc.claim(kind="book_fraction", rule=der.fraction_rule, chosen=f, convergents=tuple(der.convergents),
                    target=g.i_planetary, tolerance=g.tolerance_pct)
    for j, st in enumerate(der.stages, 1):
        if len(der.stages) > 1:
            c.p(t("Stage {j}, $i_{j} = {fraction}$:").format(j=j, fraction=_fr(st.fraction)), indent=False)
        if st.scheme == "1":
            _book_scheme1(c, st)
        else:
            _book_scheme2(c, st)
        _book_planets(c, st)
    if g.printed is not None:
        p = g.printed
        teeth = "/".join(map(str, p.stage.teeth))
        if p.coaxial_ok and p.ratio_ok:
            c.p(t("The answer of §{section} {{cite:book}} ({teeth}, $k = {planets}$) is reproduced.").format(section=p.section, teeth=teeth, planets=p.stage.planets))
        else:
            c.p(t("The answer printed in §{section} {{cite:book}}, {teeth}, does not satisfy coaxiality ({coaxial_lhs} ≠ {coaxial_rhs}) and gives $i = {ratio}$ instead of {fraction}; the procedure carried through correctly gives the numbers above.").format(section=p.section, teeth=teeth, coaxial_lhs=p.coaxial_lhs, coaxial_rhs=p.coaxial_rhs, ratio=c.q(p.ratio, sig=3), fraction=_frt(p.fraction)))


def _book_pair(c: Ctx, der) -> None:
    """Two stages (§2.2): the pairs of simple fractions near √i_pl, the one with the smallest reducer."""
    g = c.r.gears
    t, n = c.t, c.n
    tol = n(g.tolerance_pct)
    pair = " · ".join(f"${_fr(s.fraction)}$" for s in der.stages)
    product = (t("whose product is $i_\"пл\" = {ratio_fraction}$ exactly").format(ratio_fraction=_fr(der.ratio_fraction))
               if der.fraction_rule in ("exact", "forced") else
               t("whose product is within ±{tol} %").format(tol=tol))
    c.p(t("By §2.2 {{cite:book}} the ratio is split into two stages with ratios near $sqrt(i_\"пл\")$ = {i_planetary}: simple fractions (denominator up to 10) within ±{v} % of it, {product}. Of the {tried} pairs compared, {pair} gives the smallest reducer (size {size}); each stage follows §2.4 {{cite:book}}.").format(i_planetary=n(math.sqrt(g.i_planetary), sig=4), v=n(g.tolerance_pct / 2), product=product, tried=len(der.tried), pair=pair, size=der.size))
    c.doc.claim(kind="book_pair", sizes=tuple(s for _, s in der.tried), chosen_size=der.size)


def _book_scheme1(c: Ctx, st) -> None:
    t = c.t
    row = st.chosen
    a_, d_ = row.a, row.d
    half = Fraction(d_ - a_, 2)
    c.p(t("1) From the ratio, $z_n$ and $z_k$ are expressed through the factors D and A:"))
    c.formula(f"i = 1 + z_n/z_k = {_fr(st.fraction)}", f"z_n/z_k = {_fr(st.fraction)} - 1 = {_fr(st.reduced)} = D/A",
              f"D = {d_}, A = {a_}", where=["z_k", "z_n"])
    c.p(t("2) From coaxiality, the planet:"))
    c.formula(f"z_k + z_c = z_n - z_c", f"z_c = (z_n - z_k)/2 = (D - A)/2 y = ({d_} - {a_})/2 y = {_fr(half)} y",
              where=["z_c", "y"])
    c.p(t("3) With the coefficient y and Table 2.2 {cite:book} (no interference):"))
    b = row.base
    c.formula(f"z_k = {_fr(b[0])} y >= 17", f"z_c = {_fr(b[1])} y >= 20", f"z_n = {_fr(b[2])} y >= 85",
              f"y_min = {_fr(row.y_min)}")
    z = row.teeth
    c.formula(f"z_k = {z[0]}; quad z_c = {z[1]}; quad z_n = {z[2]}", numbered=False)


def _book_scheme2(c: Ctx, st) -> None:
    t = c.t
    red = st.reduced
    c.p(t("1) The ratio through the factors A, B, D, E:"))
    c.formula(f"(z_c z_n)/(z_k z'_c) = i - 1 = {_fr(st.fraction)} - 1 = {_fr(red)} = (B D)/(A E)",
              where=["z_k", "z_c", "z'_c", "z_n"])
    c.p(t("2) The factors are split within 1 < B/A ≤ 5, 2 < D/E ≤ 5 (§2.5 {cite:book}) by the cross factors:"))
    if st.x1_range:
        c.formula(f"B/A = x_1/{red.denominator}, quad D/E = {red.numerator}/x_1 quad => quad "
                  f"{st.x1_range[0]} <= x_1 <= {st.x1_range[1]}")
    if st.x2_range:
        c.formula(f"B/A = {red.numerator}/x_2, quad D/E = x_2/{red.denominator} quad => quad "
                  f"{st.x2_range[0]} <= x_2 <= {st.x2_range[1]}")
    c.p(t("3) From coaxiality $z_k + z_c = z_n - z'_c$, the tooth numbers through the coefficient y:"))
    c.formula("z_k = A(D - E) y; quad z_c = B(D - E) y; quad z'_c = E(A + B) y; quad z_n = D(A + B) y", where=["y"])
    c.p(t("4) The smallest y by Table 2.2 ($z_k >= 17$, $z_c >= 17$, $z'_c >= 20$, $z_n >= 85$) and the sizes $Γ_1 = z_k + 2 z_c$, $Γ_2 = z_n$ of the two rows for every split are given in Tables {tab:book_x1} and {tab:book_x2}."))
    for tab, xname, name in (("2.3", "x_1", "book_x1"), ("2.4x2", "x_2", "book_x2")):
        rows = [rw for rw in st.rows if rw.table == tab]
        cap = t("Tooth numbers by the split ${xname}$ (Table {tab} {{cite:book}})").format(xname=xname, tab=tab[:3])
        if not rows:
            cells = [["—"] * 9]
        else:
            cells = [[str(rw.x), f"$({rw.b}/{rw.a}) dot ({rw.d}/{rw.e})$", f"${_fr(rw.y_min)}$",
                      *(str(zz) for zz in rw.teeth), str(rw.gamma1),
                      str(rw.gamma2) + (" *" if rw is st.chosen else "")] for rw in rows]
        c.table(name, cap, [f"${xname}$", "$(B/A) dot (D/E)$", "$y_min$", "$z_k$", "$z_c$", "$z'_c$", "$z_n$",
                            "$Γ_1$", "$Γ_2$"], cells, align=["center"] * 9)
    ch = st.chosen
    xn = "x_1" if ch.table == "2.3" else "x_2"
    sizes = sorted(rw.size for rw in st.rows)
    nxt = next((s for s in sizes if s > ch.size), None)
    more = (t(" (the next is {nxt})").format(nxt=nxt) if nxt is not None else "")
    c.p(t("5) The smallest size $max(Γ_1, Γ_2) = {size}${more} is given by ${xn} = {x}$ (marked *):").format(size=ch.size, more=more, xn=xn, x=ch.x))
    c.doc.claim(kind="book_row", chosen=ch.size, sizes=tuple(sizes))
    z = ch.teeth
    c.formula(f"z_k = {z[0]}; quad z_c = {z[1]}; quad z'_c = {z[2]}; quad z_n = {z[3]}", numbered=False)


def _book_planets(c: Ctx, st) -> None:
    t, q = c.t, c.q
    zk = st.chosen.teeth[0]
    ks = ", ".join(str(k) for k in st.assembly_ks[:6]) + (" …" if len(st.assembly_ks) > 6 else "")
    c.p(t("The numbers of planets the assembly condition allows {cite:book:formula (2.4)}:"))
    den = "k" if st.assembly_c == 1 else f"{st.assembly_c} k"
    c.formula(f"(z_k i)/k c = ({zk} dot {_fr(st.fraction)})/k c = {st.assembly_n}/({den}) c", f"k = {ks}",
              where=["k", "c"])
    c.p(t("The limit by the neighbouring condition {cite:book:formula (2.5)}, computed exactly instead of being read from Table 2.1:"))
    big = max(st.chosen.teeth[1], st.chosen.teeth[2] if st.scheme == "2" else 0)
    c.formula(c.calc("sin π/k > (z_c + 2 h^*_a)/(z_k + z_c)", "({0} + 2)/({1} + {2})",
                     [V(big, exact=True), V(zk, exact=True), V(st.chosen.teeth[1], exact=True)],
                     V(st.neighbour_q, decimals=4)) + f"; quad k <= {st.neighbour_limit}", where=["h^*_a"])
    extra = ""
    if st.k_max_exact != st.k_max:
        extra = t(" (by the exact assembly condition, {k_max_exact})").format(k_max_exact=st.k_max_exact)
    c.p(t("The largest number of planets allowed by both is $k = {k_max}${extra}.").format(k_max=st.k_max, extra=extra))
    c.doc.claim(kind="book_planets", chosen=st.k_max, allowed=tuple(st.assembly_ks), limit=st.neighbour_limit)


# --------------------------------------------------------------------------------------------------
def _search(c: Ctx) -> None:
    g = c.r.gears
    t, n = c.t, c.n
    s = g.search
    design = g.planetary
    tol = n(g.tolerance_pct)
    c.doc.add(Heading(2, t("Tooth numbers by a complete search")))
    two = g.scheme == "1+1"
    what = (t("pairs of single-row stages") if two else
            t("tooth sets of the scheme"))
    c.p(t("The procedure of the textbook follows one simple fraction; another tooth set may give a smaller reducer or a "
          "more accurate ratio. Therefore all {what} with at most {z_max} teeth per wheel that satisfy coaxiality and "
          "Table 2.2 {{cite:book}} were compared: {n_sets} of them give the ratio within ±{tol} %. The size of a reducer "
          "is taken as $max(Γ_1, Γ_2) = max(z_k + 2 z_c, z_n)$ teeth (§2.5 {{cite:book}}); the smallest sets are listed "
          "in Table {{tab:search}}.").format(what=what, z_max=s.z_max, n_sets=s.n_sets, tol=tol))
    if two:
        header = [t("Stage 1: $z_k$/$z_c$/$z_n$"),
                  t("Stage 2: $z_k$/$z_c$/$z_n$")]
    else:
        header = ["$z_k$", "$z_c$", "$z'_c$", "$z_n$"] if g.scheme == "2" else ["$z_k$", "$z_c$", "$z_n$"]
    header += ["$i$", t("Deviation, %"), c.tc("note, tooth sets", "Size"), "$k$", t("Note")]
    rows = []
    shown = list(s.alternatives)
    for extra in (s.more_accurate, s.exact):
        if extra is not None and extra not in shown:
            shown.append(extra)
    for a in shown:
        cells = ["/".join(map(str, st.teeth)) for st in a.stages] if two else [str(x) for x in a.stages[0].teeth]
        note = []
        if a == design:
            note.append(t("taken"))
        if s.smallest is not None and a == s.smallest and a != design:
            note.append(t("smallest"))
        if a == s.exact and a != design:
            note.append(c.tc("note, tooth sets", "exact"))
        rows.append(cells + [n(a.ratio, decimals=4), n(a.ratio_error_pct, decimals=2), str(a.size), str(a.planets),
                             ", ".join(note)])
    teeth_w = [1.9, 1.9] if two else [0.75] * (4 if g.scheme == "2" else 3)
    c.table("search", t("Smallest tooth sets within the tolerance"),
            header, rows, align=["center"] * len(header), widths=teeth_w + [1.05, 1.2, 1.1, 0.45, 1.45])
    _selection(c)


def _selection(c: Ctx) -> None:
    g = c.r.gears
    t = c.t
    s = g.search
    design = g.planetary
    smallest = s.smallest or design
    pool = {"smallest_3plus": t("Only the sets that take at least three planets are compared (fewer planets load the bearings of the central gears unevenly)."),
            "smallest_no3": t("No set within the tolerance takes three planets; all sets are compared."),
            "forced_planets": t("The number of planets is set to {forced_planets}; the sets that take it are compared.").format(forced_planets=s.forced_planets)}[s.rule]
    e_d = design.ratio_error_pct
    if s.select == "accurate":
        if smallest == design:
            sel = t("The smallest of them, {design} (size {size}, deviation {e_d}), is also the most accurate of the sets at most {SELECT_SLACK} tooth larger; it is taken.").format(design=_teeth(design), size=design.size, e_d=c.pct(e_d, sign=True), SELECT_SLACK=SELECT_SLACK)
        else:
            sel = t("The smallest of them is {smallest} (size {size}, deviation {ratio_error_pct}). Of the sets at most {SELECT_SLACK} tooth larger, the most accurate is taken: {design} (size {size2}, deviation {e_d}); one tooth of size reduces the deviation from {ratio_error_pct2} to {e_d2}.").format(smallest=_teeth(smallest), size=smallest.size, ratio_error_pct=c.pct(smallest.ratio_error_pct, sign=True), SELECT_SLACK=SELECT_SLACK, design=_teeth(design), size2=design.size, e_d=c.pct(e_d, sign=True), ratio_error_pct2=c.pct(abs(smallest.ratio_error_pct)), e_d2=c.pct(abs(e_d)))
    else:
        sel = t("The smallest of them is taken: {design} (size {size}, deviation {e_d}).").format(design=_teeth(design), size=design.size, e_d=c.pct(e_d, sign=True))
    c.p(pool + " " + sel)
    c.doc.claim(kind="selection", select=s.select, rule=s.rule, carried=design, smallest=smallest, slack=SELECT_SLACK,
                search=s)
    # an inexact ratio although closer sets exist: why
    more, exact = s.more_accurate, s.exact
    if abs(e_d) >= INEXACT_PCT and (more is not None or exact is not None):
        parts = []
        for d in dict.fromkeys(x for x in (more, exact) if x is not None):
            grow = (d.size / design.size - 1) * 100
            parts.append(t("{d} (size {size}, {grow} larger, deviation {ratio_error_pct})").format(d=_teeth(d), size=d.size, grow=c.pct(grow, decimals=0), ratio_error_pct=c.pct(d.ratio_error_pct, sign=True)))
        c.p(t("More accurate sets exist but are larger: {parts}. The deviation of the set taken, {e_d}, is within the allowed ±{tolerance_pct} %, and a larger reducer for a more exact crank speed is not justified.").format(parts='; '.join(parts), e_d=c.pct(e_d, sign=True), tolerance_pct=c.n(g.tolerance_pct)))
        c.doc.claim(kind="inexact_accepted", carried=design, more=more, exact=exact, tolerance=g.tolerance_pct)
    der = g.derivation
    if der is not None:
        bs = der.size
        book = " + ".join("/".join(map(str, st.chosen.teeth)) for st in der.stages)
        if bs == design.size:
            cmp = t("The textbook's procedure gives {book}, a reducer of the same size.").format(book=book)
        elif design.size < bs:
            less = bs - design.size
            cmp = c.nt("The textbook's procedure gives {book} (size {bs}): the set taken is {less} tooth smaller.",
                       "The textbook's procedure gives {book} (size {bs}): the set taken is {less} teeth smaller.",
                       less).format(book=book, bs=bs, less=less)
        else:
            less = design.size - bs
            cmp = c.nt("The textbook's procedure gives {book} (size {bs}), {less} tooth smaller than the set taken, "
                       "which is preferred by the rule above.",
                       "The textbook's procedure gives {book} (size {bs}), {less} teeth smaller than the set taken, "
                       "which is preferred by the rule above.", less).format(book=book, bs=bs, less=less)
        c.p(cmp)
        c.doc.claim(kind="book_vs_carried", book_size=bs, carried_size=design.size)
    if g.scheme == "1+1":
        r1, r2 = (st.ratio for st in design.stages)
        lo, hi = STAGE_RANGE_1
        inside = s.stage_range_ok
        stages = (t("The stage with the larger ratio is put on the motor side (its gears carry the smaller torque): "
                    "$i_1 = {i1}$, $i_2 = {i2}$, both within the range {lo}…{hi} of a single-row stage.") if inside else
                  t("The stage with the larger ratio is put on the motor side (its gears carry the smaller torque): "
                    "$i_1 = {i1}$, $i_2 = {i2}$; no pair keeps both within {lo}…{hi}."))
        c.p(stages.format(i1=c.q(r1, decimals=3), i2=c.q(r2, decimals=3), lo=c.n(lo), hi=c.n(hi)))


# --------------------------------------------------------------------------------------------------
def _conditions(c: Ctx) -> None:
    g = c.r.gears
    t, q = c.t, c.q
    ch = g.checks
    c.doc.add(Heading(2, t("Conditions of synthesis for the reducer taken")))
    c.p(t("1. The ratio (the textbook allows ±{tolerance_pct} %):").format(tolerance_pct=c.n(g.tolerance_pct)),
        indent=False)
    c.formula(f"i = {_fr(ch.ratio_fraction)} = {q(ch.ratio, decimals=4)}",
              c.calc('δ = (i/i_"пл" - 1) dot 100', "({0}/{1} - 1) dot 100",
                     [V(ch.ratio, decimals=4), V(ch.target, decimals=4)], V(ch.ratio_error_pct, decimals=2), "%"),
              where=["i", "δ"])
    c.doc.claim(kind="ratio_within", error=ch.ratio_error_pct, tolerance=g.tolerance_pct, ok=ch.ratio_ok)
    multi = len(ch.stages) > 1
    for j, sc in enumerate(ch.stages, 1):
        st = sc.stage
        if multi:
            c.p(t("Stage {j} ($i_{j} = {ratio}$):").format(j=j, ratio=q(st.ratio, decimals=4)),
                indent=False)
        zc2 = "z'_c" if st.z_planet2 is not None else "z_c"
        c.p(t("2. Coaxiality:"), indent=False)
        c.formula(c.calc("z_k + z_c", "{0} + {1}", [V(st.z_sun, exact=True), V(st.z_planet, exact=True)],
                         V(sc.coaxial_lhs, exact=True)),
                  c.calc(f"z_n - {zc2}", "{0} - {1}", [V(st.z_ring, exact=True), V(st.zc2, exact=True)],
                         V(sc.coaxial_rhs, exact=True)))
        k = st.planets
        c.p(t("3. Assembly {{cite:book:formula (2.4)}} for $k = {k}$:").format(k=k), indent=False)
        if st.z_planet2 is None:
            c.formula(c.calc("(z_k + z_n)/k", "({0} + {1})/{2}", [V(st.z_sun, exact=True), V(st.z_ring, exact=True),
                                                                   V(k, exact=True)],
                             V((st.z_sun + st.z_ring) / k, sig=6)))
            c.p((t("— a whole number, the condition holds.") if (st.z_sun + st.z_ring) % k == 0 else t("— not a whole number, the condition fails.")), indent=False)
        else:
            c.formula(c.calc("(z_k z'_c + z_c z_n)/(k thin \"НОД\"(z_c, z'_c))", "{0}/({1} dot {2})",
                             [V(sc.assembly_t, exact=True), V(k, exact=True), V(sc.assembly_g, exact=True)],
                             V(sc.assembly_t / (k * sc.assembly_g), sig=6)))
            c.p((t("— a whole number: the double planets can be fitted (turned by whole teeth), the condition holds.") if sc.assembly_exact_ok else t("— not a whole number, the condition fails.")), indent=False)
            if sc.k_max != sc.k_max_book:
                c.p(t("The form of the textbook (z_k·i/k whole) admits at most $k = {k_max_book}$; the exact condition above admits $k = {k_max}$.").format(k_max_book=sc.k_max_book, k_max=sc.k_max))
        zbig = max(st.z_planet, st.zc2)
        if st.z_planet2 is None:  # a single-row planet has one crown
            head = c.nt("4. Neighbouring {{cite:book:formula (2.5)}} (the planet, {z} tooth):",
                        "4. Neighbouring {{cite:book:formula (2.5)}} (the planet, {z} teeth):", zbig)
        else:
            head = c.nt("4. Neighbouring {{cite:book:formula (2.5)}} (the larger planet, {z} tooth):",
                        "4. Neighbouring {{cite:book:formula (2.5)}} (the larger planet, {z} teeth):", zbig)
        c.p(head.format(z=zbig), indent=False)
        c.formula(c.calc(f"sin π/k", "sin π/{0}", [V(k, exact=True)], V(sc.neighbour_sin, decimals=4))
                  + " > " + c.calc("(z_c + 2 h^*_a)/(z_k + z_c)", "({0} + 2)/{1}",
                                   [V(zbig, exact=True), V(st.z_sun + st.z_planet, exact=True)],
                                   V(sc.neighbour_q, decimals=4)))
        c.p(t("5. No interference (Table 2.2 {cite:book}):"),
            indent=False)
        items = "; quad ".join(f"{_sym(i.symbol)} = {i.value} >= {i.limit}" for i in sc.interference)
        c.formula(items, numbered=False)
        ks = ", ".join(map(str, sc.assembly_ks_exact[:6])) + (" …" if len(sc.assembly_ks_exact) > 6 else "")
        ok = sc.ok
        if g.forced_planets is not None:
            choice = t("the number of planets is set to {k}").format(k=k)
        else:
            choice = t("the largest of them, {k}, is taken").format(k=c.planets(k))
        held = (t("All conditions hold. The assembly condition admits $k = {ks}$, the neighbouring condition "
                  "$k <= {limit}$; {choice}.") if ok else
                t("All conditions hold except those noted. The assembly condition admits $k = {ks}$, the neighbouring "
                  "condition $k <= {limit}$; {choice}."))
        c.p(held.format(ks=ks, limit=sc.neighbour_limit, choice=choice))
        c.doc.claim(kind="planets", chosen=k, allowed=tuple(sc.assembly_ks_exact), limit=sc.neighbour_limit,
                    forced=g.forced_planets, ok=ok)


def _sym(symbol: str) -> str:
    """'z_n − z_c′' → typst math."""
    return symbol.replace("z_c′", "z'_c").replace("−", "-")


# --------------------------------------------------------------------------------------------------
def _ratio_checks(c: Ctx) -> None:
    g = c.r.gears
    t, q = c.t, c.q
    ch = g.checks
    c.doc.add(Heading(2, t("Checking the ratio")))
    c.p(t("Analytically {cite:book:formula (2.1)}, $a$ being the number of external meshes (for a single row $z'_c = z_c$):"))
    stages = g.planetary.stages
    for j, (st, val) in enumerate(zip(stages, ch.ratio_formula_21), 1):
        idx = f"_{j}" if len(stages) > 1 else ""
        c.formula(c.calc(f"i{idx} = 1 - (-1)^a (z_c z_n)/(z_k z'_c)", "1 + ({0} dot {1})/({2} dot {3})",
                         [V(st.z_planet, exact=True), V(st.z_ring, exact=True), V(st.z_sun, exact=True),
                          V(st.zc2, exact=True)], V(val, decimals=4)), where=["a"] if j == 1 else ())
    if len(ch.ratio_formula_21) > 1:
        c.formula(c.calc("i = i_1 i_2", " dot ".join("{%d}" % k for k in range(len(ch.ratio_formula_21))),
                         [V(x, decimals=4) for x in ch.ratio_formula_21], V(ch.ratio_formula_21_total, decimals=4)))
    vp = ch.velocity
    fig = c.if_fig("gears_planetary", t(" (Figure {fig:gears_planetary})"))
    c.p(t("Graphically by the velocity pictures {{cite:book:formula (2.3)}}{fig}: the ratio is the ratio of the tangents of the angles that the lines of velocities of the sun gear and of the carrier make with the vertical,").format(fig=fig))
    for j, s in enumerate(vp.stages, 1):
        c.formula(c.calc('i = ("tg" φ_k)/("tg" φ_H)', '("tg" {0})/("tg" {1})',
                         [V(s.phi_k_deg, decimals=2, deg=True), V(s.phi_h_deg, decimals=2, deg=True)],
                         V(s.ratio, decimals=4)), where=["φ_k", "φ_H"] if j == 1 else ())
    c.p(t("and on the plan of angular velocities by the segments cut by the rays of the sun gear and of the carrier:"))
    if c.has("gears_planetary"):  # the segments as drawn on the figure [mm]
        from ..figures.note_scales import planetary_scales

        sc = planetary_scales(g)
        ok, oh = sc.ok_mm, sc.oh_mm
        where = ["o k", "o h"]
    else:  # in the units of the construction (radii in modules)
        ok, oh = vp.ok, vp.oh
        unit = t("in the units of the construction")
        where = [("o k", t("the segment cut by the ray of the sun gear, {unit}").format(unit=unit)),
                 ("o h", t("the segment cut by the ray of the carrier, {unit}").format(unit=unit))]
    c.formula(c.calc("i = (o k)/(o h)", "{0}/{1}", [V(ok, decimals=2), V(oh, decimals=2)], V(vp.ratio, decimals=4)),
              where=where)
    c.p(t("The synthesis of the reducer gives its tooth numbers only, not its module: the ratio and the angles of "
          "the velocity pictures do not depend on it. Sheet 4 draws the reducer with the largest standard module "
          "(GOST 9563, series 1) at which it fits its field at 1:1, and takes the scale of the velocities from that "
          "module; the figures of this note are drawn with the same module and give their scales at it."))
    c.fig("gears_planetary", t("Kinematic scheme of the planetary reducer, the picture of linear velocities and the plan of angular velocities"))
    k = g.planetary.planets
    c.p(t("The {k} stand at the angle $2β = 360°/k = {v}°$").format(k=c.planets(k), v=c.q(360 / k, sig=4))
        + c.if_fig("gears_assembly", t("; the assembly is shown in Figure {fig:gears_assembly}")) + ".")
    c.fig("gears_assembly", t("Assembly of the planetary reducer"))


# --------------------------------------------------------------------------------------------------
def _spur(c: Ctx) -> None:
    g = c.r.gears
    sp = g.spur
    t, n, q = c.t, c.n, c.q
    mm = t("mm")
    c.doc.add(Heading(2, t("The spur pair")))
    if sp.shifted:
        _spur_shifted(c)
        return
    c.p(t("The spur pair is made of zero gears (§2.3 {{cite:book}}): module $m = {m_mm}$ mm, profile angle $α = {alpha_deg}°$, $h^*_a = {ha_star}$, $c^* = {c_star}$, shifts $x_1 = x_2 = 0$.").format(m_mm=q(sp.m_mm), alpha_deg=q(sp.alpha_deg), ha_star=q(sp.ha_star), c_star=q(sp.c_star)))
    c.p(t("The geometry of the pair is computed by the formulas of §2.3 {cite:book}, which are those of GOST 16532-70 "
          "{cite:gost16532} for zero gears."))
    c.p(t("The module is the one the textbook fixes for every variant for the drawing of the mesh on sheet 4 (§2.1.1 "
          "{{cite:book}}): at $m = {m_mm}$ mm the teeth are large enough to construct their involutes, the line of "
          "action and the zones of the mesh by hand at a readable scale. It is a module of the drawing, not a "
          "result of a strength calculation, which the course project does not make.").format(m_mm=q(sp.m_mm)))
    c.p(t("1–2. The ratio and the tooth numbers: the smaller gear has 17 teeth, the textbook's smallest; the other is the nearest whole number to the required ratio:"))
    if not sp.multiplier:
        c.formula(c.calc('z_2 = z_1 i_"д"', "17 dot {0}", [V(sp.i_d, sig=4)], V(17 * sp.i_d, decimals=2))
                  + f" approx {sp.z2}",
                  c.calc("i = z_2/z_1", "{0}/{1}", [V(sp.z2, exact=True), V(sp.z1, exact=True)], V(sp.i_actual, sig=4)),
                  where=["z_1", "z_2"])
    else:
        c.formula(c.calc('z_1 = z_2/i_"д"', "17/{0}", [V(sp.i_d, sig=4)], V(17 / sp.i_d, decimals=2)) + f" approx {sp.z1}",
                  c.calc("i = z_2/z_1", "{0}/{1}", [V(sp.z2, exact=True), V(sp.z1, exact=True)], V(sp.i_actual, sig=4)),
                  where=["z_1", "z_2"])
    dev = (sp.i_actual / sp.i_d - 1) * 100
    cam_rpm = g.cam_rpm_actual
    rpm = t("rpm")
    c.p(t("The cam turns at {speed} instead of {required} (ratio deviation {dev}).").format(
        speed=c.qty(cam_rpm, rpm, decimals=1), required=c.qty(abs(g.cam_rpm), rpm), dev=c.pct(dev, sign=True)))
    c.doc.claim(kind="spur_teeth", z1=sp.z1, z2=sp.z2, i_d=sp.i_d, multiplier=sp.multiplier)
    ca = math.cos(math.radians(sp.alpha_deg))
    m_ = V(sp.m_mm, exact=True)
    c.p(t("3. The diameters of the pitch, base, tip and root circles:"), indent=False)
    for i, z, dv, db, da, df in ((1, sp.z1, sp.d1_mm, sp.db1_mm, sp.da1_mm, sp.df1_mm),
                                 (2, sp.z2, sp.d2_mm, sp.db2_mm, sp.da2_mm, sp.df2_mm)):
        c.formula(c.calc(f"d_{i} = m z_{i}", "{0} dot {1}", [m_, V(z, exact=True)], V(dv, decimals=2), mm),
                  c.calc(f"d_(b {i}) = d_{i} cos α", "{0} dot {1}", [V(dv, decimals=2), V(ca, decimals=4)], V(db, decimals=2), mm),
                  where=["m"] if i == 1 else ())
        c.formula(c.calc(f"d_(a {i}) = d_{i} + 2 h^*_a m", "{0} + 2 dot {1} dot {2}",
                         [V(dv, decimals=2), V(sp.ha_star, exact=True), m_], V(da, decimals=2), mm),
                  c.calc(f"d_(f {i}) = d_{i} - 2(h^*_a + c^*) m", "{0} - 2({1} + {2}) dot {3}",
                         [V(dv, decimals=2), V(sp.ha_star, exact=True), V(sp.c_star, exact=True), m_], V(df, decimals=2), mm),
                  where=["c^*"] if i == 1 else ())
    c.p(t("4–10. The centre distance, the pitches and the sizes of the teeth:"), indent=False)
    c.formula(c.calc("a = m (z_1 + z_2)/2", "{0} dot ({1} + {2})/2", [m_, V(sp.z1, exact=True), V(sp.z2, exact=True)],
                     V(sp.a_mm, decimals=2), mm))
    c.formula(c.calc("p = π m", "π dot {0}", [m_], V(sp.p_mm, decimals=3), mm),
              c.calc("p_b = p cos α", "{0} dot {1}", [V(sp.p_mm, decimals=3), V(ca, decimals=4)], V(sp.pb_mm, decimals=3), mm),
              c.calc("s = e = (π m)/2", "(π dot {0})/2", [m_], V(sp.s_mm, decimals=3), mm), where=["p_b"])
    c.formula(c.calc("τ_1 = (360 degree)/z_1", "{0}/{1}", [V(360, exact=True, deg=True), V(sp.z1, exact=True)],
                     V(sp.tau1_deg, decimals=3, deg=True)),
              c.calc("τ_2 = (360 degree)/z_2", "{0}/{1}", [V(360, exact=True, deg=True), V(sp.z2, exact=True)],
                     V(sp.tau2_deg, decimals=3, deg=True)), where=["τ_1"])
    c.formula(c.calc("h = (2 h^*_a + c^*) m", "(2 dot {0} + {1}) dot {2}", [V(sp.ha_star, exact=True), V(sp.c_star, exact=True), m_],
                     V(sp.h_mm, decimals=2), mm),
              c.calc('h_"з" = 2 h^*_a m', "2 dot {0} dot {1}", [V(sp.ha_star, exact=True), m_], V(sp.hd_mm, decimals=2), mm),
              c.calc("C = c^* m", "{0} dot {1}", [V(sp.c_star, exact=True), m_], V(sp.c_mm, decimals=2), mm))
    c.p(t("11. Check of the centre distance and of the tooth height:"),
        indent=False)
    c.formula(c.calc("a = d_(a 1)/2 + d_(f 2)/2 + C", "{0}/2 + {1}/2 + {2}",
                     [V(sp.da1_mm, decimals=2), V(sp.df2_mm, decimals=2), V(sp.c_mm, decimals=2)], V(sp.check_a_12_mm, decimals=2), mm),
              c.calc("2 h = d_(a 1) - d_(f 1)", "{0} - {1}", [V(sp.da1_mm, decimals=2), V(sp.df1_mm, decimals=2)],
                     V(sp.check_2h_1_mm, decimals=2), mm))
    ok = sp.check_ok
    c.p(t("The centre distance equals $a$ and the tooth height $h$: the check holds.") if ok else
        t("The centre distance equals $a$ and the tooth height $h$: the check fails."))
    if min(sp.z1, sp.z2) < sp.z_min_undercut:
        c.p(t("With $α = 20°$ and $h^*_a = 1$ the undercut limit of a zero gear is $z_min = 2 h^*_a/sin^2 α = {z_min_undercut}$: the 17-tooth gear has an insignificant undercut of the root, which the textbook's rule $z >= 17$ accepts.").format(z_min_undercut=q(sp.z_min_undercut, decimals=2)))
    _contact_ratio(c)


def _contact_ratio(c: Ctx) -> None:
    g = c.r.gears
    sp = g.spur
    t, q = c.t, c.q
    mm = t("mm")
    c.p(t("The transverse contact ratio is computed from the geometry — the active length of the line of action $P_1 P_2$ over the base pitch — instead of being measured on the drawing (note to §2.3 {cite:book}):"))
    ra1, rb1, ra2, rb2 = sp.da1_mm / 2, sp.db1_mm / 2, sp.da2_mm / 2, sp.db2_mm / 2
    c.formula(c.calc("g_α = sqrt(r_(a 1)^2 - r_(b 1)^2) + sqrt(r_(a 2)^2 - r_(b 2)^2) - a sin α",
                     "sqrt({0}^2 - {1}^2) + sqrt({2}^2 - {3}^2) - {4} dot sin {5}",
                     [V(ra1, decimals=3), V(rb1, decimals=3), V(ra2, decimals=3), V(rb2, decimals=3),
                      V(sp.a_mm, decimals=2), V(sp.alpha_deg, exact=True, deg=True)], V(sp.g_alpha_mm, decimals=2), mm),
              where=["g_α"])
    c.formula(c.calc("ε_α = g_α/p_b", "{0}/{1}", [V(sp.g_alpha_mm, decimals=2), V(sp.pb_mm, decimals=3)],
                     V(sp.eps_alpha, decimals=3)), where=["ε_α"])
    c.formula(c.calc("φ_(α 1) = ε_α τ_1", "{0} dot {1}", [V(sp.eps_alpha, decimals=3), V(sp.tau1_deg, decimals=3, deg=True)],
                     V(sp.phi_alpha1_deg, decimals=2, deg=True)),
              c.calc("φ_(α 2) = ε_α τ_2", "{0} dot {1}", [V(sp.eps_alpha, decimals=3), V(sp.tau2_deg, decimals=3, deg=True)],
                     V(sp.phi_alpha2_deg, decimals=2, deg=True)))
    eps = sp.eps_alpha
    two = (eps - 1) * 100
    ok = eps >= 1.2
    zones = t("On the line of action the zones of two-pair mesh $P_1 U_2 = U_1 P_2 = {double}$ mm enclose the zone of "
              "single-pair mesh $U_2 U_1 = {single}$ mm. With $ε_α = {eps}$ two pairs of teeth are in mesh during "
              "$ε_α - 1$ = {two} of the running time and one pair during the remaining {one}.").format(
        double=q(sp.double_zone_mm, decimals=2), single=q(sp.single_zone_mm, decimals=2), eps=q(eps, decimals=3),
        two=c.pct(two, decimals=1), one=c.pct(100 - two, decimals=1))
    smooth = (t("Since $ε_α >= \"1.2\"$, the recommended least value for spur gears, the pair runs smoothly.") if ok else
              t("Since $ε_α < \"1.2\"$, the recommended least value for spur gears, the smoothness of the pair is "
                "insufficient."))
    c.p(zones + " " + smooth)
    c.doc.claim(kind="contact_ratio", eps=eps, two_pair_pct=two, ok=ok, double=sp.double_zone_mm,
                single=sp.single_zone_mm, pb=sp.pb_mm)
    if c.has("gears_mesh"):
        c.p(t("The mesh with the line of action and its zones is shown in Figure {fig:gears_mesh}."))
        c.fig("gears_mesh", t("Involute mesh of the spur pair"))


def _spur_shifted(c: Ctx) -> None:
    """A shifted pair (beyond the textbook): its geometry as a table."""
    g = c.r.gears
    sp = g.spur
    pr = sp.pair
    t, n = c.t, c.n
    c.p(t("The spur pair is cut with profile shifts $x_1 = {x1}$, $x_2 = {x2}$ (beyond the textbook, which takes zero gears): $z_1 = {z1}$, $z_2 = {z2}$, $m = {m_mm}$ mm. The working pressure angle follows from $\"inv\" α_w = \"inv\" α + 2 (x_1 + x_2) \"tg\" α/(z_1 + z_2)$; its geometry is given in Table {{tab:spur_shifted}}.").format(x1=c.q(sp.x1, decimals=4), x2=c.q(sp.x2, decimals=4), z1=sp.z1, z2=sp.z2, m_mm=c.q(sp.m_mm)))
    mm = t("mm")
    rows = [
        [t("Working pressure angle $α_w$, °"), n(pr.alpha_w_deg, decimals=3), ""],
        [t("Centre distance $a_w$, ") + mm, n(pr.a_w_mm, decimals=3), ""],
        [t("Pitch diameters $d$, ") + mm, n(pr.d_mm[0], decimals=2), n(pr.d_mm[1], decimals=2)],
        [t("Base diameters $d_b$, ") + mm, n(pr.db_mm[0], decimals=2), n(pr.db_mm[1], decimals=2)],
        [t("Tip diameters $d_a$, ") + mm, n(pr.da_mm[0], decimals=2), n(pr.da_mm[1], decimals=2)],
        [t("Root diameters $d_f$, ") + mm, n(pr.df_mm[0], decimals=2), n(pr.df_mm[1], decimals=2)],
        [t("Tooth thickness at the tip $s_a$, ") + mm, n(pr.sa_mm[0], decimals=2),
         n(pr.sa_mm[1], decimals=2)],
        [t("Transverse contact ratio $ε_α$"), n(pr.eps_alpha, decimals=3), ""],
    ]
    c.table("spur_shifted", t("Geometry of the shifted spur pair"),
            [t("Quantity"), t("Gear 1"), t("Gear 2")], rows,
            align=["left", "center", "center"], widths=[3, 1, 1])
    c.doc.claim(kind="spur_teeth", z1=sp.z1, z2=sp.z2, i_d=sp.i_d, multiplier=sp.multiplier)
    smooth = sp.eps_alpha >= 1.2
    c.p((t("The transverse contact ratio $ε_α = {eps}$ is not below 1.2, the recommended least value: the pair runs "
           "smoothly.") if smooth else
         t("The transverse contact ratio $ε_α = {eps}$ is below 1.2, the recommended least value: the smoothness is "
           "insufficient.")).format(eps=c.q(sp.eps_alpha, decimals=3)))
    if c.has("gears_mesh"):
        c.p(t("The mesh is shown in Figure {fig:gears_mesh}."))
        c.fig("gears_mesh", t("Involute mesh of the spur pair"))


# --------------------------------------------------------------------------------------------------
def _power(c: Ctx) -> None:
    g = c.r.gears
    t, q = c.t, c.q
    c.doc.add(Heading(2, t("Power of the motor")))
    if g.power is None:
        c.p(t("The required power of the motor (§2.6 {{cite:book}}) is $N_\"д\" = M ω_\"кр\"/(η_1 η_2) dot 10^(-3)$ kW with $η_1 = {eta1}$ and $η_2 = {eta2}$; the mean reduced moment M is found on sheet 2 of the project, which is not part of this note, so the power is not computed here.").format(eta1=q(g.eta1, sig=4), eta2=q(g.eta2)))
        return
    p = g.power
    s2 = c.r.linkage
    if s2 is not None and s2.is_engine:  # an engine: no electric motor drives it
        c.p(t("The mechanism of sheet 2 is an engine: here $M$ is its consumer's resisting moment $M_\"с\"$, the gear train is taken to pass it from the crank to the consumer, and the choice of an electric motor below is only a formal check of the train's load (an engine needs none)."))
    c.p(t("The required power is the mean reduced moment times the crank's angular speed, divided by the efficiencies of the reducer and of the linkage (§2.6 {cite:book}):"))
    c.formula(c.calc('ω_"кр" = (π n_"кр")/30', "(π dot {0})/30", [V(g.crank_rpm, exact=True)], V(p.omega_cr_rad_s, decimals=3),
                     t("rad/s")), where=['ω_"кр"'])
    c.formula(c.calc('N_"д" = (M ω_"кр")/(η_1 η_2) dot 10^(-3)', "({0} dot {1})/({2} dot {3}) dot 10^(-3)",
                     [V(p.torque_nm, sig=5), V(p.omega_cr_rad_s, decimals=3), V(p.eta1, sig=4), V(p.eta2, exact=True)],
                     V(p.power_kw, decimals=3), t("kW")), where=['N_"д"', "M", "η_1", "η_2"])
    if p.rated_kw is not None:
        below = [x for x in RATED_POWER_KW if x < p.rated_kw]
        prev = (t(" (the next lower, {below} kW, is less than required)").format(below=c.n(below[-1])) if below else "")
        c.p(t("A motor of the standard series is taken with the nearest rated power not below the required one, $N_\"ном\" = {rated_kw}$ kW ≥ $N_\"д\"$ = {power_kw} kW{prev}; no overload of the motor is allowed. Its speed is {motor_rpm} rpm.").format(rated_kw=q(p.rated_kw), power_kw=c.n(p.power_kw, decimals=3), prev=prev, motor_rpm=g.motor_rpm))
        c.doc.claim(kind="motor_power", rated=p.rated_kw, power=p.power_kw, series=RATED_POWER_KW)
    else:
        c.p(t("The required power is above the largest motor of the standard series ({RATED_POWER_KW} kW).").format(RATED_POWER_KW=c.n(RATED_POWER_KW[-1])))
