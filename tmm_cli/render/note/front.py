"""The parts of the note around the chapters (ГОСТ 7.32-2017): title page, task, abstract, contents,
introduction, the assumptions, the conclusion, the list of sources and the appendix."""

from __future__ import annotations

import math

from ..terminal.variants import law_words
from .ctx import Ctx
from .model import Abstract, Contents, Heading, ListBlock, ReferenceList, TaskSheet, TitlePage

from .sources import SOURCES

MINISTRY_RU = "Министерство науки и высшего образования Российской Федерации"


def title_meta(c: Ctx, title) -> dict:
    """The title page's fields and the words the style prints (note-style.typ reads them)."""
    t = c.t
    v = c.r.variant
    org = [s.strip() for s in (title.org or "").split(",") if s.strip()]
    return {
        "lang": c.lang,
        "doc-title": t("Explanatory note, TMM course project, variant {number}").format(number=v.number),
        "ministry": MINISTRY_RU if c.lang == "ru" else "",
        "org-lines": org,
        "doc-kind": t("Explanatory note"),
        "discipline": t("to the course project in the discipline «Theory of mechanisms and machines»"),
        "topic": t("«Synthesis of the cam mechanism and of the gear drive»"),
        "variant-line": t("Variant {number}").format(number=v.number),
        "designation": title.designation_for(0, v.number) + (" ПЗ" if c.lang == "ru" else ""),  # ГОСТ 2.102's code
        "teacher-label": t("Supervisor"),
        "teacher": title.teacher,
        "student-label": t("Student"),
        "student": title.student,
        "group-label": t("group"),
        "group": title.group,
        "sign-label": t("signature"),
        "date-label": "г." if c.lang == "ru" else "",  # after «  » ______ 20__
        "grade-label": t("Defended with the mark"),
        "city": getattr(title, "city", "") or "",
        "year": str(title.the_year),
        "figure-word": t("Figure"),
        "table-word": t("Table"),
        "continued-word": t("Table continued"),
        "where-word": t("where"),
        "appendix-word": t("Appendix"),
    }


def front_matter(c: Ctx, title) -> None:
    c.doc.sources = {k: v["ru" if c.ru else "en"] for k, v in SOURCES.items()}
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
    crank = (c.t2(f"crank speed $n_\"кр\"$ = {c.qty(g.crank_rpm, 'rpm')}", f"частота вращения кривошипа $n_\"кр\"$ = "
               f"{c.qty(g.crank_rpm, 'об/мин')}") + (t(" (taken as in the textbook's example)")
                                                    if g.crank_rpm_assumed else ""))
    torque = ("; " + c.t2(f"mean reduced moment M = {c.qty(g.torque_nm, 'N·m')}", f"средний приведённый момент M = "
                       f"{c.qty(g.torque_nm, 'Н·м')}")) if g.torque_nm is not None else ""
    who = title.student or "_" * 24
    group = title.group or "_" * 10
    lines = [
        t("Student: {who}, group {group}.").format(who=who, group=group),
        t("Topic: synthesis of the cam mechanism and of the gear drive, variant {number}.").format(number=v.number),
        c.t2(f"Input data (Table 1.2 {{cite:book}}, variant {v.number}): scheme of the cam mechanism {v.scheme}; "
          f"acceleration law {v.law} ({law_words(v.law, c.lang)}); {stroke}; allowed pressure angle $ν_max$ = "
          f"{n(v.nu_max_deg)}°; cam speed $n_k$ = {c.qty(v.n_cam_rpm, 'rpm' if not c.ru else 'об/мин')}; phase angles "
          f"$φ_\"у\"$ = {n(v.phi_rise_deg)}°, $φ_\"дс\"$ = {n(v.phi_far_dwell_deg)}°, $φ_\"в\"$ = {n(v.phi_return_deg)}°; "
          f"{crank}{torque}.",
          f"Исходные данные (таблица 1.2 {{cite:book}}, вариант {v.number}): схема кулачкового механизма {v.scheme}; "
          f"закон изменения ускорения {v.law} ({law_words(v.law, c.lang)}); {stroke}; допустимый угол давления "
          f"$ν_max$ = {n(v.nu_max_deg)}°; частота вращения кулачка $n_k$ = {c.qty(v.n_cam_rpm, 'об/мин')}; фазовые "
          f"углы $φ_\"у\"$ = {n(v.phi_rise_deg)}°, $φ_\"дс\"$ = {n(v.phi_far_dwell_deg)}°, $φ_\"в\"$ = "
          f"{n(v.phi_return_deg)}°; {crank}{torque}."),
        t("Drawings: sheet 3 — synthesis of the cam mechanism (A1); sheet 4 — synthesis of the gear mechanisms (A1)."),
        t("Date of issue ____________    Supervisor ____________"),
    ]
    contents = [
        t("The explanatory note contains:"),
        t("the motion law of the follower, its diagrams and scales;"),
        t("the main dimensions of the cam mechanism by the allowed pressure angle;"),
        t("the profile of the cam;"),
        t("the choice of the motor, the scheme and the tooth numbers of the planetary reducer;"),
        t("the geometry of the spur pair and its contact ratio; the power of the motor."),
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
    geo = (c.t2(f"$l_(O C)$ = {c.qty(z.l_oc_m * 1000, 'mm', decimals=2)}", f"$l_(O C)$ = {c.qty(z.l_oc_m * 1000, 'мм', decimals=2)}")
           if r.variant.is_rocker else c.t2(f"$e$ = {c.qty(z.e_m * 1000, 'mm', decimals=2)}",
                                         f"$e$ = {c.qty(z.e_m * 1000, 'мм', decimals=2)}"))
    text = [
        t("The object of the project is the drive of a machine: the cam mechanism of variant {number} and the gear mechanisms between the motor, the cam and the crank of the linkage.").format(number=r.variant.number),
        t("The aim is to find the main dimensions and the profile of the cam and the tooth numbers of the planetary reducer and of the spur pair that satisfy the conditions of the textbook."),
        c.t2(f"Results: the cam with the base radius $r_0$ = {c.qty(z.r0_m * 1000, 'mm', decimals=2)}, {geo}; the "
          f"planetary reducer {_teeth_text(g)} with {c.planets(g.planetary.planets)}; the spur pair "
          f"$z_1$ = {g.spur.z1}, $z_2$ = {g.spur.z2}, $m$ = {c.qty(g.spur.m_mm, 'mm')}.",
          f"Результаты: кулачок с радиусом основной окружности $r_0$ = {c.qty(z.r0_m * 1000, 'мм', decimals=2)}, "
          f"{geo}; планетарный редуктор с числами зубьев {_teeth_text(g)} и {c.planets(g.planetary.planets)}; "
          f"простая передача $z_1$ = {g.spur.z1}, $z_2$ = {g.spur.z2}, $m$ = {c.qty(g.spur.m_mm, 'мм')}."),
    ]
    c.doc.add(Abstract(kw, text))


def _teeth_text(g) -> str:
    from ...gears.design import design_teeth_text

    return design_teeth_text(g.planetary)


def _introduction(c: Ctx) -> None:
    t = c.t
    c.doc.add(Heading(1, t("Introduction"), "structural"))
    c.p(t("The course project in the theory of mechanisms and machines teaches the synthesis of the main mechanisms of a machine by the methods of the discipline. This note covers sheets 3 and 4 of the project: the synthesis of the cam mechanism (the motion law of the follower, the main dimensions by the allowed pressure angle, the profile of the cam) and the synthesis of the gear mechanisms of the drive (the choice of the motor and of the scheme of the planetary reducer, its tooth numbers under the conditions of synthesis, the geometry of the spur pair) by the textbook {cite:book}."))
    c.p(t("The computations were made with the program tmm, which follows the procedures of the textbook and prints every substitution, so that each number of the note can be checked by hand."))


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
        c.t2(f"The diagrams are laid out for the sheet with $b$ = {c.qty(s.b_mm, 'mm')} for the working angle and "
          f"$Y_(S max)$ = {c.qty(s.y_s_max_mm, 'mm')}; the integration bases are the largest round values that keep "
          "the ordinates within 60 mm.",
          f"Диаграммы размещаются на листе при длине рабочего угла $b$ = {c.qty(s.b_mm, 'мм')} и наибольшей "
          f"ординате перемещений $Y_(S max)$ = {c.qty(s.y_s_max_mm, 'мм')}; базы интегрирования — наибольшие "
          "круглые значения, при которых ординаты не превышают 60 мм."),
    ]
    if g.crank_rpm_assumed:
        items.append(c.t2(f"The crank speed of the linkage is not given by Table 1.2; $n_\"кр\"$ = {c.qty(g.crank_rpm, 'rpm')} "
                       "is taken as in the example of §2.4 {cite:book}. With the crank speed of sheet 1 the motor, the "
                       "ratios and the reducer change.",
                       f"Частота вращения кривошипа в таблице 1.2 не задана; принята $n_\"кр\"$ = "
                       f"{c.qty(g.crank_rpm, 'об/мин')}, как в примере п. 2.4 {{cite:book}}. При частоте вращения "
                       "кривошипа по листу 1 изменятся двигатель, передаточные отношения и редуктор."))
    items.append(t("The planetary ratio may deviate from the required by ±{tolerance_pct} % (§2.4 {{cite:book}}); the ranges of the schemes are read as $i <= 8$ — scheme 1, $8 < i <= 16$ — scheme 2, $i > 16$ — two stages.").format(tolerance_pct=n(g.tolerance_pct)))
    items.append(t("The neighbouring condition (2.5) is computed exactly instead of being read from Table 2.1."))
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

    geo = (f"$l_(O C)$ = {c.qty(z.l_oc_m * 1000, mm, decimals=2)}" if v.is_rocker
           else t("offset") + f" $e$ = {c.qty(z.e_m * 1000, mm, decimals=2)}")
    c.p(t("A cam mechanism of scheme {scheme} is designed: the base radius of the pitch profile $r_0$ = {v}, {geo}, the roller radius $r_\"р\"$ = {v2}; the profile is drawn at {scale}.").format(scheme=v.scheme, v=c.qty(z.r0_m * 1000, mm, decimals=2), geo=geo, v2=c.qty(p.roller_m * 1000, mm, decimals=2), scale=cam.drawing.scale))
    reqs = []
    ok = ch.nu_rise_ok and ch.nu_return_ok
    where_en = f"on the rise {n(ch.nu_rise_deg, decimals=2)}°"
    where_ru = f"на удалении {n(ch.nu_rise_deg, decimals=2)}°"
    if ch.return_limited:
        where_en += f", on the return {n(ch.nu_return_deg, decimals=2)}°"
        where_ru += f", на возвращении {n(ch.nu_return_deg, decimals=2)}°"
    nu_txt = c.t2(f"the largest pressure angle ({where_en}) {'does not exceed' if ok else 'exceeds'} the allowed "
               f"$ν_max$ = {n(v.nu_max_deg)}°",
               f"наибольший угол давления ({where_ru}) {'не превышает' if ok else 'превышает'} допускаемый "
               f"$ν_max$ = {n(v.nu_max_deg)}°")
    reqs.append((nu_txt, ok))
    reqs.append((c.t2(f"no undercut of the profile: $r_\"р\"$ = {n(ch.roller_m * 1000, decimals=2)} mm < $ρ_min$ = "
                   f"{n(ch.rho_limit_m * 1000, decimals=2)} mm",
                   f"отсутствие подреза профиля: $r_\"р\"$ = {c.qty(ch.roller_m * 1000, 'мм', decimals=2)} < $ρ_min$ = "
                   f"{c.qty(ch.rho_limit_m * 1000, 'мм', decimals=2)}"), ch.undercut_ok))
    if ch.pivot_ok is not None:
        reqs.append((c.t2(f"the cam clears the rocker's pivot: $l_(O C)$ = {n(ch.l_oc_m * 1000, decimals=2)} mm > "
                       f"{n(ch.body_m * 1000, decimals=2)} mm",
                       f"кулачок не задевает ось коромысла: $l_(O C)$ = {c.qty(ch.l_oc_m * 1000, 'мм', decimals=2)} > "
                       f"{c.qty(ch.body_m * 1000, 'мм', decimals=2)}"), bool(ch.pivot_ok)))
    reqs.append((t("the profile fits the field of the sheet at a standard scale ({scale})").format(scale=cam.drawing.scale), cam.drawing.fits))
    c.doc.add(ListBlock([f"{txt} — {verdict(ok)};" for txt, ok in reqs[:-1]] + [f"{reqs[-1][0]} — {verdict(reqs[-1][1])}."]))
    c.doc.claim(kind="conclusion_cam", met=tuple(ok for _, ok in reqs), checks=ch, fits=cam.drawing.fits)

    d = g.planetary
    scheme_words = {"1": t("a single-row planetary reducer"),
                    "2": t("a double-row planetary reducer"),
                    "1+1": t("two single-row planetary stages")}[g.scheme]
    sp = g.spur
    c.p(c.t2(f"The drive: a motor of {c.qty(g.motor_rpm, 'rpm')}, {scheme_words} {_teeth_text(g)} with "
          f"{c.planets(d.planets)} ($i$ = {n(d.ratio, decimals=4)}), the spur pair $z_1$ = {sp.z1}, $z_2$ = {sp.z2}, "
          f"$m$ = {c.qty(sp.m_mm, 'mm')}.",
          f"Спроектирован привод: двигатель с частотой вращения {c.qty(g.motor_rpm, 'об/мин')}, {scheme_words} "
          f"{_teeth_text(g)} с {d.planets} {'сателлитом' if d.planets == 1 else 'сателлитами'} ($i$ = "
          f"{n(d.ratio, decimals=4)}), простая передача $z_1$ = {sp.z1}, $z_2$ = {sp.z2}, $m$ = {c.qty(sp.m_mm, 'мм')}."))
    gch = g.checks
    greqs = [(c.t2(f"the ratio deviates from the required {n(g.i_planetary, decimals=4)} by {c.pct(gch.ratio_error_pct, sign=True)}, "
                f"within ±{n(g.tolerance_pct)} % (the crank turns at {c.qty(g.crank_rpm_actual, 'rpm', decimals=1)})",
                f"отклонение передаточного отношения от требуемого {n(g.i_planetary, decimals=4)} составляет "
                f"{c.pct(gch.ratio_error_pct, sign=True)} при допускаемых ±{n(g.tolerance_pct)} % (кривошип вращается "
                f"с частотой {c.qty(g.crank_rpm_actual, 'об/мин', decimals=1)})"), gch.ratio_ok)]
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
            greqs.append((c.t2(f"the motor's rated power {n(g.power.rated_kw)} kW ≥ the required {n(g.power.power_kw, decimals=3)} kW",
                            f"номинальная мощность двигателя {c.qty(g.power.rated_kw, 'кВт')} ≥ потребной "
                            f"{c.qty(g.power.power_kw, 'кВт', decimals=3)}"), True))
        else:
            greqs.append((t("a motor of the standard series covers the required power"), False))
    c.doc.add(ListBlock([f"{txt} — {verdict(ok)};" for txt, ok in greqs[:-1]] + [f"{greqs[-1][0]} — {verdict(greqs[-1][1])}."]))
    c.doc.claim(kind="conclusion_gears", met=tuple(ok for _, ok in greqs), gears=g)
    bad = [txt for txt, ok in reqs + greqs if not ok]
    if bad:
        c.p(t("{bad} of the requirements {v} not met; the design has to be revised there.").format(bad=len(bad), v='is' if len(bad) == 1 else 'are'))
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
    cap = c.t2("Coordinates of the pitch profile ($x$, $y$, radius $R$) and of the working profile ($x_1$, $y_1$"
            + (t("; the outer wall of the groove $x_2$, $y_2$") if groove else "") + ")",
            "Координаты теоретического профиля ($x$, $y$, радиус-вектор $R$) и действительного профиля ($x_1$, $y_1$"
            + ("; наружная стенка паза $x_2$, $y_2$" if groove else "") + ")")
    c.table("profile_xy", cap, header, rows, align=["center"] * len(header))
