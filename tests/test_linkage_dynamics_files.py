"""Hostile sheet-2 tables ([[mass]], [load], [dynamics], gravity): each is one TmmError line naming the
key and the problem, in Russian too; the example files' tables are read as they are meant."""

import copy
import math
import re
import tomllib
from pathlib import Path

import pytest

from tmm_cli.errors import TmmError
from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.sheet2_file import parse_sheet2

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "examples"


def base(name="compressor"):
    return tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))


DELETE = object()


def mutate(data, path, value):
    data = copy.deepcopy(data)
    *head, last = path
    node = data
    for key in head:
        node = node[key]
    if value is DELETE:
        del node[last]
    else:
        node[last] = value
    return data


C, F, S = "compressor", "four_bar", "shaper"
CASES = [
    (C, ("gravity",), "yes", "'gravity' is 'yes'; write gravity = true"),
    (C, ("mass",), {"m": 1}, "'mass' must be tables [[mass]]"),
    (C, ("mass",), [{"joint": "B", "m": 1}] * 4, "'mass' has 4 entries; at most 3 are read"),
    (C, ("mass", 1, "m"), -2.4, "'mass[2].m' is -2.4; a mass must lie in [0, 100000] kg"),
    (C, ("mass", 1, "m"), math.nan, "'mass[2].m' is nan; give a finite number"),
    (C, ("mass", 1, "m"), math.inf, "'mass[2].m' is inf; give a finite number"),
    (C, ("mass", 1, "m"), "2.4", "'mass[2].m' must be a number"),
    (C, ("mass", 1, "m"), DELETE, "'mass[2].m' is missing"),
    (C, ("mass", 1, "J"), -0.1, "'mass[2].J' is -0.1; a moment of inertia must lie in [0, 100000]"),
    (C, ("mass", 1, "link"), ["A", "Q"], "'mass[2].link': no moving link joins A and Q"),
    (C, ("mass", 1, "link"), ["A"], "'mass[2].link' must be a list of 2 joint names"),
    (C, ("mass", 1, "centre"), "O", "'mass[2].centre' is 'O', not a point of the link A–B; give one of its joints"),
    (C, ("mass", 1, "centre"), "Zz", "'mass[2].centre' is 'Zz', not a point of the link A–B"),
    (C, ("mass", 1, "joint"), "B", "'mass[2]' needs either link"),
    (C, ("mass", 1, "weight"), 3, "unknown key 'mass[2].weight'; known keys here: link, joint, m, J, centre"),
    (C, ("mass", 2, "joint"), "A", "'mass[3].joint': no slider or block sits on the joint A"),
    (C, ("mass", 2, "J"), 0.5, "'mass[3].J' is 0.5: the slider B does not turn; leave J out"),
    (C, ("mass", 2, "centre"), "A", "'mass[3].centre' is 'A': the centre of mass of the slider B is its joint B"),
    (C, ("mass", 2), {"link": ["A", "O"], "m": 1.0}, "'mass[3]': the link A–O already has its mass in mass[1]"),
    (C, ("load", "on"), "Q", "'load.on' is 'Q': no slider sits on that joint"),
    (C, ("load", "on"), ["O", "A"], "'load.on': no moving link joins O and A (the crank takes no load)"),
    (C, ("load", "on"), ["A", "B"], "'load.on' is the link AB but the output link is B"),
    (C, ("load", "on"), 5, "'load.on' must be a list of 2 joint names"),
    (C, ("load", "on"), DELETE, "'load.on' is missing"),
    (C, ("load", "force"), [0.0, 900.0, 2400.0, 6300.0], "'load.force' has 4 values but 'load.stroke' has 5"),
    (C, ("load", "force"), [0.0, 900.0, -2400.0, 6300.0, 0.0], "'load.force' has -2400; give magnitudes in [0, 1e+09] N"),
    (C, ("load", "force"), [0.0, 900.0, math.nan, 6300.0, 0.0], "'load.force' is nan; give a finite number"),
    (C, ("load", "force"), [0.0, 900.0, "x", 6300.0, 0.0], "'load.force' must be a number"),
    (C, ("load", "force"), 5.0, "'load.force' must be a list of 2 to 1000 numbers"),
    (C, ("load", "moment"), [0, 1, 1, 1, 1], "'load.moment': a slider takes a force; give load.force = [...]"),
    (C, ("load", "stroke"), [0.0, 0.7, 0.4, 0.85, 1.0], "'load.stroke' must run from 0 to 1 without decreasing"),
    (C, ("load", "stroke"), [0.1, 0.4, 0.7, 0.85, 1.0], "'load.stroke' must run from 0 to 1"),
    (C, ("load", "stroke"), [0.0, 0.4, 0.7, 0.85, 1.5], "'load.stroke' must run from 0 to 1"),
    (C, ("load", "stroke"), DELETE, "'load.stroke' is missing"),
    (C, ("load", "push"), 1, "unknown key 'load.push'"),
    (F, ("load", "force"), [0, 1, 1], "'load.force': a turning link takes a moment; give load.moment = [...]"),
    (F, ("load", "moment"), [0.0, -40.0, 40.0], "'load.moment' has -40; give magnitudes in [0, 1e+09] N·m"),
    (S, ("mass", 2, "centre"), DELETE, "'mass[3].centre' is missing: the slotted link AO2 has no fixed middle"),
    (C, ("dynamics", "delta"), 0.0, "'dynamics.delta' is 0; the coefficient of speed fluctuation δ must lie in (0, 0.5]"),
    (C, ("dynamics", "delta"), -0.02, "'dynamics.delta' is -0.02"),
    (C, ("dynamics", "delta"), DELETE, "'dynamics.delta' is missing"),
    (C, ("dynamics", "J_rotor"), -1.0, "'dynamics.J_rotor' is -1; a moment of inertia must lie in [0, 100000] kg·m²"),
    (C, ("dynamics", "flywheel"), "ring", "'dynamics.flywheel' is 'ring'; choose one of disc, rim"),
    (C, ("dynamics", "width_ratio"), 0.0, "'dynamics.width_ratio' is 0; it must lie in (0, 2]"),
    (C, ("dynamics", "density"), math.inf, "'dynamics.density' is inf; give a finite number"),
    (C, ("dynamics", "omega"), 3, "unknown key 'dynamics.omega'"),
]


def _error(name, path, value):
    data = mutate(base(name), path, value)
    mech = parse_mechanism(data, "m.toml")
    parse_sheet2(mech, "m.toml")


@pytest.mark.parametrize("name,path,value,fragment", CASES, ids=[f"{c[0]}:{'.'.join(map(str, c[1]))}={c[2]!r}"[:60]
                                                                for c in CASES])
def test_hostile_sheet2_tables(name, path, value, fragment):
    with pytest.raises(TmmError) as err:
        _error(name, path, value)
    text = str(err.value)
    assert "\n" not in text and text.startswith("m.toml: "), text
    assert fragment in text, text


def test_every_message_has_its_russian_line():
    from tmm_cli.i18n.errors import translate_error

    english = re.compile(r"\b[A-Za-z]{2,} [A-Za-z]{2,} [A-Za-z]{2,}\b")
    for name, path, value, _ in CASES:
        try:
            _error(name, path, value)
        except TmmError as exc:
            text = str(exc)
        ru = translate_error(text)
        assert ru != text and re.search("[А-Яа-я]", ru) and not english.search(ru), (text, ru)


def test_the_examples_tables():
    from tmm_cli.linkage.sheet2_file import parse_sheet2

    for name in ("compressor", "four_bar", "shaper"):
        mech = parse_mechanism(base(name), name)
        inp = parse_sheet2(mech, name)
        assert inp.gravity and inp.masses and inp.load is not None and inp.dynamics is not None
        assert inp.load.link == mech.output.link
    crank = parse_sheet2(parse_mechanism(base("compressor")))
    assert crank.masses[0].centre == "O" and crank.masses[0].link == "OA"  # a balanced crank: S1 on its pivot
    assert [m.label for m in crank.masses] == ["O", "S2", "B"]
    whitworth = parse_sheet2(parse_mechanism(base("whitworth")))
    assert not whitworth.has_forces and whitworth.dynamics is None


def test_a_load_table_with_only_working_is_no_load():
    data = base("compressor")
    data["load"] = {"working": "away"}
    assert parse_sheet2(parse_mechanism(data)).load is None


def test_a_load_on_a_turning_output_is_refused():
    from tmm_cli.linkage.sheet1 import analyse_mechanism
    from tmm_cli.linkage.sheet2 import analyse_sheet2

    data = {"frame": {"O": [0.0, 0.0], "C": [0.05, 0.0]},
            "crank": {"pivot": "O", "joint": "A", "length": 0.2, "rpm": 60},
            "group": [{"kind": "RPR", "joints": ["A", "C"]}],
            "point": [{"name": "S3", "link": ["C", "A"], "along": 0.1}],
            "mass": [{"link": ["C", "A"], "m": 1.0, "centre": "S3"}],
            "load": {"on": ["C", "A"], "stroke": [0, 1], "moment": [1, 1]}}
    mech = parse_mechanism(data, "m.toml")
    with pytest.raises(TmmError, match="the load needs an output link that moves back and forth") as err:
        analyse_sheet2(analyse_mechanism(mech), parse_sheet2(mech, "m.toml"), "m.toml")
    from tmm_cli.i18n.errors import translate_error

    assert "нагрузке нужно выходное звено" in translate_error(str(err.value))
