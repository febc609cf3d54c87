"""Every size and number a user controls has a limit, here, in one place (docs/limits.md).

A value outside its limit is refused before any work with one line naming the limit, so no input
can make `tmm` run for minutes, eat the memory, or print an absurd machine (a spur gear with 10¹³
teeth). The numbers are generous for the course project: Table 1.2 and the book's examples lie
well inside every range.
"""

from __future__ import annotations

import math

from .errors import TmmError

# numbers given on the command line or in a roster --------------------------------------------
CRANK_RPM = (1.0, 3000.0)  # n_кр [rpm]; the book's 220, rosters 60…140
TORQUE_NM = (0.0, 1.0e5)  # mean reduced moment M [N·m] from sheet 2
TOLERANCE_PCT = (0.01, 20.0)  # allowed planetary ratio error [%]; the book's 5
STEP_DEG = (0.5, 30.0)  # cam table step [deg]; the book's 10
PLANETS = (1, 12)  # forced number of planets
RTOL_PCT = (0.01, 50.0)  # tmm check tolerance [%]; default 3
JOBS = (1, 64)  # batch worker processes

# tmm linkage (sheets 1-2) ------------------------------------------------------------------
LINKAGE_LENGTH_M = (1e-4, 100.0)  # r1, h, r2, r3 [m] (|c|, |b| up to the same 100 m)
LINKAGE_RPM = (0.1, 10000.0)  # --rpm [rpm]
LINKAGE_OMEGA = (0.01, 1100.0)  # --omega [rad/s] (10000 rpm is 1047 rad/s)
LINKAGE_EPS = (-1.0e6, 1.0e6)  # --eps-crank [rad/s²]

# tmm planetary (seed 000) and the spur pair's shifts ----------------------------------------
PLANETARY_Z = (6, 400)  # --z-min / --z-max: teeth of any wheel of the AA-bar mechanism
PLANETARY_FAMILY = (1, 20)  # --family K
MODULE_MM = (0.1, 100.0)  # --module [mm]
SHIFT_X = (-5.0, 5.0)  # a profile shift coefficient (--shift, --x1, --x2); the results are checked too

# Table 1.2 rows (--variants-file) -----------------------------------------------------------
N_CAM_RPM = (300.0, 5000.0)  # |n_k| [rpm]; Table 1.2 has 700…2500 (below 300 the spur pair outgrows 160 teeth)
S_MAX_M = (0.001, 1.0)  # stroke S_max [m]; Table 1.2 has 0.02…0.25
L_BC_M = (0.005, 2.0)  # rocker length l_BC [m]; Table 1.2 has 0.05…0.3

# reducer accuracy (tmm carrier, tmm chain; docs/accuracy.md) -----------------------------------
CARRIER_RADIUS_MM = (1.0, 5000.0)  # --radius of the bore circle [mm]
CARRIER_TOL_UM = (0.01, 10000.0)  # --tol-radial, --tol-tangential [µm]
CARD_BORES = (3, 12)  # bores (planets) of a measurement card
CHAIN_RISK_PCT = (0.001, 50.0)  # --risk [%]; the default 0.27 gives t = 3

# files and lists ------------------------------------------------------------------------------
VARIANTS_FILE_BYTES = 1 << 20  # 1 MiB
VARIANTS_ROWS = 1000  # rows of a --variants-file (Table 1.2 has 68)
ROSTER_BYTES = 1 << 20  # 1 MiB
ROSTER_ROWS = 1000  # students in one roster
ANSWERS_BYTES = 64 << 10  # 64 KiB per answers file
ANSWERS_ROWS = 200  # lines with a key in one answers file
VARIANT_SPEC_CHARS = 1000  # length of a --variants list
VARIANT_SPEC_COUNT = 1000  # variants in one batch
NAME_CHARS = 100  # a student's name as shown (longer is refused in its roster row)
FILE_NAME_CHARS = 64  # a student's name as a file or folder name (cut to this length)
CARD_BYTES = 64 << 10  # 64 KiB: a measurement card (a 12-bore card is under 1 KiB)
CHAIN_BYTES = 256 << 10  # 256 KiB: a dimensional chain file
CHAIN_LINKS = 200  # links of one chain (the article's longest has 11)
SETTINGS_BYTES = 64 << 10  # tmm.toml (title fields)
INPUT_FILE_BYTES = 64 << 10  # tmm linkage --input
NOTE_TEMPLATE_BYTES = 1 << 20  # --note-template

# the note's typesetting ---------------------------------------------------------------------
TYPST_MEMORY_BYTES = 2 << 30  # memory typst may use (RLIMIT_DATA on Linux, RLIMIT_AS on other Unix)
TYPST_SECONDS = 60.0  # wall-clock time of one typst compile (the note, an assignment, a feedback PDF)
NOTE_FOLDER_FILES = 2000  # `tmm note`: regular files of the note's folder given to typst
NOTE_FOLDER_BYTES = 512 << 20  # ... of them copied where hard links are not possible
NOTE_FOLDER_DEPTH = 4  # ... sub-folder levels


def check_range(value, lo, hi, what: str, hint: str = "") -> float:
    """`value` as a finite float within [lo, hi]; TmmError naming `what` and the range otherwise.

    >>> check_range(95, *CRANK_RPM, "--crank-rpm")
    95.0
    >>> check_range(float("nan"), 0, 1, "--rtol")
    Traceback (most recent call last):
    tmm_cli.errors.TmmError: --rtol is nan; give a finite number from 0 to 1
    """
    try:
        x = float(value)
    except (TypeError, ValueError, OverflowError):
        raise TmmError(f"{what} is '{value}', not a number; give a number from {lo:g} to {hi:g}{hint}") from None
    if not math.isfinite(x):
        raise TmmError(f"{what} is {value}; give a finite number from {lo:g} to {hi:g}{hint}")
    if not lo <= x <= hi:
        raise TmmError(f"{what} is {x:g}; give a number from {lo:g} to {hi:g}{hint}")
    return x


def check_int_range(value, lo: int, hi: int, what: str) -> int:
    """`value` as an int within [lo, hi] (no float conversion, so 10²⁰ is refused, not overflowed)."""
    if isinstance(value, bool) or not isinstance(value, int):
        raise TmmError(f"{what} is '{value}'; give a whole number from {lo} to {hi}")
    if not lo <= value <= hi:
        text = str(value) if abs(value) < 10**30 else f"a {len(str(abs(value)))}-digit number"
        raise TmmError(f"{what} is {text}; give a whole number from {lo} to {hi}")
    return value
