"""The parts of the note around the chapters (ГОСТ 7.32-2017): title page, task, abstract, contents,
introduction, the assumptions, the conclusion, the list of sources and the appendix."""

from __future__ import annotations

import math

from ..terminal.variants import law_words
from .ctx import Ctx, sheet1_of
from .model import Abstract, Contents, Heading, ListBlock, ReferenceList, TaskSheet, TitlePage, literal

from .sources import source_text


def title_meta(c: Ctx, title) -> dict:
    """The title page's fields and the words the style prints (note-style.typ reads them)."""
    t = c.t
    v = c.r.variant
    org = [s.strip() for s in (title.org or "").split(",") if s.strip()]
    return {
        "lang": c.lang,
        "doc-title": t("Explanatory note, TMM course project, variant {number}").format(number=v.number),
        # the founder's line of ГОСТ 7.32's title page, on the Russian note only (a Russian university's)
        "ministry": t("Ministry of Science and Higher Education of the Russian Federation") if c.lang == "ru" else "",
        "org-lines": org,
        "doc-kind": t("Explanatory note"),
        "discipline": t("to the course project in the discipline «Theory of mechanisms and machines»"),
        "topic": (t("«Analysis of the lever mechanism, synthesis of the cam mechanism and of the gear drive»")
                  if _sheet1(c) is not None else t("«Synthesis of the cam mechanism and of the gear drive»")),
        "variant-line": t("Variant {number}").format(number=v.number),
        # ГОСТ 2.102's code of an explanatory note (ПЗ), a part of the Russian designation
        "designation": title.designation_for(0, v.number) + (" ПЗ" if c.lang == "ru" else ""),
        "teacher-label": t("Supervisor"),
        "teacher": title.teacher,
        "student-label": c.tc("note, title page", "Student"),
        "student": title.student,
        "group-label": c.tc("note, title page", "group"),
        "group": title.group,
        "sign-label": t("signature"),
        "date-label": "г." if c.lang == "ru" else "",  # the Russian date's «  » ______ 20__ г.; none in English
        "grade-label": t("Defended with the mark"),
        "city": getattr(title, "city", "") or "",
        # ГОСТ 7.32's labels under the lines left blank (no --org, no --city)
        "org-label": t("name of the organisation"),
        "dept-label": t("name of the department"),
        "city-label": t("city"),
        "year": str(title.the_year),
        "figure-word": t("Figure"),
        "table-word": t("Table"),
        "continued-word": t("Table continued"),
        "where-word": t("where"),
        "appendix-word": t("Appendix"),
    }


def front_matter(c: Ctx, title) -> None:
    c.doc.sources = source_text(c.lang)
    c.doc.add(TitlePage(title_meta(c, title)))
    _task(c, title)
    _abstract(c)
    c.doc.add(Heading(1, c.t("Contents"), "structural", outlined=False))
    c.doc.add(Contents())
    _introduction(c)


def _task(c: Ctx, title) -> None:
    t, n = c.t, c.n
    r = c.r
    v, g = r.variant, r.gears
    mm = t("mm")
    stroke = (t("swing of the rocker $γ_max$ = {stroke}°, rocker length $l_(B C)$ = {v}").format(stroke=n(v.stroke), v=c.qty(v.l_bc_m * 1000, mm)) if v.is_rocker else
              t("stroke of the follower $S_max$ = {v}").format(v=c.qty(v.stroke * 1000, mm)))
    rpm = t("rpm")
    crank = (t("crank speed $n_\"кр\"$ = {speed}").format(speed=c.qty(g.crank_rpm, rpm))
             + (t(" (taken as in the textbook's example)") if g.crank_rpm_assumed else ""))
    s1 = _sheet1(c)
    torque = ("; " + t("mean reduced moment M = {torque}").format(torque=c.qty(g.torque_nm, t("N·m")))
              if g.torque_nm is not None and s1 is None else "")  # with a mechanism, M is a result of sheet 2
    who = literal(title.student) if title.student else "_" * 24  # a person's text: set as typed
    group = literal(title.group) if title.group else "_" * 10
    lines = [
        t("Student: {who}, group {group}.").format(who=who, group=group),
        (t("Topic: analysis of the lever mechanism, synthesis of the cam mechanism and of the gear drive, variant "
           "{number}.") if s1 is not None else
         t("Topic: synthesis of the cam mechanism and of the gear drive, variant {number}.")).format(number=v.number),
        *([_mechanism_line(c, s1)] if s1 is not None else []),
        t("Input data (Table 1.2 {{cite:book}}, variant {number}): scheme of the cam mechanism {scheme}; acceleration "
          "law {law} ({law_words}); {stroke}; allowed pressure angle $ν_max$ = {nu_max}°; cam speed $n_\"к\"$ = {n_cam}; "
          "phase angles $φ_\"у\"$ = {phi_rise}°, $φ_\"дс\"$ = {phi_far}°, $φ_\"в\"$ = {phi_return}°; "
          "{crank}{torque}.").format(
            number=v.number, scheme=v.scheme, law=v.law, law_words=law_words(v.law, c.lang), stroke=stroke,
            nu_max=n(v.nu_max_deg), n_cam=c.qty(v.n_cam_rpm, rpm), phi_rise=n(v.phi_rise_deg),
            phi_far=n(v.phi_far_dwell_deg), phi_return=n(v.phi_return_deg), crank=crank, torque=torque),
        (t("Drawings: sheet 1 — structural and kinematic analysis of the lever mechanism (A1); sheet 2 — force "
           "analysis of the lever mechanism and the flywheel (A1); sheet 3 — synthesis of the cam mechanism (A1); "
           "sheet 4 — synthesis of the gear mechanisms (A1).") if s1 is not None else
         t("Drawings: sheet 3 — synthesis of the cam mechanism (A1); sheet 4 — synthesis of the gear mechanisms (A1).")),
        t("Date of issue ____________    Supervisor ____________"),
    ]
    contents = [
        t("The explanatory note contains:"),
        *([t("the structure of the lever mechanism, its positions, the velocity and acceleration plans and the "
             "kinematics in all positions;")] if s1 is not None else []),
        *([t("the force analysis of the lever mechanism and the mean moment of the resistance forces reduced to the "
             "crank, M = {torque}, from which the motor is chosen; the flywheel;").format(
               torque=c.qty(g.torque_nm, t("N·m"), sig=4))] if s1 is not None and g.torque_nm is not None else []),
        t("the motion law of the follower, its diagrams and scales;"),
        t("the main dimensions of the cam mechanism by the allowed pressure angle;"),
        t("the profile of the cam;"),
        t("the choice of the motor, the scheme and the tooth numbers of the planetary reducer;"),
        t("the geometry of the spur pair and its contact ratio; the power of the motor.") if c.r.gears.torque_nm is not None
        else t("the geometry of the spur pair and its contact ratio."),
    ]
    c.doc.add(TaskSheet(t("Task"), lines, contents))


def _abstract(c: Ctx) -> None:
    t = c.t
    r = c.r
    z, g = r.cam.sizing, r.gears
    kw = [t("cam mechanism"), t("pressure angle"),
          t("cam profile"), t("planetary reducer"),
          t("tooth numbers"), t("assembly condition"),
          t("neighbouring condition"), t("involute mesh"),
          t("contact ratio")]
    s1, s2 = _sheet1(c), _sheet2(c)
    if s1 is not None:
        kw = [t("lever mechanism"), t("Assur group"), t("velocity plan"), t("acceleration plan")] + kw
    if s2 is not None:  # sheet 2's words; ГОСТ 7.32 allows 5…15 key words: the reducer's conditions give way
        kw = kw[:4] + [t("kinetostatics"), t("Zhukovsky's lever")] + (
            [t("flywheel")] if s2.flywheel is not None else []) + [w for w in kw[4:] if w not in (
                t("assembly condition"), t("neighbouring condition"))]
    mm = t("mm")
    geo = (f"$l_(O C)$ = {c.qty(z.l_oc_m * 1000, mm, decimals=2)}" if r.variant.is_rocker
           else f"$e$ = {c.qty(z.e_m * 1000, mm, decimals=2)}")
    if s1 is None:
        obj = t("The object of the project is the drive of a machine: the cam mechanism of variant {number} and the gear mechanisms between the motor, the cam and the crank of the linkage.").format(number=r.variant.number)
        aim = t("The aim is to find the main dimensions and the profile of the cam and the tooth numbers of the planetary reducer and of the spur pair that satisfy the conditions of the textbook.")
    else:
        obj = t("The object of the project is a machine: the lever mechanism «{name}», the cam mechanism of variant "
                "{number} and the gear mechanisms between the motor, the cam and the crank of the lever "
                "mechanism.").format(name=literal(s1.mechanism.name) if s1.mechanism.name else t("Mechanism"),
                                      number=r.variant.number)
        aim = (t("The aim is to analyse the structure, the motion and the forces of the lever mechanism, to find the "
                 "balancing moment, the driving moment and the flywheel that keeps the crank's speed within the "
                 "allowed fluctuation, and to find the main dimensions and the profile of the cam and the tooth "
                 "numbers of the planetary reducer and of the spur pair that satisfy the conditions of the textbook.")
               if s2 is not None else
               t("The aim is to analyse the structure and the motion of the lever mechanism and to find the main "
                 "dimensions and the profile of the cam and the tooth numbers of the planetary reducer and of the "
                 "spur pair that satisfy the conditions of the textbook."))
    results = t("Results: the cam with the base radius $r_0$ = {r0}, {geo}; the planetary reducer {teeth} with {planets}; "
                "the spur pair $z_1$ = {z1}, $z_2$ = {z2} (its mesh drawn at the drawing's module $m$ = {m} that the textbook gives in §2.1.1).").format(
        r0=c.qty(z.r0_m * 1000, mm, decimals=2), geo=geo, teeth=_teeth_text(g), planets=c.planets(g.planetary.planets),
        z1=g.spur.z1, z2=g.spur.z2, m=c.qty(g.spur.m_mm, mm))
    text = [obj, aim]
    if s1 is not None:
        text.append(t("Results of the lever mechanism: {items}.").format(items="; ".join(linkage_results(c))))
    text.append(results)
    c.doc.add(Abstract(kw, text))


def linkage_results(c: Ctx) -> list[str]:
    """What sheets 1 and 2 found, each a phrase read from the result objects (the abstract and the
    conclusion say the same): the stroke or swing and K; the balancing moment of the position of the
    force analysis by both methods; the driving moment; the flywheel and its size."""
    t, n = c.t, c.n
    s1, s2 = _sheet1(c), _sheet2(c)
    out = []
    if s1 is None:
        return out
    cy = s1.cycle
    if cy.stroke is not None:
        from .linkage_part import role_genitive

        move = (t("the stroke of the {whose} $H$ = {h}").format(whose=role_genitive(c, s1, s1.mechanism.output.link, False),
                                                                  h=c.qty(cy.stroke * 1000, t("mm"), decimals=2))
                if s1.mechanism.output.kind == "slider" else
                t("the swing of the rocker $ψ$ = {psi}°").format(psi=n(math.degrees(cy.stroke), decimals=2)))
        if cy.working is not None:
            move += t(", the time ratio $K$ = {k}").format(k=n(cy.time_ratio, decimals=3))
        out.append(move)
    if s2 is None:
        return out
    i = s2.force_position
    mb = float(s2.balancing[i])
    out.append(t("the balancing moment in position {label} $M_\"ур\"$ = {mb} (by Zhukovsky's lever, a difference of "
                 "{diff})").format(label=s2.sheet1.cycle.positions[i].label, mb=c.qty(mb, t("N·m"), decimals=2),
                                   diff=_lever_difference(c, s2)))
    if s2.is_engine:  # an engine: the constant moment is its consumer's resistance
        out.append(t("the consumer's resisting moment $M_\"с\"$ = {mc}").format(mc=c.qty(-s2.dynamics.M_d, t("N·m"), sig=4)))
    else:
        out.append(t("the driving moment $M_\"д\"$ = {md}").format(md=c.qty(abs(s2.dynamics.M_d), t("N·m"), sig=4)))
    fw = s2.flywheel
    if fw is not None:
        if fw.size is not None:
            size = fw.size
            dims = t("$D$ = {d}").format(d=c.qty(size.D * 1000, t("mm"), decimals=0))
            out.append(t("the flywheel $J_\"м\"$ = {j} ({dims}, mass {m})").format(
                j=c.qty(fw.mertsalov.J_fl, t("kg·m²"), sig=5), dims=dims, m=c.qty(size.m, t("kg"), decimals=1)))
        else:
            out.append(t("no flywheel is needed"))
    return out


def _lever_difference(c: Ctx, s2) -> str:
    """Zhukovsky's difference as §2.3 and sheet 2 give it (the lever's table, to its digits)."""
    return c.pct_digits(abs(s2.lever_table().difference_pct))


def linkage_requirements(c: Ctx) -> list[tuple[str, bool]]:
    """Sheet 2's checks, each (text, met): the balancing moment by the two methods within 1 %; the
    speed with the flywheel within the allowed δ."""
    t = c.t
    out = _sheet1_requirements(c)
    s2 = _sheet2(c)
    if s2 is None:
        return out
    diff = s2.lever_table().difference_pct
    out += [(t("the balancing moments by the force analysis and by Zhukovsky's lever agree within 1 % ({diff})").format(
        diff=_lever_difference(c, s2)), abs(diff) < 1.0)]
    fw = s2.flywheel
    if fw is not None:
        ok = fw.delta_actual <= fw.delta * (1 + 1e-6)
        out.append(((t("with the flywheel the coefficient of speed fluctuation $δ$ = {actual} does not exceed the "
                       "allowed {delta}") if ok else
                     t("with the flywheel the coefficient of speed fluctuation $δ$ = {actual} exceeds the allowed "
                       "{delta}")).format(actual=c.n(fw.delta_actual, sig=3), delta=c.n(fw.delta, sig=4)), ok))
    return out


def _sheet1_requirements(c: Ctx) -> list[tuple[str, bool]]:
    """Sheet 1's checks, each (text, met): every group's largest pressure angle within the usual limit
    of a lever mechanism (45°: the transmission angle at least 45°, Artobolevsky), and a working stroke
    not faster than the return (K ≥ 1: the output moves slowly under the load and returns fast)."""
    from ...linkage.positions import PRESSURE_WARN_DEG
    from ..terminal.mechanism import pattern

    t, n = c.t, c.n
    s1 = _sheet1(c)
    if s1 is None:
        return []
    m, cy = s1.mechanism, s1.cycle
    out = []
    for p in cy.pressure:
        g = m.groups[p.group - 1]
        if g.kind == "RPR" and not g.offset:  # the block acts at right angles to the slot: 0°
            continue
        worst = math.degrees(p.worst)
        ok = worst <= PRESSURE_WARN_DEG
        out.append(((t("the largest pressure angle of group {group} ({kind}), {angle}°, does not exceed the usual "
                       "limit of a lever mechanism, {limit}°") if ok else
                     t("the largest pressure angle of group {group} ({kind}), {angle}° at $φ$ = {phi}°, exceeds the "
                       "usual limit of a lever mechanism, {limit}°: the group transmits motion poorly there")).format(
            group=p.group, kind=pattern(g.kind, c.lang), angle=n(worst, decimals=2), limit=n(PRESSURE_WARN_DEG),
            phi=n(round(math.degrees(p.phi), 1) % 360.0, decimals=1)), ok))
    if cy.time_ratio is not None and m.gas_head is None:
        ok = cy.time_ratio >= 1.0 - 1e-9
        out.append(((t("the working stroke is not faster than the return stroke: $K$ = {K} ≥ 1") if ok else
                     t("$K$ = {K} < 1: the working stroke is faster than the return stroke (the output moves "
                       "faster under the load than without it)")).format(K=n(cy.time_ratio, decimals=3)), ok))
    return out


def _teeth_text(g) -> str:
    from ...gears.design import design_teeth_text

    return design_teeth_text(g.planetary)


def _introduction(c: Ctx) -> None:
    t = c.t
    c.doc.add(Heading(1, t("Introduction"), "structural"))
    if _sheet1(c) is None:
        c.p(t("The course project in the theory of mechanisms and machines teaches the synthesis of the main mechanisms of a machine by the methods of the discipline. This note covers sheets 3 and 4 of the project: the synthesis of the cam mechanism (the motion law of the follower, the main dimensions by the allowed pressure angle, the profile of the cam) and the synthesis of the gear mechanisms of the drive (the choice of the motor and of the scheme of the planetary reducer, its tooth numbers under the conditions of synthesis, the geometry of the spur pair) by the textbook {cite:book}."))
    else:  # the four sheets, in the order of the note
        c.p(t("The course project in the theory of mechanisms and machines teaches the analysis and the synthesis of "
              "the main mechanisms of a machine by the methods of the discipline. This note covers the four sheets of "
              "the project: the structural and kinematic analysis of the lever mechanism (sheet 1); its force analysis, "
              "which gives the mean moment of the resistance forces the motor has to overcome, and the flywheel "
              "(sheet 2); the synthesis of the cam mechanism (sheet 3) and the synthesis of the gear mechanisms of the "
              "drive (sheet 4) by the textbook {cite:book}."))
    c.p(t("The computations were made with the program tmm, which follows the procedures of the textbook and prints every substitution, so that each number of the note can be checked by hand."))
    c.p(t("The drawing sheets follow the unified system for design documentation: the title block by GOST 2.104 "
          "{cite:gost2104}, the scales by GOST 2.302 {cite:gost2302}; the note is set out by GOST 7.32 {cite:gost732}."))


def _sheet1(c: Ctx):
    return sheet1_of(c.r)


def _sheet2(c: Ctx):
    """Sheet 2 (forces and the flywheel) of the project, or None."""
    s = getattr(c.r, "linkage", None)
    return s if s is not None and hasattr(s, "flywheel") else None


def _mechanism_line(c: Ctx, s1) -> str:
    """The lever mechanism of the task: its name, crank, groups (sheet 1's data)."""
    from ..terminal.mechanism import pattern

    m = s1.mechanism
    cr = m.crank
    sense = c.t("counter-clockwise") if cr.sense > 0 else c.t("clockwise")
    groups = ", ".join(f"{pattern(g.kind, c.lang)} ({'–'.join(g.joints)})" for g in m.groups)
    return c.t("Lever mechanism: «{name}»; the crank {crank} of length {length} turns {sense} at {rpm}; the groups "
               "{groups}; {count} positions per turn.").format(
        name=literal(m.name) if m.name else c.t("Mechanism"), crank=m.links[0].name, length=c.qty(cr.length * 1000, c.t("mm")),
        sense=sense, rpm=c.qty(cr.rpm, c.t("rpm"), sig=6), groups=groups, count=m.positions)


# --- assumptions -------------------------------------------------------------------------------------


def assumptions(c: Ctx) -> None:
    """The assumptions of the calculation, each once, short (ГОСТ 7.32: its own section)."""
    t, n = c.t, c.n
    r = c.r
    g, cam = r.gears, r.cam
    s = cam.motion.scales
    c.doc.add(Heading(1, t("Assumptions"), "chapter", "assumptions"))
    items = [
        t("The schemes of Figure 1.8 {cite:book} are read as: 1 — translating roller follower, force closure; 2 — the same, form closure (grooved cam); 3 — rocker, force closure; 4 — rocker, form closure."),
        t("The diagrams are laid out for the sheet with $b$ = {b} for the working angle and $Y_(S max)$ = {y_max}; the "
          "integration bases are the largest round values that keep the ordinates within 60 mm.").format(
            b=c.qty(s.b_mm, t("mm")), y_max=c.qty(s.y_s_max_mm, t("mm"))),
    ]
    if g.crank_rpm_assumed:
        items.append(t("The crank speed of the linkage is not given by Table 1.2; $n_\"кр\"$ = {speed} is taken as in the "
                       "example of §2.4 {{cite:book}}. With the crank speed of sheet 1 the motor, the ratios and the "
                       "reducer change.").format(speed=c.qty(g.crank_rpm, t("rpm"))))
    items.append(t("The planetary ratio may deviate from the required by ±{tolerance_pct} % (§2.4 {{cite:book}}); the ranges of the schemes are read as $i <= 8$ — scheme 1, $8 < i <= 16$ — scheme 2, $i > 16$ — two stages.").format(tolerance_pct=n(g.tolerance_pct)))
    items.append(t("The neighbouring condition (2.5) is computed exactly instead of being read from Table 2.1."))
    s1 = _sheet1(c)
    if s1 is not None and abs(g.crank_rpm_actual - s1.mechanism.crank.rpm) > 1e-9:
        # the drive's real crank speed differs from the file's within the reducer's tolerance: say which is used
        items.append(t("The analysis of the lever mechanism (sheets 1 and 2) is made at the crank speed of the task, "
                       "$n_1$ = {n1} ($ω_1$ = {w1} rad/s); the drive turns the crank at {actual} (the reducer's ratio "
                       "differs from the required by {error}), which changes the velocities by the same share and the "
                       "inertia forces by about twice it.").format(
            n1=c.qty(s1.mechanism.crank.rpm, t("rpm"), sig=6), w1=c.n(abs(s1.mechanism.crank.omega), sig=4),
            actual=c.qty(g.crank_rpm_actual, t("rpm"), decimals=1),
            error=c.pct(g.checks.ratio_error_pct, sign=True)))
    items.append(t("The efficiencies in the power of the motor are $η_1$ = {eta1} (0,96 per single- or double-row stage) and $η_2$ = {eta2} (§2.6 {{cite:book}}).").format(eta1=c.n(g.eta1, sig=4), eta2=c.n(g.eta2)))
    if g.torque_nm is None:
        items.append(t("The mean reduced moment of sheet 2 is not given; the power of the motor is not computed."))
    items.append(t("A transverse contact ratio of at least 1,2 is taken as sufficient for the smoothness of a spur pair."))
    c.doc.add(ListBlock(items, ordered=True))


# --- conclusion --------------------------------------------------------------------------------------


def conclusion(c: Ctx) -> None:
    t, n = c.t, c.n
    r = c.r
    cam, g = r.cam, r.gears
    v, z, p, ch = cam.variant, cam.sizing, cam.profile, cam.checks
    c.doc.add(Heading(1, t("Conclusion"), "structural"))
    mm = t("mm")
    met, unmet = t("met"), t("NOT met")

    def verdict(ok: bool) -> str:
        return met if ok else unmet

    lk = linkage_results(c)
    if lk:
        s1 = _sheet1(c)
        c.p(t("The lever mechanism «{name}» is analysed (sheets 1 and 2): {items}.").format(
            name=literal(s1.mechanism.name) if s1.mechanism.name else t("Mechanism"), items="; ".join(lk)))
        lreqs = linkage_requirements(c)
        if lreqs:
            c.doc.add(ListBlock([f"{txt} — {verdict(ok)};" for txt, ok in lreqs[:-1]] +
                                [f"{lreqs[-1][0]} — {verdict(lreqs[-1][1])}."]))
        c.doc.claim(kind="conclusion_linkage", items=tuple(lk), met=tuple(ok for _, ok in lreqs))
    else:
        lreqs = []
    geo = (f"$l_(O C)$ = {c.qty(z.l_oc_m * 1000, mm, decimals=2)}" if v.is_rocker
           else t("offset") + f" $e$ = {c.qty(z.e_m * 1000, mm, decimals=2)}")
    c.p(t("A cam mechanism of scheme {scheme} is designed: the base radius of the pitch profile $r_0$ = {v}, {geo}, the roller radius $r_\"р\"$ = {v2}; the profile is drawn at {scale}.").format(scheme=v.scheme, v=c.qty(z.r0_m * 1000, mm, decimals=2), geo=geo, v2=c.qty(p.roller_m * 1000, mm, decimals=2), scale=cam.drawing.scale))
    reqs = []
    ok = ch.nu_rise_ok and ch.nu_return_ok
    where = t("on the rise {nu}°").format(nu=n(ch.nu_rise_deg, decimals=2))
    if ch.return_limited:
        where += t(", on the return {nu}°").format(nu=n(ch.nu_return_deg, decimals=2))
    nu_txt = (t("the largest pressure angle ({where}) does not exceed the allowed $ν_max$ = {nu_max}°") if ok else
              t("the largest pressure angle ({where}) exceeds the allowed $ν_max$ = {nu_max}°")).format(
        where=where, nu_max=n(v.nu_max_deg))
    reqs.append((nu_txt, ok))
    reqs.append((t("no undercut of the profile: $r_\"р\"$ = {roller} < $ρ_min$ = {rho}").format(
        roller=c.qty(ch.roller_m * 1000, mm, decimals=2), rho=c.qty(ch.rho_limit_m * 1000, mm, decimals=2)), ch.undercut_ok))
    if ch.pivot_ok is not None:
        reqs.append((t("the cam clears the rocker's pivot: $l_(O C)$ = {l_oc} > {body}").format(
            l_oc=c.qty(ch.l_oc_m * 1000, mm, decimals=2), body=c.qty(ch.body_m * 1000, mm, decimals=2)), bool(ch.pivot_ok)))
    reqs.append((t("the profile fits the field of the sheet at a standard scale ({scale})").format(scale=cam.drawing.scale), cam.drawing.fits))
    c.doc.add(ListBlock([f"{txt} — {verdict(ok)};" for txt, ok in reqs[:-1]] + [f"{reqs[-1][0]} — {verdict(reqs[-1][1])}."]))
    c.doc.claim(kind="conclusion_cam", met=tuple(ok for _, ok in reqs), checks=ch, fits=cam.drawing.fits)

    d = g.planetary
    scheme_words = {"1": t("a single-row planetary reducer"),
                    "2": t("a double-row planetary reducer"),
                    "1+1": t("two single-row planetary stages")}[g.scheme]
    sp = g.spur
    rpm = t("rpm")
    c.p(t("The drive: a motor of {speed}, {scheme_words} {teeth} {with_planets} ($i$ = {ratio}), the spur pair "
          "$z_1$ = {z1}, $z_2$ = {z2} (its mesh drawn at the drawing's module $m$ = {m} that the textbook gives in §2.1.1).").format(
        speed=c.qty(g.motor_rpm, rpm), scheme_words=scheme_words, teeth=_teeth_text(g),
        with_planets=c.nt("with {k} planet", "with {k} planets", d.planets).format(k=d.planets),
        ratio=n(d.ratio, decimals=4), z1=sp.z1, z2=sp.z2, m=c.qty(sp.m_mm, mm)))
    gch = g.checks
    greqs = [(t("the ratio deviates from the required {i_pl} by {error}, within ±{tolerance} % (the crank turns at "
                "{speed})").format(i_pl=n(g.i_planetary, decimals=4), error=c.pct(gch.ratio_error_pct, sign=True),
                                   tolerance=n(g.tolerance_pct), speed=c.qty(g.crank_rpm_actual, rpm, decimals=1)),
              gch.ratio_ok)]
    for j, sc in enumerate(gch.stages, 1):
        stage = t(" of stage {j}").format(j=j) if len(gch.stages) > 1 else ""
        greqs.append((t("coaxiality, assembly, neighbouring and no interference{stage}").format(stage=stage), sc.ok))
    greqs.append((t("at least three planets ($k$ = {planets})").format(planets=d.planets),
                  d.planets >= 3))
    if not sp.shifted:
        greqs.append((t("the centre distance and the tooth heights of the spur pair agree"), sp.check_ok))
    greqs.append((t("smooth running of the spur pair: $ε_α$ = {eps_alpha} ≥ 1,2").format(eps_alpha=n(sp.eps_alpha, decimals=3)).replace(
        "≥", "≥" if sp.eps_alpha >= 1.2 else "<"), sp.eps_alpha >= 1.2))
    if min(sp.z1, sp.z2) < 17:
        greqs.append((t("no gear below 17 teeth (undercut)"), False))
    if g.power is not None:
        if g.power.rated_kw is not None:
            kw = t("kW")
            greqs.append((t("the motor's rated power {rated} ≥ the required {power}").format(
                rated=c.qty(g.power.rated_kw, kw), power=c.qty(g.power.power_kw, kw, decimals=3)), True))
        else:
            greqs.append((t("a motor of the standard series covers the required power"), False))
    c.doc.add(ListBlock([f"{txt} — {verdict(ok)};" for txt, ok in greqs[:-1]] + [f"{greqs[-1][0]} — {verdict(greqs[-1][1])}."]))
    c.doc.claim(kind="conclusion_gears", met=tuple(ok for _, ok in greqs), gears=g)
    bad = [txt for txt, ok in lreqs + reqs + greqs if not ok]
    if bad:
        c.p(c.nt("{bad} of the requirements is not met; the design has to be revised there.",
                 "{bad} of the requirements are not met; the design has to be revised there.", len(bad)).format(bad=len(bad)))
    elif g.power is None:  # no mean moment (sheet 2) given: the motor is chosen by its speed alone
        c.p(t("All requirements checked in this note are met. The motor is chosen by its speed only: its power "
              "needs the mean reduced moment of sheet 2, which is not given."))
    else:
        c.p(t("All requirements of the task are met."))


# --- references and appendix ---------------------------------------------------------------------------


def references(c: Ctx) -> None:
    t = c.t
    c.doc.add(Heading(1, t("References"), "structural"))
    c.doc.add(ReferenceList())


def appendix_profile(c: Ctx) -> None:
    """Appendix А: the coordinates of the pitch and working profiles every 10° (for drawing the cam)."""
    import numpy as np

    t, n = c.t, c.n
    cam = c.r.cam
    p = cam.profile
    c.doc.add(Heading(1, t("Coordinates of the cam profile"), "appendix", "profile",
                      status=t("informative")))
    c.p(t("The coordinates are given in the frame of the cam: the origin at its centre O, the axis y along the initial direction of the follower's rise; the polar angle is counted against the cam's rotation (Table {tab:profile_xy})."))
    phi = np.degrees(np.asarray(p.phi))
    rows = []
    mm = t("mm")
    groove = p.outer is not None
    for a in range(0, 360, 10):
        k = int(np.argmin(np.abs(phi - a)))
        px, py = p.pitch[k] * 1000
        wx, wy = p.inner[k] * 1000
        row = [n(a), n(px, decimals=2), n(py, decimals=2), n(math.hypot(px, py), decimals=2), n(wx, decimals=2), n(wy, decimals=2)]
        if groove:
            ox, oy = p.outer[k] * 1000
            row += [n(ox, decimals=2), n(oy, decimals=2)]
        rows.append(row)
    header = ["$φ$, °", f"$x$, {mm}", f"$y$, {mm}", f"$R$, {mm}", f"$x_1$, {mm}", f"$y_1$, {mm}"]
    if groove:
        header += [f"$x_2$, {mm}", f"$y_2$, {mm}"]
    cap = (t("Coordinates of the pitch profile ($x$, $y$, radius $R$) and of the working profile ($x_1$, $y_1$; the "
             "outer wall of the groove $x_2$, $y_2$)") if groove else
           t("Coordinates of the pitch profile ($x$, $y$, radius $R$) and of the working profile ($x_1$, $y_1$)"))
    c.table("profile_xy", cap, header, rows, align=["center"] * len(header))
