"""The answer keys of `tmm check`: what a student may report, where it is in the project document,
how it is compared, where the book explains it, and the names students write it under.

A student writes ``r0_mm``, ``r_0``, ``r0`` or ``R0`` — all are the key ``r0_mm``; the book's symbols
(``φ_у``, ``z_1``, ``u_1H``, ``ν_у``, ``ψ_дс``, Cyrillic or Latin look-alikes alike) name keys too.
:func:`resolve_key` finds the key of a written name, :func:`suggest_key` the nearest key of a typo.
"""

from __future__ import annotations

import difflib
import unicodedata

from ..i18n import N_
from ..records import record


@record
class AnswerKey:
    key: str
    path: tuple  # path into the project JSON document
    kind: str  # "int" exact, "float" within tolerance, "input" the variant's data (exact)
    meaning: str  # English msgid (shown with tr)
    scale_path: tuple | None = None  # tolerance relative to this value instead (e.g. e relative to r0)
    book_path: tuple | None = None  # the book's graphical answer, also accepted (status "pass (book)")
    aliases: tuple = ()  # other names students write (the book's symbols)
    unit: str = ""  # "mm", "deg", "rpm", "%", "m", "" (a count or a ratio)


def _k(key, path, kind, meaning, scale_path=None, book_path=None, aliases=(), unit=""):
    return AnswerKey(key, tuple(path), kind, meaning, None if scale_path is None else tuple(scale_path),
                     None if book_path is None else tuple(book_path), tuple(aliases), unit)


ANSWER_KEYS: tuple[AnswerKey, ...] = (
    _k("n_motor_rpm", ("gears", "motor", "n_rpm"), "int", N_("motor speed n_d [rpm]"),
       aliases=("n_д", "n_d", "n_дв", "n_motor"), unit="rpm"),
    _k("i_spur", ("gears", "i_spur"), "float", N_("spur-pair ratio i_d"),
       aliases=("i_д", "i_d", "u_д", "u_d", "i_пп")),
    _k("i_planetary", ("gears", "i_planetary"), "float", N_("required planetary ratio i_pl = n_d/n_cr"), aliases=("i_пл", "i_pl", "u_пл", "u_pl")),
    _k("i_kh", ("gears", "planetary", "ratio"), "float", N_("ratio of the tooth set i_kH = 1 + z_c·z_n/(z_k·z_c′) (2.1)"),
       aliases=("u_1H", "i_1H", "i_kH", "u_kH", "i_кН", "u_кН", "i_kH^n", "i_set")),
    _k("ratio_error_pct", ("gears", "planetary", "ratio_error_pct"), "float",
       N_("ratio error of the tooth set [%] (tolerance in percentage points)"),
       aliases=("δi", "Δi", "delta_i", "ratio_error", "err_i", "погрешность_i"), unit="%"),
    _k("z_sun", ("gears", "planetary", "stages", 0, "z_sun"), "int", N_("sun teeth z_k (stage 1)"),
       aliases=("z_k", "z_к", "zk")),
    _k("z_planet", ("gears", "planetary", "stages", 0, "z_planet"), "int", N_("planet teeth z_c (stage 1)"),
       aliases=("z_c", "z_с", "zc")),
    _k("z_planet2", ("gears", "planetary", "stages", 0, "z_planet2"), "int", N_("second planet row z_c′ (scheme 2)"), aliases=("z_c′", "z_c'", "z_с′", "z_с'", "z_c2", "zc2")),
    _k("z_ring", ("gears", "planetary", "stages", 0, "z_ring"), "int", N_("ring teeth z_n (stage 1)"),
       aliases=("z_n", "z_н", "zn")),
    _k("planets", ("gears", "planetary", "stages", 0, "planets"), "int", N_("number of planets k (stage 1)"),
       aliases=("k", "k_наиб", "n_сат", "число_сателлитов")),
    _k("z_sun_2", ("gears", "planetary", "stages", 1, "z_sun"), "int", N_("sun teeth, stage 2"),
       aliases=("z_k2", "z_к2", "z_k_2")),
    _k("z_planet_2", ("gears", "planetary", "stages", 1, "z_planet"), "int", N_("planet teeth, stage 2"),
       aliases=("z_c_2", "z_с2")),
    _k("z_ring_2", ("gears", "planetary", "stages", 1, "z_ring"), "int", N_("ring teeth, stage 2"),
       aliases=("z_n2", "z_н2", "z_n_2")),
    _k("planets_2", ("gears", "planetary", "stages", 1, "planets"), "int", N_("planets, stage 2"),
       aliases=("k2", "k_2")),
    _k("z1", ("gears", "spur", "z1"), "int", N_("spur pinion teeth z1"), aliases=("z_1",)),
    _k("z2", ("gears", "spur", "z2"), "int", N_("spur wheel teeth z2"), aliases=("z_2",)),
    _k("a_mm", ("gears", "spur", "a_mm"), "float", N_("spur centre distance a [mm]"),
       aliases=("a",), unit="mm"),
    _k("eps_alpha", ("gears", "spur", "eps_alpha"), "float", N_("transverse contact ratio ε_α"),
       aliases=("ε_α", "ε_a", "eps_a", "epsilon_alpha", "e_alpha")),
    _k("x1", ("gears", "spur", "x1"), "float", N_("spur shift x1 (the pair is recomputed with the given x1, x2; 0: the book's)"), aliases=("x_1",)),
    _k("x2", ("gears", "spur", "x2"), "float", N_("spur shift x2 (the pair is recomputed with the given x1, x2; 0: the book's)"), aliases=("x_2",)),
    _k("a_w_mm", ("gears", "spur", "a_w_mm"), "float", N_("spur working centre distance a_w [mm]"),
       aliases=("a_w", "aw"), unit="mm"),
    _k("alpha_w_deg", ("gears", "spur", "alpha_w_deg"), "float", N_("spur working pressure angle α_w [deg]"),
       aliases=("α_w", "alpha_w"), unit="deg"),
    _k("r0_mm", ("cam", "r0_mm"), "float", N_("cam base radius r0 [mm] (the book's vertex is accepted too)"), book_path=("cam", "book_vertex", "r0_mm"),
       aliases=("r_0", "r0", "r_min", "rmin"), unit="mm"),
    _k("e_mm", ("cam", "e_mm"), "float", N_("offset e [mm] (tolerance relative to r0; the book's vertex accepted)"), ("cam", "r0_mm"), ("cam", "book_vertex", "e_mm"),
       aliases=("e", "e_c", "e_т"), unit="mm"),
    _k("l_oc_mm", ("cam", "l_oc_mm"), "float", N_("centre distance l_OC [mm] (the book's vertex accepted)"), book_path=("cam", "book_vertex", "l_oc_mm"),
       aliases=("l_OC", "l_oc", "l_ОС", "loc"), unit="mm"),
    _k("roller_mm", ("cam", "roller_mm"), "float", N_("roller radius r_p [mm] (the book's 0.2·r0 accepted, marked)"), aliases=("r_р", "r_p", "rp", "r_ролика", "roller", "r_roller"),
       unit="mm"),
    _k("nu_rise_deg", ("cam", "pressure_angle_max_deg", "rise"), "float", N_("max pressure angle on rise [deg]"), aliases=("ν_у", "nu_у", "ν_max_у", "nu_rise", "ν_rise"), unit="deg"),
    _k("nu_return_deg", ("cam", "pressure_angle_max_deg", "return"), "float", N_("max pressure angle on return [deg]"), aliases=("ν_в", "nu_в", "ν_max_в", "nu_return", "ν_return"), unit="deg"),
    _k("psi_rise_deg", ("cam", "psi_deg", "rise"), "float", N_("profile angle ψ_у [deg]"),
       aliases=("ψ_у", "psi_у", "psi_y", "ψ_y"), unit="deg"),
    _k("psi_far_dwell_deg", ("cam", "psi_deg", "far_dwell"), "float", N_("profile angle ψ_дс [deg]"),
       aliases=("ψ_дс", "psi_дс", "ψ_ds", "psi_ds"), unit="deg"),
    _k("psi_return_deg", ("cam", "psi_deg", "return"), "float", N_("profile angle ψ_в [deg]"),
       aliases=("ψ_в", "psi_в", "ψ_v", "psi_v"), unit="deg"),
    # the variant's own data (Table 1.2): a student who restates it is checked against the variant
    # (a mismatch means the wrong row of the table); never required
    _k("phi_rise_deg", ("input", "phi_rise_deg"), "input", N_("phase angle of rise φ_у [deg] (Table 1.2)"), aliases=("φ_у", "phi_у", "phi_y", "φ_y"), unit="deg"),
    _k("phi_far_dwell_deg", ("input", "phi_far_dwell_deg"), "input", N_("phase angle of far dwell φ_дс [deg] (Table 1.2)"), aliases=("φ_дс", "phi_дс", "phi_ds"), unit="deg"),
    _k("phi_return_deg", ("input", "phi_return_deg"), "input", N_("phase angle of return φ_в [deg] (Table 1.2)"), aliases=("φ_в", "phi_в", "phi_v"), unit="deg"),
    _k("nu_max_deg", ("input", "nu_max_deg"), "input", N_("allowed pressure angle ν_max [deg] (Table 1.2)"), aliases=("ν_max", "nu_max", "ν_доп"), unit="deg"),
    _k("n_cam_rpm", ("input", "n_cam_rpm"), "input", N_("cam speed n_k [rpm] (Table 1.2)"),
       aliases=("n_к", "n_k", "n_кул"), unit="rpm"),
)
KEYS_BY_NAME = {k.key: k for k in ANSWER_KEYS}

# The keys a student must give for each sheet (those the variant computes: z_planet2 only for
# scheme 2, the stage-2 keys only for a two-stage reducer, e_mm for a translating follower,
# l_oc_mm for a rocker). A missing required key fails the check.
REQUIRED = {
    "4": ("n_motor_rpm", "z_sun", "z_planet", "z_planet2", "z_ring", "planets",
          "z_sun_2", "z_planet_2", "z_ring_2", "planets_2", "z1", "z2", "eps_alpha"),
    "3": ("r0_mm", "e_mm", "l_oc_mm"),
}
SHEETS = ("3", "4")

_SUFFIXES = ("_mm", "_deg", "_rpm", "_pct", "_m")
_DROP = str.maketrans({**{c: None for c in " _-{}^()\\`."}, "′": "2", "'": "2", "’": "2"})
# Cyrillic letters that look like Latin ones, read as the Latin letter (r_р with a Cyrillic р is r_p)
_LOOKALIKE = str.maketrans("асеорхукнтвмАСЕОРХУКНТВМ", "aceopxykhtbmACEOPXYKHTBM")


def normal_name(name: str) -> str:
    """A written key reduced for matching: NFKC, case folded, separators dropped, a prime read as 2.

    >>> normal_name("r_0"), normal_name("  R0 "), normal_name("z_c′"), normal_name("u_1H")
    ('r0', 'r0', 'zc2', 'u1h')
    """
    return unicodedata.normalize("NFKC", str(name)).casefold().translate(_DROP)


def _names(k: AnswerKey) -> list[str]:
    out = [k.key, *k.aliases]
    for suffix in _SUFFIXES:
        if k.key.endswith(suffix):
            out.append(k.key[: -len(suffix)])
    return out


def _index() -> tuple[dict[str, str], dict[str, str]]:
    """(normal name -> key, normal name with look-alikes read as Latin -> key). A name two keys
    share (none today) is left out rather than guessed."""
    exact: dict[str, str] = {}
    loose: dict[str, str] = {}
    clash: set[str] = set()
    for k in ANSWER_KEYS:
        for n in _names(k):
            for table, name in ((exact, normal_name(n)), (loose, normal_name(n).translate(_LOOKALIKE))):
                if table.get(name, k.key) != k.key:
                    clash.add(name)
                table[name] = k.key
    for name in clash:
        exact.pop(name, None)
        loose.pop(name, None)
    return exact, loose


_EXACT, _LOOSE = _index()


def resolve_key(written: str) -> str | None:
    """The answer key a student's written name stands for, or None.

    >>> [resolve_key(n) for n in ("r0_mm", "r_0", "z_1", "u_1H", "φ_у", "ν_у", "l_OC", "r_р", "zz")]
    ['r0_mm', 'r0_mm', 'z1', 'i_kh', 'phi_rise_deg', 'nu_rise_deg', 'l_oc_mm', 'roller_mm', None]
    """
    if written in KEYS_BY_NAME:
        return written
    n = normal_name(written)
    return _EXACT.get(n) or _LOOSE.get(n.translate(_LOOKALIKE))


def suggest_key(written: str) -> str | None:
    """The key a typo most likely meant (difflib over every key and its names), or None.

    >>> suggest_key("r0_nm"), suggest_key("z_sum"), suggest_key("eps_alfa"), suggest_key("banana")
    ('r0_mm', 'z_sun', 'eps_alpha', None)
    """
    n = normal_name(written).translate(_LOOKALIKE)
    if not n:
        return None
    hit = difflib.get_close_matches(n, list(_LOOSE), n=1, cutoff=0.75)
    return _LOOSE[hit[0]] if hit else None
