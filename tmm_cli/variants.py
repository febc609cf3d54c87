"""Table 1.2 of the textbook (§1.5): load and validate the 68 variants of sheet 3.

The table is a CSV with the units in its column names (``variants/table_1_2.csv``, shipped in the
package as ``tmm_cli.data``). Every check lives here, so a bad row is reported once, naming the
variant, the field and what to do.
"""

from __future__ import annotations

import csv
import math
from pathlib import Path

from .errors import TmmError
from .limits import L_BC_M, N_CAM_RPM, S_MAX_M, VARIANTS_FILE_BYTES, VARIANTS_ROWS
from .records import record

COLUMNS = (
    "variant",
    "scheme",
    "l_bc_m",
    "nu_max_deg",
    "n_cam_rpm",
    "s_max_m",
    "gamma_max_deg",
    "law",
    "phi_rise_deg",
    "phi_far_dwell_deg",
    "phi_return_deg",
)

SCHEME_FOLLOWER = {1: "translating", 2: "translating", 3: "rocker", 4: "rocker"}
SCHEME_CLOSURE = {1: "force", 2: "form", 3: "force", 4: "form"}


@record
class Variant:
    """One row of Table 1.2, validated. Units as in the book: m, deg, rpm."""

    number: int
    scheme: int  # 1..4, see SCHEME_FOLLOWER / SCHEME_CLOSURE
    l_bc_m: float | None  # rocker length l_BC [m] (schemes 3, 4)
    nu_max_deg: float  # maximum allowed pressure angle ν_max [deg]
    n_cam_rpm: float  # n_k [rpm]; < 0 clockwise, > 0 counter-clockwise
    stroke: float  # S_max [m] (schemes 1, 2) or γ_max [deg] (schemes 3, 4)
    law: int  # acceleration law 1..4 (Fig. 1.9)
    phi_rise_deg: float
    phi_far_dwell_deg: float
    phi_return_deg: float

    @property
    def follower(self) -> str:
        """"translating" or "rocker"."""
        return SCHEME_FOLLOWER[self.scheme]

    @property
    def closure(self) -> str:
        """"force" (spring) or "form" (grooved cam)."""
        return SCHEME_CLOSURE[self.scheme]

    @property
    def is_rocker(self) -> bool:
        return self.scheme in (3, 4)

    @property
    def phi_near_dwell_deg(self) -> float:
        """Near dwell φ_бс = 360° − (φ_у + φ_дс + φ_в) [deg]."""
        return 360.0 - self.phi_working_deg

    @property
    def phi_working_deg(self) -> float:
        """Working angle φ_р = φ_у + φ_дс + φ_в, (1.3) [deg]."""
        return self.phi_rise_deg + self.phi_far_dwell_deg + self.phi_return_deg

    @property
    def ccw(self) -> bool:
        """True when the cam turns counter-clockwise (n_k > 0, §1.5)."""
        return self.n_cam_rpm > 0

    @property
    def omega_cam(self) -> float:
        """|ω_k| = π·|n_k|/30, (1.5) [rad/s]."""
        return math.pi * abs(self.n_cam_rpm) / 30.0

    def as_input_dict(self) -> dict:
        """The row as used, with the JSON keys of the `input` object."""
        return {
            "scheme": self.scheme,
            "l_bc_m": self.l_bc_m,
            "nu_max_deg": self.nu_max_deg,
            "n_cam_rpm": self.n_cam_rpm,
            "stroke": self.stroke,
            "stroke_unit": "deg" if self.is_rocker else "m",
            "law": self.law,
            "phi_rise_deg": self.phi_rise_deg,
            "phi_far_dwell_deg": self.phi_far_dwell_deg,
            "phi_return_deg": self.phi_return_deg,
            "phi_near_dwell_deg": self.phi_near_dwell_deg,
        }


def _num(row: dict, field: str, where: str, *, integer: bool = False) -> float | int | None:
    raw = (row.get(field) or "").strip()
    if raw == "" or raw in {"—", "-"}:
        return None
    try:
        value = float(raw.replace(",", "."))
    except ValueError:
        raise TmmError(f"{where}: field '{field}' is '{raw}', not a number; fix the table") from None
    if not math.isfinite(value):
        raise TmmError(f"{where}: field '{field}' is '{raw}'; give a finite number")
    if integer:
        if value != int(value):
            raise TmmError(f"{where}: field '{field}' is '{raw}'; it must be a whole number")
        return int(value)
    return value


def _require(value, field: str, where: str):
    if value is None:
        raise TmmError(f"{where}: field '{field}' is empty; fill it in")
    return value


def parse_row(row: dict, where: str) -> Variant:
    """Validate one CSV row (a dict keyed by COLUMNS) into a Variant; `where` names it in errors."""
    number = _require(_num(row, "variant", where, integer=True), "variant", where)
    where = f"{where} (variant {number})"
    scheme = _require(_num(row, "scheme", where, integer=True), "scheme", where)
    if scheme not in (1, 2, 3, 4):
        raise TmmError(f"{where}: scheme is {scheme}; it must be 1, 2, 3 or 4")
    law = _require(_num(row, "law", where, integer=True), "law", where)
    if law not in (1, 2, 3, 4):
        raise TmmError(f"{where}: law is {law}; it must be 1, 2, 3 or 4")
    nu = _require(_num(row, "nu_max_deg", where), "nu_max_deg", where)
    if not 0.0 < nu < 90.0:
        raise TmmError(f"{where}: nu_max_deg is {nu:g}; it must lie between 0 and 90 degrees")
    n_k = _require(_num(row, "n_cam_rpm", where), "n_cam_rpm", where)
    if n_k == 0:
        raise TmmError(f"{where}: n_cam_rpm is 0; give the cam speed (negative = clockwise)")
    if not N_CAM_RPM[0] <= abs(n_k) <= N_CAM_RPM[1]:
        raise TmmError(f"{where}: n_cam_rpm is {n_k:g}; give a cam speed of {N_CAM_RPM[0]:g} to {N_CAM_RPM[1]:g} rpm "
                       f"either way (negative = clockwise; docs/limits.md)")
    l_bc = _num(row, "l_bc_m", where)
    s_max = _num(row, "s_max_m", where)
    gamma = _num(row, "gamma_max_deg", where)
    if scheme in (3, 4):
        if l_bc is None:
            raise TmmError(f"{where}: scheme {scheme} is a rocker; fill in l_bc_m")
        if l_bc <= 0:
            raise TmmError(f"{where}: l_bc_m is {l_bc:g}; the rocker length must be positive")
        if not L_BC_M[0] <= l_bc <= L_BC_M[1]:
            raise TmmError(f"{where}: l_bc_m is {l_bc:g}; give a rocker length of {L_BC_M[0]:g} to {L_BC_M[1]:g} m (docs/limits.md)")
        if s_max is not None:
            raise TmmError(f"{where}: scheme {scheme} is a rocker; give gamma_max_deg, leave s_max_m empty")
        stroke = _require(gamma, "gamma_max_deg", where)
        if not 0 < stroke < 90:
            raise TmmError(f"{where}: gamma_max_deg is {stroke:g}; the swing must lie between 0 and 90 degrees")
    else:
        if l_bc is not None:
            raise TmmError(f"{where}: scheme {scheme} has a translating follower; leave l_bc_m empty")
        if gamma is not None:
            raise TmmError(f"{where}: scheme {scheme} has a translating follower; give s_max_m, leave gamma_max_deg empty")
        stroke = _require(s_max, "s_max_m", where)
        if stroke <= 0:
            raise TmmError(f"{where}: s_max_m is {stroke:g}; the stroke must be positive")
        if not S_MAX_M[0] <= stroke <= S_MAX_M[1]:
            raise TmmError(f"{where}: s_max_m is {stroke:g}; give a stroke of {S_MAX_M[0]:g} to {S_MAX_M[1]:g} m (docs/limits.md)")
    phases = {}
    for field in ("phi_rise_deg", "phi_far_dwell_deg", "phi_return_deg"):
        phases[field] = _require(_num(row, field, where), field, where)
        if phases[field] < 0:
            raise TmmError(f"{where}: {field} is {phases[field]:g}; phase angles cannot be negative")
    for field in ("phi_rise_deg", "phi_return_deg"):
        if phases[field] == 0:
            raise TmmError(f"{where}: {field} is 0; rise and return need a positive angle")
    total = sum(phases.values())
    if total > 360.0 + 1e-9:
        raise TmmError(
            f"{where}: the phase angles sum to {total:g} deg, over 360; shorten the rise, dwell or return"
        )
    return Variant(
        number=number,
        scheme=scheme,
        l_bc_m=l_bc,
        nu_max_deg=nu,
        n_cam_rpm=n_k,
        stroke=stroke,
        law=law,
        phi_rise_deg=phases["phi_rise_deg"],
        phi_far_dwell_deg=phases["phi_far_dwell_deg"],
        phi_return_deg=phases["phi_return_deg"],
    )


def parse_table(text: str, source: str) -> dict[int, Variant]:
    """Parse a whole Table 1.2 CSV text; `source` names the file in errors."""
    import io

    reader = csv.DictReader(io.StringIO(text, newline=""))
    header = [h.strip() for h in (reader.fieldnames or [])]
    missing = [c for c in COLUMNS if c not in header]
    if missing:
        raise TmmError(
            f"{source}: missing column(s) {', '.join(missing)}; the header must be {','.join(COLUMNS)}"
        )
    table: dict[int, Variant] = {}
    for lineno, row in enumerate(reader, start=2):
        if len(table) >= VARIANTS_ROWS:
            raise TmmError(f"{source}: more than {VARIANTS_ROWS} variants, over the limit; split the table (docs/limits.md)")
        row = {(k or "").strip(): v for k, v in row.items()}
        if not any((v or "").strip() for v in row.values() if isinstance(v, str)):
            continue
        v = parse_row(row, f"{source} line {lineno}")
        if v.number in table:
            raise TmmError(f"{source} line {lineno}: variant {v.number} appears twice; keep one row")
        table[v.number] = v
    if not table:
        raise TmmError(f"{source}: no variants in the table; add rows under the header")
    return table


def default_table_text() -> str:
    """The book's Table 1.2 as shipped with the package.

    Read beside the package's own file (pip never installs it zipped): ``importlib.resources``
    would load zipfile, lzma and bz2 on every run (≈ 3 ms of a 0.2 s `--json` run).
    """
    from . import data

    return Path(data.__file__).with_name("table_1_2.csv").read_text(encoding="utf-8")


def load_table(path: str | Path | None = None) -> dict[int, Variant]:
    """Load Table 1.2 (the book's, or a teacher's file of the same format)."""
    if path is None:
        return parse_table(default_table_text(), "Table 1.2")
    from .inputs.tables import read_text

    p = Path(path)
    key = _file_key(p)
    if key is not None and key in _LOADED:
        return _LOADED[key]
    text = read_text(p, f"variants file {p}", VARIANTS_FILE_BYTES).text
    table = parse_table(text, str(p))
    if key is not None:
        _LOADED.clear()
        _LOADED[key] = table
    return table


_LOADED: dict = {}  # the last --variants-file parsed, by (path, size, mtime): a batch reads it once per process


def _file_key(p: Path):
    try:
        st = p.stat()
    except OSError:
        return None
    return (str(p.resolve()), st.st_size, st.st_mtime_ns)


def get_variant(number: int | str, path: str | Path | None = None) -> Variant:
    """One validated variant by number; a one-line TmmError when there is no such row."""
    try:
        n = int(str(number).strip())
    except ValueError:
        raise TmmError(f"variant '{number}' is not a number; give a variant number such as 17") from None
    table = load_table(path)
    if n not in table:
        lo, hi = min(table), max(table)
        raise TmmError(f"variant {n} is not in the table; choose a variant from {lo} to {hi}")
    return table[n]
