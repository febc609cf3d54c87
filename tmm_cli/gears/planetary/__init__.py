"""Planetary reducer synthesis: the five conditions of §2.1.3, the exhaustive search, the book's
hand procedure (§2.4, §2.5) and the checks by (2.1) and by the velocity pictures (2.3).

Symbols follow the book: k — the driving sun (z_k), c — the planet (z_c; scheme 2 also c′, z_c′),
n — the fixed ring (z_n), H — the carrier (output), k — also the number of planets. Scheme keys:
"1" single-row, "2" double-row, "1+1" two single-row stages in series (Fig. 2.4 scheme 3).

One chapter a module:

- :mod:`.conditions` — one stage and its conditions (coaxiality, assembly, neighbouring (2.5),
  Table 2.2), the size measure Γ1, Γ2 of §2.5, a design of one or two stages;
- :mod:`.search` — the tables of all tooth sets within Z_MAX and the exhaustive search (numpy);
- :mod:`.book` — the book's hand procedure (§2.4, §2.5) and its printed answers;
- :mod:`.velocity` — the checks of a design: (2.1) and the velocity pictures (2.3).

The public names of all four are importable from here too.
"""

from .book import (
    BOOK_PRINTED,
    BookDerivation,
    BookRow,
    BookStage,
    PrintedCheck,
    book_derivation,
    book_scheme1,
    book_scheme2,
    check_printed,
    exact_fraction,
    convergents,
    simple_fractions,
)
from .conditions import (
    HA_STAR,
    K_MAX,
    REL_EPS,
    Z_DIFF,
    Z_EXT_EXT,
    Z_EXT_INT,
    Z_RING,
    InterferenceItem,
    PlanetaryDesign,
    Stage,
    StageChecks,
    assembly_book,
    assembly_ok,
    assembly_value,
    check_stage,
    divisors,
    interference_items,
    max_planets,
    neighbour_limit,
    neighbour_ok,
    neighbour_ratio,
    stage_ratio_split_key,
)
from .search import (
    SELECT_RULES,
    SELECT_SLACK,
    STAGE_RANGE_1,
    Z_MAX,
    SearchResult,
    closest_ratio,
    scheme1_table,
    scheme2_table,
    search_designs,
)
from .velocity import (
    DesignChecks,
    VelocityPicture,
    VelocityStage,
    check_design,
    ratio_21,
    velocity_picture,
)

__all__ = [
    # conditions
    "HA_STAR", "K_MAX", "REL_EPS", "Z_DIFF", "Z_EXT_EXT", "Z_EXT_INT", "Z_RING", "InterferenceItem",
    "PlanetaryDesign", "Stage", "StageChecks", "assembly_book", "assembly_ok", "assembly_value", "check_stage",
    "divisors", "interference_items", "max_planets", "neighbour_limit", "neighbour_ok", "neighbour_ratio",
    "stage_ratio_split_key",
    # search
    "SELECT_RULES", "SELECT_SLACK", "STAGE_RANGE_1", "Z_MAX", "SearchResult", "closest_ratio", "scheme1_table",
    "scheme2_table", "search_designs",
    # book
    "BOOK_PRINTED", "BookDerivation", "BookRow", "BookStage", "PrintedCheck", "book_derivation", "book_scheme1",
    "book_scheme2", "check_printed", "convergents", "exact_fraction", "simple_fractions",
    # velocity
    "DesignChecks", "VelocityPicture", "VelocityStage", "check_design", "ratio_21", "velocity_picture",
]
