"""Table 1.2: transcription against the seed text, and the validation rules."""


import pytest

from conftest import ROOT, SEED
from tmm_cli.errors import TmmError
from tmm_cli.variants import COLUMNS, get_variant, load_table, parse_table

HEADER = ",".join(COLUMNS)


def test_68_variants_and_row_1_as_method_reads_it(table):
    assert sorted(table) == list(range(1, 69))
    v = table[1]
    assert (v.scheme, v.nu_max_deg, v.n_cam_rpm, v.stroke, v.law) == (1, 25, 800, 0.05, 1)
    assert (v.phi_rise_deg, v.phi_far_dwell_deg, v.phi_return_deg) == (100, 20, 100)
    assert v.phi_near_dwell_deg == 140


def test_schemes_cycle_and_rockers_have_lengths(table):
    for n, v in table.items():
        assert v.scheme == (n - 1) % 4 + 1, n  # the book's table cycles 1, 2, 3, 4
        assert (v.l_bc_m is not None) == v.is_rocker
        if v.is_rocker:
            assert 10 <= v.stroke <= 40  # γ_max in degrees
        else:
            assert 0.01 <= v.stroke <= 0.3  # S_max in metres


BOOK = ROOT / "tests" / "data" / "table_1_2_book.md"  # the book's Table 1.2, verbatim, with its source


def test_every_row_matches_the_book(table):
    """Independent re-reading of Table 1.2 from the OCR text of the book (kept in the repo, so
    that it runs on every clone)."""
    rows = {}
    for line in BOOK.read_text(encoding="utf-8").splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 10 and cells[0].isdigit() and cells[1] in ("1", "2", "3", "4"):
            rows[int(cells[0])] = cells
    assert len(rows) == 68
    for n, c in rows.items():
        v = table[n]
        num = lambda s: float(s.replace(",", "."))
        assert v.scheme == int(c[1])
        assert (v.l_bc_m is None) if c[2] == "—" else v.l_bc_m == num(c[2])
        assert v.nu_max_deg == num(c[3])
        assert v.n_cam_rpm == num(c[4])
        assert v.stroke == num(c[5])
        assert v.law == int(c[6])
        assert (v.phi_rise_deg, v.phi_far_dwell_deg, v.phi_return_deg) == (num(c[7]), num(c[8]), num(c[9]))


@pytest.mark.skipif(not SEED.exists(), reason="the seeds are not beside the repo (only the project's own machine)")
def test_the_books_table_in_the_repo_is_the_seeds():
    """tests/data/table_1_2_book.md holds the seed's lines unchanged (from 'Таблица 1.2' to row 68)."""
    seed = SEED.read_text(encoding="utf-8").splitlines()
    start = seed.index("Таблица 1.2")
    end = next(i for i, ln in enumerate(seed) if ln.startswith("| 68 |"))
    kept = BOOK.read_text(encoding="utf-8").splitlines()
    kept = kept[kept.index("Таблица 1.2"):]
    assert kept == seed[start:end + 1]


def _row(**over):
    base = dict(variant="1", scheme="1", l_bc_m="", nu_max_deg="25", n_cam_rpm="800", s_max_m="0.05",
                gamma_max_deg="", law="1", phi_rise_deg="100", phi_far_dwell_deg="20", phi_return_deg="100")
    base.update(over)
    return HEADER + "\n" + ",".join(base[c] for c in COLUMNS) + "\n"


@pytest.mark.parametrize(
    "over, words",
    [
        (dict(scheme="5"), "scheme"),
        (dict(law="0"), "law"),
        (dict(nu_max_deg="90"), "nu_max_deg"),
        (dict(n_cam_rpm="0"), "n_cam_rpm"),
        (dict(s_max_m="-0.05"), "s_max_m"),
        (dict(l_bc_m="0.1"), "l_bc_m"),
        (dict(scheme="3"), "l_bc_m"),
        (dict(scheme="3", l_bc_m="0.1"), "gamma_max_deg"),
        (dict(phi_rise_deg="200", phi_return_deg="150"), "over 360"),
        (dict(phi_return_deg="0"), "phi_return_deg"),
        (dict(phi_far_dwell_deg="-5"), "phi_far_dwell_deg"),
        (dict(law="abc"), "law"),
    ],
)
def test_bad_rows_name_the_field(over, words):
    with pytest.raises(TmmError) as err:
        parse_table(_row(**over), "t.csv")
    msg = str(err.value)
    assert words in msg and "\n" not in msg and "variant 1" in msg


def test_missing_column_is_named(tmp_path):
    p = tmp_path / "t.csv"
    p.write_text(_row().replace(",law", "", 1))
    with pytest.raises(TmmError, match="missing column.*law"):
        load_table(p)


def test_unknown_variant_and_non_number():
    with pytest.raises(TmmError, match="from 1 to 68"):
        get_variant(69)
    with pytest.raises(TmmError, match="not a number"):
        get_variant("abc")


def test_teacher_table_is_used(tmp_path):
    p = tmp_path / "mine.csv"
    p.write_text(_row(variant="101", nu_max_deg="20"))
    v = get_variant(101, p)
    assert v.nu_max_deg == 20 and v.closure == "force" and v.follower == "translating"


def test_shipped_table_is_the_repo_file():
    from tmm_cli.variants import default_table_text

    assert default_table_text() == (ROOT / "variants" / "table_1_2.csv").read_text(encoding="utf-8")
