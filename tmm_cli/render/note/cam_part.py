"""The chapter on the cam mechanism (sheet 3, book section 1), from a CamResult.

Every sentence that gives a reason is made from the decision the core took (the swing of a
rocker, the centre of the cam, the roller, the drawing scale) and is recorded as a claim
(:meth:`~.model.Document.claim`) that the tests check against the numbers.
"""

from __future__ import annotations

import math

from functools import reduce

from ...cam.laws import law_impacts, law_max
from ...i18n import N_
from ..terminal.variants import law_words
from .ctx import Ctx, V

_PHASE = {"rise": N_("rise"), "far_dwell": N_("far dwell"), "return": N_("return"), "near_dwell": N_("near dwell")}

_LAW_F = {
    1: ['f(t) = 2t^2 "  for " 0 <= t <= 1/2', 'f(t) = 1 - 2(1 - t)^2 "  for " 1/2 < t <= 1'],  # "for" translated
    2: ["f(t) = 3t^2 - 2t^3"],
    3: ["f(t) = (1 - cos π t)/2"],
    4: ["f(t) = t - (sin 2π t)/(2π)"],
}

_SCHEME = {
    1: N_("a translating roller follower kept on the cam by a spring (force closure)"),
    2: N_("a translating roller follower in a groove of the cam (form closure)"),
    3: N_("an oscillating roller follower (rocker) kept on the cam by a spring (force closure)"),
    4: N_("an oscillating roller follower (rocker) in a groove of the cam (form closure)"),
}


def cam_chapter(c: Ctx) -> None:
    r = c.r.cam
    c.doc.add(_heading(c, 1, c.t("Synthesis of the cam mechanism"), "cam"))
    _input(c, r)
    _motion(c, r)
    _scales(c, r)
    _sizing(c, r)
    _profile(c, r)
    _pressure(c, r)


def _heading(c: Ctx, level: int, text: str, label: str | None = None):
    from .model import Heading

    return Heading(level, text, "chapter", label)


# --------------------------------------------------------------------------------------------------
def _input(c: Ctx, r) -> None:
    v = r.variant
    t, n = c.t, c.n
    mm = t("mm")
    c.doc.add(_heading(c, 2, t("Input data")))
    c.p(t("The cam mechanism is designed for variant {number} of Table 1.2 {{cite:book}}: {scheme}. The input data "
          "are given in Table {{tab:cam_input}}.").format(number=v.number, scheme=t(_SCHEME[v.scheme])))
    rows = [
        [t("Scheme of the mechanism"), "—", str(v.scheme)],
        [c.tc("note, input data", "Acceleration law"), "—",
         f"{v.law} ({law_words(v.law, c.lang)})"],
    ]
    if v.is_rocker:
        rows += [[t("Swing of the rocker"), "$γ_max$, °", n(v.stroke)],
                 [t("Length of the rocker"), f"$l_(B C)$, {mm}", n(v.l_bc_m * 1000)]]
    else:
        rows += [[t("Stroke of the follower"), f"$S_max$, {mm}", n(v.stroke * 1000)]]
    rows += [
        [t("Allowed pressure angle"), "$ν_max$, °", n(v.nu_max_deg)],
        [t("Cam speed (sign: sense of rotation)"),
         "$n_\"к\"$, " + t("rpm"), n(v.n_cam_rpm)],
        [t("Rise angle"), '$φ_"у"$, °', n(v.phi_rise_deg)],
        [t("Far-dwell angle"), '$φ_"дс"$, °', n(v.phi_far_dwell_deg)],
        [t("Return angle"), '$φ_"в"$, °', n(v.phi_return_deg)],
    ]
    c.table("cam_input", t("Input data of the cam mechanism, variant {number}").format(number=v.number),
            [t("Quantity"), t("Symbol, unit"), t("Value")], rows,
            align=["left", "center", "center"], widths=[2.4, 1.3, 1.5])
    sense = t("counter-clockwise") if v.ccw else t("clockwise")
    c.p(t("The cam turns {sense} (the sign of $n_\"к\"$). Its working angle {{cite:book:formula (1.3)}} and the near-dwell angle are").format(sense=sense))
    c.formula(c.calc('φ_"р" = φ_"у" + φ_"дс" + φ_"в"', "{0} + {1} + {2}",
                     [V(v.phi_rise_deg, exact=True), V(v.phi_far_dwell_deg, exact=True), V(v.phi_return_deg, exact=True)],
                     V(v.phi_working_deg, exact=True, deg=True)),
              where=['φ_"р"', 'φ_"у"', 'φ_"дс"', 'φ_"в"'])
    c.formula(c.calc('φ_"бс" = 360 degree - φ_"р"', "{0} - {1}", [V(360, exact=True, deg=True),
                                                                  V(v.phi_working_deg, exact=True, deg=True)],
                     V(v.phi_near_dwell_deg, exact=True, deg=True)), where=['φ_"бс"'])
    m = r.motion
    c.p(t("The angular speed of the cam {cite:book:formula (1.5)} and the time of one turn:"))
    c.formula(c.calc("ω_k = (π |n_\"к\"|)/30", "(π dot {0})/30", [V(abs(v.n_cam_rpm), exact=True)],
                     V(m.omega, decimals=2), t("rad/s")), label="omega_k", where=["ω_k", "n_\"к\""])
    c.formula(c.calc("T = 60/(|n_\"к\"|)", "60/{0}", [V(abs(v.n_cam_rpm), exact=True)],
                     V(m.period_s, sig=4), t("s")), where=["T"])


# --------------------------------------------------------------------------------------------------
def _motion(c: Ctx, r) -> None:
    v, m = r.variant, r.motion
    t, n = c.t, c.n
    rocker = v.is_rocker
    c.doc.add(_heading(c, 2, t("Motion law of the follower")))
    impacts = (t("the acceleration jumps at the ends of the phases, which gives soft impacts")
               if law_impacts(v.law) == "soft" else
               t("velocity and acceleration change without jumps, so there are no impacts"))
    c.p(t("The follower moves by the {law} law (Figure 1.9 {{cite:book}}), the same on the rise and on the return; {impacts}. With the share $t$ of the phase angle turned, the displacement as a share of the stroke is").format(law=law_words(v.law, c.lang), impacts=impacts))
    for j, line in enumerate(_LAW_F[v.law]):
        c.formula(line.replace('"  for "', '"  ' + t("for") + ' "'),
                  where=["t", "f(t)"] if j == len(_LAW_F[v.law]) - 1 else ())
    if rocker:  # the rocker's angle, its angular velocity and acceleration (§1.2)
        c.p(t("The rocker's angle on the rise is $γ = γ_max f(φ/φ_\"у\")$, on the return $γ = γ_max (1 - f((φ - φ_\"у\" - φ_\"дс\")/φ_\"в\"))$. The cam turns at a constant speed, so $ω = ω_k (d γ)/(d φ)$ and $ε = ω_k^2 (d^2 γ)/(d φ^2)$; the largest values on the rise are"))
    else:
        c.p(t("The follower's displacement on the rise is $s = S_max f(φ/φ_\"у\")$, on the return $s = S_max (1 - f((φ - φ_\"у\" - φ_\"дс\")/φ_\"в\"))$. The cam turns at a constant speed, so $V = ω_k (d s)/(d φ)$ and $a = ω_k^2 (d^2 s)/(d φ^2)$; the largest values on the rise are"))
    f1, f2, _ = law_max(v.law)
    mx = m.maxima
    h_num = math.radians(v.stroke) if rocker else v.stroke
    phr = math.radians(v.phi_rise_deg)
    vs, as_ = ("ω", "ε") if rocker else ("V", "a")
    vu = t("rad/s") if rocker else t("m/s")
    au = t("rad/s²") if rocker else t("m/s²")
    a_rise = max(abs(mx.a_rise_max), abs(mx.a_rise_min))
    a_ret = max(abs(mx.a_return_max), abs(mx.a_return_min))
    c.formula(c.calc(f'{vs}_("у" max) = (f\'_max h ω_k)/φ_"у"', "({0} dot {1} dot {2})/{3}",
                     [V(f1, sig=4, exact=f1 == round(f1)), V(h_num, sig=4), V(m.omega, decimals=2), V(phr, sig=4)],
                     V(mx.v_rise_max, sig=4), vu),
              where=[f'{vs}_("у" max)', "f'_max", ("h", t("the stroke, m") if not rocker else
                                                    t("the swing of the rocker, rad"))])
    c.formula(c.calc(f'{as_}_("у" max) = (f\'\'_max h ω_k^2)/φ_"у"^2', "({0} dot {1} dot {2}^2)/{3}^2",
                     [V(f2, sig=4, exact=f2 == round(f2)), V(h_num, sig=4), V(m.omega, decimals=2), V(phr, sig=4)],
                     V(a_rise, sig=4), au),
              where=[f'{as_}_("у" max)', "f''_max"])
    c.p(t("The largest accelerations of the return and of the rise are in the ratio {cite:book:formula (1.7)}"))
    c.formula(c.calc(f'abs({as_}_("в" max)/{as_}_("у" max))',
                     '{0}/{1} = (φ_"у"/φ_"в")^2 = ({2}/{3})^2',
                     [V(a_ret, sig=4), V(a_rise, sig=4), V(v.phi_rise_deg, exact=True), V(v.phi_return_deg, exact=True)],
                     V(mx.accel_ratio_book, sig=4)), where=[f'{as_}_("в" max)'])
    if rocker:
        lb = v.l_bc_m
        c.p(t("The roller centre B moves along an arc of radius $l_(B C)$; its largest displacement and velocity {cite:book:formula (1.6)} are"))
        c.formula(c.calc("S_(B max) = γ_max l_(B C)", "{0} dot {1}", [V(h_num, sig=4), V(lb, exact=True)],
                         V(h_num * lb, sig=4), t("m")),
                  c.calc("V_(B max) = ω_max l_(B C)", "{0} dot {1}", [V(mx.v_rise_max, sig=4), V(lb, exact=True)],
                         V(mx.v_rise_max * lb, sig=4), t("m/s")),
                  where=["S_(B max)", "V_(B max)", "l_(B C)"])
    step = (n(m.table_step_rise_deg) + "°" if m.table_step_rise_deg == m.table_step_return_deg else
            t("{table_step_rise_deg}° on the rise and {table_step_return_deg}° on the return").format(table_step_rise_deg=n(m.table_step_rise_deg), table_step_return_deg=n(m.table_step_return_deg)))
    halved = ""
    if m.table_step_rise_deg < r.step_deg or m.table_step_return_deg < r.step_deg:
        halved = t(" (the step of {step_deg}° is halved on a phase shorter than eight steps, §1.2 {{cite:book}})").format(step_deg=n(r.step_deg))
    c.p(t("The values at the positions of the cam, every {step}{halved}, are given in Table {{tab:cam_motion}}; the column $B D$ holds the segments $B_i D_i = V_(B i)/ω_k$ of the sizing construction {{cite:book:formula (1.20)}}.").format(step=step, halved=halved)
        + c.if_fig("cam_motion", t(" The diagrams are shown in Figure {fig:cam_motion}.")))
    _motion_table(c, r)
    c.fig("cam_motion", t("Diagrams of the displacement, velocity and acceleration of the follower"))


def _motion_table(c: Ctx, r) -> None:
    v, m = r.variant, r.motion
    t, n = c.t, c.n
    rocker = v.is_rocker
    mm, ms, rad_s, rad_s2, m_s, m_s2 = t("mm"), t("ms"), t("rad/s"), t("rad/s²"), t("m/s"), t("m/s²")
    if rocker:
        header = ["№", "$φ$, °", f"$t$, {ms}", "$γ$, °", f"$ω$, {rad_s}", f"$ε$, {rad_s2}", f"$S_B$, {mm}",
                  f"$V_B$, {m_s}", f"$a_B$, {m_s2}", f"$B D$, {mm}"]
    else:
        header = ["№", "$φ$, °", f"$t$, {ms}", f"$S$, {mm}", f"$V$, {m_s}", f"$a$, {m_s2}", f"$B D$, {mm}",
                  t("Phase")]
    rows = []
    for row in m.table:
        bd = abs(row.v_b_m_s if rocker else row.v) / m.omega * 1000
        if rocker:
            rows.append([str(row.index), n(row.phi_deg), n(row.t_s * 1000, decimals=2),
                         n(math.degrees(row.s), decimals=3), n(row.v, decimals=3), n(row.a, decimals=1),
                         n(row.s_b_m * 1000, decimals=2), n(row.v_b_m_s, decimals=3), n(row.a_b_m_s2, decimals=1),
                         n(bd, decimals=2)])
        else:
            rows.append([str(row.index), n(row.phi_deg), n(row.t_s * 1000, decimals=2), n(row.s * 1000, decimals=3),
                         n(row.v, decimals=3), n(row.a, decimals=1), n(bd, decimals=2), t(_PHASE[row.phase])])
    align = ["center"] + ["right"] * (len(header) - 1 - (0 if rocker else 1)) + ([] if rocker else ["left"])
    widths = [0.55, 0.7, 0.9, 0.9, 1.0, 1.0, 1.0, 1.0, 1.0, 0.9] if rocker else [0.5, 0.65, 0.85, 1.0, 0.9, 1.0, 0.9, 1.55]
    c.table("cam_motion", t("Displacement, velocity and acceleration of the follower in the positions of the cam"), header, rows, align=align,
            widths=widths)


# --------------------------------------------------------------------------------------------------
def _scales(c: Ctx, r) -> None:
    v, m = r.variant, r.motion
    s = m.scales
    t = c.t
    q = c.q
    rocker = v.is_rocker
    c.doc.add(_heading(c, 2, t("Scales of the diagrams")))
    c.p(t("On the sheet the working angle is drawn as a segment $b = {b_mm}$ mm and the largest displacement as an ordinate $Y_(S max) = {y_s_max_mm}$ mm; the integration bases are $H_V = {h_v_mm}$ mm and $H_a = {h_a_mm}$ mm, the largest round bases that keep the ordinates of the velocity and acceleration diagrams within 60 mm. The scales {{cite:book:formulas (1.9)–(1.18)}}:").format(b_mm=q(s.b_mm), y_s_max_mm=q(s.y_s_max_mm), h_v_mm=q(s.h_v_mm), h_a_mm=q(s.h_a_mm)))
    deg_mm = t("°/mm")
    c.formula(c.calc('k_φ = φ_"р"/b', "{0}/{1}", [V(v.phi_working_deg, exact=True), V(s.b_mm, exact=True)],
                     V(s.k_phi_deg_mm, sig=4), deg_mm), where=["k_φ", "b"])
    c.formula(c.calc('k_t = φ_"р"/(6 |n_"к"| b)', "{0}/(6 dot {1} dot {2})",
                     [V(v.phi_working_deg, exact=True), V(abs(v.n_cam_rpm), exact=True), V(s.b_mm, exact=True)],
                     V(s.k_t_s_mm, sig=4), t("s/mm")), where=["k_t"])
    if rocker:
        c.formula(c.calc('k_(γ "°") = γ_max/Y_(γ max)', "{0}/{1}", [V(v.stroke, exact=True), V(s.y_s_max_mm, exact=True)],
                         V(s.k_gamma_deg_mm, sig=4), deg_mm), where=['k_(γ "°")', ("Y_(γ max)", c.glossary_text("Y_(γ max)"))])
        c.formula(c.calc('k_γ = k_(γ "°") π/180', "{0} dot π/180", [V(s.k_gamma_deg_mm, sig=4)],
                         V(s.k_s, sig=4), t("rad/mm")), where=["k_γ"])
        c.formula(c.calc("k_ω = k_γ/(k_t H_V)", "{0}/({1} dot {2})", [V(s.k_s, sig=4), V(s.k_t_s_mm, sig=4), V(s.h_v_mm, exact=True)],
                         V(s.k_v, sig=4), t("(rad/s)/mm")), where=["k_ω", "H_V"])
        c.formula(c.calc("k_ε = k_ω/(k_t H_a)", "{0}/({1} dot {2})", [V(s.k_v, sig=4), V(s.k_t_s_mm, sig=4), V(s.h_a_mm, exact=True)],
                         V(s.k_a, sig=4), t("(rad/s²)/mm")), where=["k_ε", "H_a"])
        c.p(t("The scales of the roller centre's displacement, velocity and acceleration {cite:book:formula (1.18)}:"))
        lb = v.l_bc_m
        c.formula(c.calc("k_S = k_γ l_(B C)", "{0} dot {1}", [V(s.k_s, sig=4), V(lb, exact=True)], V(s.k_s_b, sig=4),
                         t("m/mm")),
                  c.calc("k_V = k_ω l_(B C)", "{0} dot {1}", [V(s.k_v, sig=4), V(lb, exact=True)], V(s.k_v_b, sig=4),
                         t("(m/s)/mm")), where=["k_S", "k_V"])
        c.formula(c.calc("k_a = k_ε l_(B C)", "{0} dot {1}", [V(s.k_a, sig=4), V(lb, exact=True)], V(s.k_a_b, sig=4),
                         t("(m/s²)/mm")), where=["k_a"])
    else:
        c.formula(c.calc("k_S = S_max/Y_(S max)", "{0}/{1}", [V(v.stroke, exact=True), V(s.y_s_max_mm, exact=True)],
                         V(s.k_s, sig=4), t("m/mm")), where=["k_S", "S_max", "Y_(S max)"])
        c.formula(c.calc("k_V = k_S/(k_t H_V)", "{0}/({1} dot {2})", [V(s.k_s, sig=4), V(s.k_t_s_mm, sig=4), V(s.h_v_mm, exact=True)],
                         V(s.k_v, sig=4), t("(m/s)/mm")), where=["k_V", "H_V"])
        c.formula(c.calc("k_a = k_V/(k_t H_a)", "{0}/({1} dot {2})", [V(s.k_v, sig=4), V(s.k_t_s_mm, sig=4), V(s.h_a_mm, exact=True)],
                         V(s.k_a, sig=4), t("(m/s²)/mm")), where=["k_a", "H_a"])
    c.p(t("The largest ordinate of the acceleration diagram on the return follows from that on the rise {cite:book:formula (1.8)}:"))
    c.formula(c.calc('Y_(a "в" max) = Y_(a "у" max) (φ_"у"/φ_"в")^2', "{0} dot ({1}/{2})^2",
                     [V(s.y_a_rise_max_mm, sig=4), V(v.phi_rise_deg, exact=True), V(v.phi_return_deg, exact=True)],
                     V(s.y_a_return_max_mm, sig=4), t("mm")), where=['Y_(a "в" max)', 'Y_(a "у" max)'])
    if c.has("cam_motion"):  # the note's figures are drawn for the page, not at the sheet's scales
        c.p(t("These are the scales of sheet 3. The figures of this note are drawn for its page, each at its own "
              "scales μ, stated on the figure."))


# --------------------------------------------------------------------------------------------------
def _sizing(c: Ctx, r) -> None:
    v, z = r.variant, r.sizing
    t, n = c.t, c.n
    mm = t("mm")
    rocker = v.is_rocker
    c.doc.add(_heading(c, 2, t("Main dimensions of the mechanism")))
    c.p(t("The main dimensions follow from the condition that limits the pressure angle {cite:book:formula (1.19)}"))
    c.formula('ν_i <= ν_max < ν_"кр"', where=["ν_i", "ν_max", 'ν_"кр"'])
    closure = (t("The mechanism has force closure: on the return the spring presses the roller to the cam and the cam does not drive the follower, so the condition is imposed on the rise only.")
               if z.closure == "force" else
               t("The mechanism has form closure (a groove): the cam drives the follower both ways, so the condition holds on the rise and on the return."))
    c.p(t("By the theorem on the position of the cam centre (§1.3 {{cite:book}}), in every position of the follower the segment $B_i D_i = V_(B i)/ω_k$ {{cite:book:formula (1.20)}} is laid off from the roller centre along its velocity turned by 90° in the sense of $ω_k$; the cam centre must lie inside the angle $2 ν_max$ with the vertex $D_i$ whose bisector is opposite to the rise. {closure} The zone common to all positions (every 0,2° of the cam angle) is the zone of admissible centres; the base radius is the distance from the centre to the initial position $B_0$ of the roller centre.").format(closure=closure))
    if rocker:
        _swing(c, r)
    own = r.own
    geometry_given = r.choice is not None and any(x is not None for x in (r.choice.r0_mm, r.choice.offset_mm, r.choice.l_oc_mm))
    student = r.source == "student" and geometry_given and own is not None
    r0 = z.r0_m * 1000
    book_r0 = z.book_r0_m * 1000
    if student:
        ch = r.choice
        given = []
        if ch.r0_mm is not None:
            given.append("$r_0$")
        if ch.offset_mm is not None:
            given.append("$e$")
        if ch.l_oc_mm is not None:
            given.append("$l_(O C)$")
        own_geo = (t(", $l_(O C) = {v}$ mm").format(v=c.q(own.l_oc_m * 1000, decimals=2))
                   if rocker else t(", $e = {v}$ mm").format(v=c.q(own.e_m * 1000, decimals=2)))
        given_text = reduce(lambda a, b: t("{a} and {b}").format(a=a, b=b), given)
        c.p(t("The designer sets {given}; the other dimensions follow from them. The point of the zone nearest to $B_0$ "
              "would give $r_0 = {r0}$ mm{own_geo}.").format(given=given_text, r0=c.q(own.r0_m * 1000, decimals=2),
                                                           own_geo=own_geo))
        c.doc.claim(kind="cam_student", r0_mm=r0, own_r0_mm=own.r0_m * 1000)
    elif r.pivot_move == "centre":
        r0_min = (z.r0_min_m or z.r0_m) * 1000
        c.p(t("The point of the zone nearest to $B_0$ gives $r_0 = {r0_min}$ mm, but there the cam body reaches the rocker's pivot C; the centre is moved along the zone to the nearest point at which the cam clears the pivot, $r_0 = {r0}$ mm.").format(r0_min=c.q(r0_min, decimals=2), r0=c.q(r0, decimals=2)))
        c.doc.claim(kind="cam_centre_moved", r0_mm=r0, r0_min_mm=r0_min)
    else:
        nearest = (t("The cam centre is taken at the point of the zone nearest to $B_0$, which gives the smallest cam "
                     "for this swing: $r_0 = {r0}$ mm.") if rocker else
                   t("The cam centre is taken at the point of the zone nearest to $B_0$, which gives the smallest cam: "
                     "$r_0 = {r0}$ mm."))
        c.p(nearest.format(r0=c.q(r0, decimals=2)))
        c.doc.claim(kind="cam_centre_nearest", r0_mm=r0)
    # the book's vertex beside the taken centre
    if not student:
        base = (z.r0_min_m or z.r0_m) * 1000
        diff = (round(book_r0, 2) / round(base, 2) - 1) * 100  # of the printed radii: the reader's check
        if n(book_r0, decimals=2) == n(base, decimals=2):
            cmp = t("The construction of the textbook (the vertex where its two bounding lines meet) gives the same point.")
        elif abs(diff) < 0.1:
            cmp = t("The construction of the textbook (the vertex where its two bounding lines meet) gives $r_0 = {book_r0}$ mm: the two differ by less than 0,1 %, within the step of the construction.").format(book_r0=c.q(book_r0, decimals=2))
        else:
            more = diff > 0
            cmp = (t("The construction of the textbook (the vertex where its two bounding lines meet) gives "
                     "$r_0 = {book_r0}$ mm, {diff} larger") if more else
                   t("The construction of the textbook (the vertex where its two bounding lines meet) gives "
                     "$r_0 = {book_r0}$ mm, {diff} smaller")).format(book_r0=c.q(book_r0, decimals=2), diff=c.pct(abs(diff)))
            book_nu = z.book_nu_rise_max_deg if z.closure == "force" else max(z.book_nu_rise_max_deg, z.book_nu_return_max_deg)
            if book_nu > v.nu_max_deg + 0.05:
                cmp += t(", and there the pressure angle reaches {book_nu}° > $ν_max$: the bounding lines of the textbook turn with the follower and do not bound the zone exactly.").format(book_nu=n(book_nu, decimals=2))
            else:
                cmp += "."
        c.p(cmp)
        c.doc.claim(kind="cam_book_vertex", r0_mm=base, book_r0_mm=book_r0, diff_pct=diff)
    c.p(t("The main dimensions are"))
    if rocker:
        c.formula(f"r_0 = {c.q(r0, decimals=2)} {c.u(mm)}", f"l_(O C) = {c.q(z.l_oc_m * 1000, decimals=2)} {c.u(mm)}",
                  where=["r_0", "l_(O C)"])
    else:
        c.formula(f"r_0 = {c.q(r0, decimals=2)} {c.u(mm)}", f"e = {c.q(z.e_m * 1000, decimals=2)} {c.u(mm)}",
                  where=["r_0", ("e", t("the offset of the follower axis from the cam centre (e > 0: to the right of the centre, the follower above the cam), mm"))])
    ch = r.checks
    rows = [["$r_0$, " + mm, n(r0, decimals=2), n(book_r0, decimals=2)]]
    if rocker:
        rows.append(["$l_(O C)$, " + mm, n(z.l_oc_m * 1000, decimals=2), n(z.book_l_oc_m * 1000, decimals=2)])
    else:
        rows.append(["$e$, " + mm, n(z.e_m * 1000, decimals=2), n(z.book_e_m * 1000, decimals=2)])
    rows.append([t("largest $ν$ on the rise, °"), n(ch.nu_rise_deg, decimals=2),
                 n(z.book_nu_rise_max_deg, decimals=2)])
    rows.append([t("largest $ν$ on the return, °"), n(ch.nu_return_deg, decimals=2),
                 n(z.book_nu_return_max_deg, decimals=2)])
    taken = t("Taken")
    c.p(t("They are compared with the construction of the textbook in Table {tab:cam_dims}")
        + c.if_fig("cam_zone", t("; the zone is shown in Figure {fig:cam_zone}")) + ".")
    c.table("cam_dims", t("Main dimensions of the cam mechanism"),
            [t("Quantity"), taken, t("Construction of the textbook")], rows,
            align=["left", "center", "center"], widths=[2, 1, 1.3])
    c.fig("cam_zone", t("Zone of admissible positions of the cam centre"))


def _swing(c: Ctx, r) -> None:
    """Which way the rocker turns on the rise, and why (the decision of cam/design.py)."""
    z = r.sizing
    t = c.t
    sense = {"same": t("the same way as the cam"),
             "opposite": t("against the cam")}
    r0 = z.r0_m * 1000
    if r.source == "student" and r.choice.swing is not None:
        c.p(t("On the rise the rocker turns {sense}, as the designer chose.").format(sense=sense[z.swing]))
        return
    pc = r.pivot_conflict
    if pc is not None and r.pivot_move == "swing":
        c.p(t("The rocker may turn on the rise either way. Turning {other_sense} it needs the smaller cam, "
              "$r_0 = {other_r0}$ mm, but then the cam body (radius {body}) reaches the rocker's pivot C "
              "($l_(O C) = {other_l_oc}$ mm). Therefore the rocker is made to turn {sense}: $r_0 = {r0}$ mm, and the "
              "cam clears the pivot.").format(
            other_sense=sense[pc.swing], other_r0=c.q(pc.r0_m * 1000, decimals=2),
            body=c.qty(pc.body_m * 1000, t("mm"), decimals=2), other_l_oc=c.q(pc.l_oc_m * 1000, decimals=2),
            sense=sense[z.swing], r0=c.q(r0, decimals=2)))
        c.doc.claim(kind="cam_swing_pivot", carried_r0_mm=r0, rejected_r0_mm=pc.r0_m * 1000,
                    rejected_l_oc_mm=pc.l_oc_m * 1000, rejected_body_mm=pc.body_m * 1000)
        return
    other = z.r0_other_swing_m
    if other is None:
        return
    o = other * 1000
    if c.n(o, decimals=2) == c.n(r0, decimals=2):
        c.p(t("On the rise the rocker turns {sense}; the other sense needs the same cam ($r_0 = {o}$ mm): the mechanism is symmetric.").format(sense=sense[z.swing], o=c.q(o, decimals=2)))
    else:
        c.p(t("On the rise the rocker turns {sense}: the other sense would need a larger cam, $r_0 = {o}$ mm ({v} more).").format(sense=sense[z.swing], o=c.q(o, decimals=2), v=c.pct((round(o, 2) / round(r0, 2) - 1) * 100)))
    c.doc.claim(kind="cam_swing_smaller", carried_r0_mm=r0, other_r0_mm=o)


# --------------------------------------------------------------------------------------------------
def _profile(c: Ctx, r) -> None:
    v, z, p, d = r.variant, r.sizing, r.profile, r.drawing
    t, n = c.t, c.n
    mm = t("mm")
    c.doc.add(_heading(c, 2, c.tc("note, heading", "Profile of the cam")))
    c.p(t("The profile is built by inversion (§1.4 {cite:book}): the cam is held still and the frame with the follower is turned about the cam centre against the cam's rotation; the roller centre then traces the pitch (theoretical) profile, and the working profile is the envelope of the roller's circles."))
    w, h = d.extent_mm
    c.p(t("The profile is drawn at the scale {scale} ($k_(S k) = {k_sk}$ m/mm, Table 1.1 {{cite:book}}): the largest "
          "scale of the standard series at which the cam with its roller ({width} × {height}) fits the field of "
          "{field} × {field} of the sheet. The sizing construction is built in the scale of the displacement "
          "diagram, $k'_S = k_S$ (§1.3.1 {{cite:book}}: its segments are laid off from the diagram's ordinates); "
          "sheet 3 shows it at the standard scale stated in its field. The lengths are carried over to the "
          "drawing of the profile {{cite:book:formulas (1.26), (1.27)}}, the first for the largest displacement, the "
          "second for the base radius $r_0$:").format(
        scale=d.scale, k_sk=c.q(d.k_sk, sig=4), width=c.qty(w, mm, decimals=1), height=c.qty(h, mm, decimals=1),
        field=c.qty(d.field_mm, mm, decimals=0)))
    c.doc.claim(kind="cam_drawing_scale", scale=d.scale, fits=d.fits, width_mm=w, height_mm=h, field_mm=d.field_mm)
    st = d.size("stroke")
    r0s = d.size("r0")
    c.formula(c.calc("y_(S i k) = k_S/k_(S k) y_(S i)", "{0}/{1} dot {2}",
                     [V(d.k_s, sig=4), V(d.k_sk, sig=4), V(st.at_k_s_mm, sig=4)], V(st.drawn_mm, sig=4), mm),
              where=["y_(S i k)", "y_(S i)", "k_(S k)"])
    c.formula(c.calc("x_(i k) = (k'_S)/k_(S k) x_i", "{0} dot {1}",
                     [V(d.k_s_prime / d.k_sk, sig=4), V(r0s.at_k_s_mm, sig=4)], V(r0s.drawn_mm, sig=4), mm),
              where=["x_(i k)", "k'_S", "x_i"])
    c.p(t("The profile angles differ from the phase angles when the follower axis is offset and for a rocker; they are measured on the profile and checked {cite:book:formulas (1.1), (1.2), (1.4)}:"))
    c.formula(c.calc('ψ_"у" + ψ_"дс" + ψ_"в" + ψ_"бс"', "{0} + {1} + {2} + {3}",
                     [V(p.psi_rise_deg, decimals=2, deg=True), V(abs(p.psi_far_deg), decimals=2, deg=True),
                      V(p.psi_return_deg, decimals=2, deg=True), V(p.psi_near_deg, decimals=2, deg=True)],
                     V(360, exact=True, deg=True)))
    c.formula(c.calc('ψ_"р" = ψ_"у" + ψ_"дс" + ψ_"в"', "{0} + {1} + {2}",
                     [V(p.psi_rise_deg, decimals=2, deg=True), V(abs(p.psi_far_deg), decimals=2, deg=True),
                      V(p.psi_return_deg, decimals=2, deg=True)], V(p.psi_working_deg, decimals=2, deg=True))
              + ' = φ_"р"', where=['ψ_"р"'])  # φ_р is the task's, given above: no second value of it
    _roller(c, r)
    if c.has("cam_profile"):
        c.p(t("The profile with the pitch curve, the base circle and the positions of the follower in the inverted motion is shown in Figure {fig:cam_profile}."))
    c.fig("cam_profile", t("Profile of the cam"))


def _roller(c: Ctx, r) -> None:
    z, p = r.sizing, r.profile
    t = c.t
    mm = t("mm")
    rho = p.roller_max_m * 1000
    book = p.roller_book_m * 1000
    roller = p.roller_m * 1000
    r0 = z.r0_m * 1000
    concave = z.closure == "form" and p.rho_min_concave_m is not None and p.rho_min_concave_m * 1000 <= rho + 1e-9
    where_rho = (t("of the concave side of the groove") if concave else
                 t("of the convex part of the pitch profile"))
    c.p(t("The roller radius by the textbook's rule {cite:book:formula (1.28)}:"))
    c.formula(c.calc('r_"р" = "0,2" r_0', '{0} dot {1}', [V(0.2, exact=True), V(r0, decimals=2)], V(book, decimals=2), mm),
              where=['r_"р"'])
    rule = p.roller_rule
    if rule == "book":
        c.p(t("The roller must be smaller than the smallest radius of curvature {where_rho}, $ρ_min = {rho}$ mm, or the working profile is undercut; $r_\"р\" = {roller} < ρ_min$, so the roller of the textbook is taken and the profile is not undercut.").format(where_rho=where_rho, rho=c.q(rho, decimals=2), roller=c.q(roller, decimals=2)))
    elif rule == "limited":
        limited = (t("The roller must be smaller than the smallest radius of curvature {where_rho}, $ρ_min = {rho}$ mm, or "
                     "the working profile is undercut. The textbook's roller reaches it, so the roller is reduced to "
                     "0,8 $ρ_min$:") if book >= rho else
                   t("The roller must be smaller than the smallest radius of curvature {where_rho}, $ρ_min = {rho}$ mm, or "
                     "the working profile is undercut. The textbook's roller comes within 20 % of it, so the roller is "
                     "reduced to 0,8 $ρ_min$:"))
        c.p(limited.format(where_rho=where_rho, rho=c.q(rho, decimals=2)))
        c.formula(c.calc('r_"р" = "0,8" ρ_min', "{0} dot {1}", [V(0.8, exact=True), V(rho, decimals=2)],
                         V(roller, decimals=2), mm), where=["ρ_min"])
        fix = r.book_roller_fix
        if fix is not None:
            geo = (f"l_(O C) = {c.q(fix.l_oc_m * 1000, decimals=2)}" if r.variant.is_rocker
                   else f"e = {c.q(fix.e_m * 1000, decimals=2)}")
            c.p(t("The textbook's roller could be kept with a larger cam, $r_0 = {v}$ mm, ${geo}$ mm; the smaller roller keeps the smallest cam.").format(v=c.q(fix.r0_m * 1000, decimals=2), geo=geo))
    else:
        ok = roller < rho
        given = (t("The designer takes the roller $r_\"р\" = {roller}$ mm. The smallest radius of curvature {where_rho} is "
                   "$ρ_min = {rho}$ mm: the roller is smaller, the profile is not undercut.") if ok else
                 t("The designer takes the roller $r_\"р\" = {roller}$ mm. The smallest radius of curvature {where_rho} is "
                   "$ρ_min = {rho}$ mm: the roller is not smaller, the working profile is undercut."))
        c.p(given.format(roller=c.q(roller, decimals=2), where_rho=where_rho, rho=c.q(rho, decimals=2)))
    c.doc.claim(kind="cam_roller", rule=rule, roller_mm=roller, book_mm=book, rho_mm=rho)
    c.p(t("Here $r_0$ is the base radius of the pitch profile; the smallest radius of the working profile is $r_0 - r_\"р\" = {v}$ mm; the far-dwell radius of the pitch profile is {v2}.").format(v=c.q(p.working_min_radius_m * 1000, decimals=2), v2=c.qty(p.r_far_m * 1000, mm, decimals=2)))


# --------------------------------------------------------------------------------------------------
def _pressure(c: Ctx, r) -> None:
    v, z, ch = r.variant, r.sizing, r.checks
    t, n = c.t, c.n
    c.doc.add(_heading(c, 2, t("Pressure angle over the cycle")))
    rise_ok = ch.nu_rise_ok
    sign = "≤" if rise_ok else ">"
    rise = t("on the rise the pressure angle reaches {nu_rise_deg}° {sign} $ν_max$ = {nu_max_deg}°").format(nu_rise_deg=n(ch.nu_rise_deg, decimals=2), sign=sign, nu_max_deg=n(v.nu_max_deg))
    if z.closure == "force":
        ret = t("on the return the spring drives the follower and the pressure angle is not limited (it reaches {nu_return_deg}°)").format(nu_return_deg=n(ch.nu_return_deg, decimals=1))
    else:
        sign2 = "≤" if ch.nu_return_ok else ">"
        ret = t("on the return it reaches {nu_return_deg}° {sign2} $ν_max$").format(nu_return_deg=n(ch.nu_return_deg, decimals=2), sign2=sign2)
    verdict = (t("The condition (1.19) holds.")
               if rise_ok and ch.nu_return_ok else
               t("The condition is not met."))
    fig = c.if_fig("cam_pressure_angle", t(" (Figure {fig:cam_pressure_angle})"))
    c.p(t("With the centre taken, {rise}; {ret}{fig}. {verdict}").format(rise=rise, ret=ret, fig=fig, verdict=verdict))
    c.doc.claim(kind="cam_pressure", nu_rise=ch.nu_rise_deg, nu_return=ch.nu_return_deg, nu_max=v.nu_max_deg,
                limited_return=z.closure == "form", ok=rise_ok and ch.nu_return_ok)
    c.fig("cam_pressure_angle", t("Pressure angle against the cam angle"))
