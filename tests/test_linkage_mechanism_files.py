"""Hostile mechanism files: each is one TmmError line that names the key and the problem; groups
that cannot be assembled say at which crank angle and which link is too short. The sheet-2 tables
are kept, unchecked."""

import copy
import math
import tomllib

import pytest

from tmm_cli.errors import TmmError
from tmm_cli.linkage.mechanism_file import parse_mechanism
from tmm_cli.linkage.positions import cycle
from tmm_cli.linkage.sheet1 import analyse_mechanism

BASE = {
    "name": "test",
    "frame": {"O": [0.0, 0.0], "C": [0.30, 0.0]},
    "crank": {"pivot": "O", "joint": "A", "length": 0.08, "rpm": 120},
    "group": [
        {"kind": "RRR", "joints": ["A", "B", "C"], "lengths": [0.28, 0.20], "branch": "left"},
        {"kind": "RRP", "joints": ["D", "E"], "length": 0.3, "guide": {"through": [0.0, 0.3], "angle_deg": 0.0},
         "branch": "ahead"},
    ],
    "point": [{"name": "D", "link": ["C", "B"], "along": 0.25}],
}


def mutate(path, value):
    data = copy.deepcopy(BASE)
    *head, last = path
    node = data
    for key in head:
        node = node[key]
    if value is DELETE:
        del node[last]
    else:
        node[last] = value
    return data


DELETE = object()

CASES = [
    (("extra",), 1, "unknown key 'extra'"),
    (("positions",), 1, "'positions' is 1; give a whole number of crank positions from 2 to 360"),
    (("positions",), True, "'positions' is True"),
    (("name",), 5, "'name' must be text in quotes"),
    (("frame",), DELETE, "'[frame]' is missing"),
    (("frame",), {}, "'[frame]' must be a table of fixed joints"),
    (("frame", "O"), [0.0], "'frame.O' must be a list of two numbers [x, y] in metres"),
    (("frame", "O"), [0.0, math.nan], "'frame.O' is nan; give a finite number"),
    (("frame", "O"), [0.0, 1e6], "'frame.O' is 1e+06; a coordinate must lie in"),
    (("frame", "O"), ["0", 0.0], "'frame.O' must be a number"),
    (("crank",), DELETE, "'[crank]' is missing"),
    (("crank", "pivot"), "Q", "'crank.pivot' is 'Q', not a joint of [frame]"),
    (("crank", "joint"), "C", "'crank.joint': the name C is taken"),
    (("crank", "joint"), "1A", "'crank.joint' is '1A'; a name is a letter followed by"),
    (("crank", "joint"), "A-B", "'crank.joint' is 'A-B'; a name is a letter"),
    (("crank", "joint"), "", "'crank.joint' is ''"),
    (("crank", "length"), -0.08, "'crank.length' is -0.08; a length must lie in (0, 100] m"),
    (("crank", "length"), 0, "'crank.length' is 0; a length must lie in (0, 100] m"),
    (("crank", "length"), math.inf, "'crank.length' is inf; give a finite number"),
    (("crank", "length"), True, "'crank.length' must be a number"),
    (("crank", "length"), DELETE, "'crank.length' is missing, e.g. length = 0.06"),
    (("crank", "rpm"), -5, "'crank.rpm' is -5; the mean speed must lie in (0, 100000] rpm"),
    (("crank", "rpm"), DELETE, "'crank.rpm' is missing"),
    (("crank", "omega"), 10.0, "give the crank's speed once: 'crank.rpm' or 'crank.omega', not both"),
    (("crank", "sense"), "left", "'crank.sense' is 'left'; choose one of ccw, cw"),
    (("crank", "start_deg"), "90", "'crank.start_deg' must be a number"),
    (("crank", "speed"), 1, "unknown key 'crank.speed'; known keys here: pivot, joint"),
    (("crank", "positions"), 12, "'positions' is read as 'crank.positions': a top-level key must come before"),
    (("group",), [], "the mechanism has no [[group]]"),
    (("group",), [{}] * 21, "'group' has 21 entries; at most 20 are read"),
    (("group", 0, "kind"), "RRRR", "'group[1].kind' is 'RRRR'; the kinds are RRR, RRP, RPR, PRP and RPP"),
    (("group", 0, "kind"), 3, "'group[1].kind' must be text in quotes"),
    (("group", 0, "joints"), ["A", "B"], "'group[1].joints' must be a list of 3 joint names"),
    (("group", 0, "joints"), ["A", "A", "C"], "'group[1].joints' names a joint twice"),
    (("group", 0, "joints"), ["A", "B", "Z"], "'group[1].joints': joint Z is not placed before this group"),
    (("group", 0, "joints"), ["O", "B", "C"], "group 1 (RRR O-B-C) hangs on fixed joints only (O, C)"),
    (("group", 0, "joints"), ["A", "O", "C"], "'group[1].joints': the name O is taken"),
    (("group", 0, "lengths"), [0.28], "'group[1].lengths' must be a list of two lengths [AB, BC]"),
    (("group", 0, "lengths"), [0.28, -0.2], "'group[1].lengths' is -0.2; a length must lie in"),
    (("group", 0, "branch"), DELETE, "'group[1].branch' is missing, e.g. branch = \"left\""),
    (("group", 0, "branch"), "ahead", "'group[1].branch' is 'ahead'; choose one of left, right"),
    (("group", 0, "length"), 0.3, "unknown key 'group[1].length'; known keys here: kind, joints, lengths, branch"),
    (("group", 1, "guide"), DELETE, "'group[2].guide' is missing"),
    (("group", 1, "guide"), {"through": [0, 0]}, "'group[2].guide.angle_deg' is missing"),
    (("group", 1, "guide"), {"through": [0, 0], "angle_deg": 0, "x": 1}, "unknown key 'group[2].guide.x'"),
    (("group", 1, "joints"), ["D", "B"], "'group[2].joints': the name B is taken"),
    (("group", 1, "branch"), "left", "'group[2].branch' is 'left'; choose one of ahead, behind"),
    (("group", 1, "joints"), ["Q", "E"], "'group[2].joints': joint Q is not placed before this group"),
    (("point", 0, "link"), ["A", "C"], "'group[2].joints': joint D is the [[point]] of the link A–C, which is not "
                                       "placed before this group"),
    (("point", 0, "link"), ["B"], "'point[1].link' must be a list of 2 joint names"),
    (("point", 0, "link"), ["A", "E"], "'group[2].joints': joint D is the [[point]] of the link A–E"),
    (("point", 0, "name"), "A", "'point[1].name': the name A is taken"),
    (("point", 0, "along"), DELETE, "'point[1].along' is missing"),
    (("point",), {"name": "D"}, "'point' must be tables [[point]]"),
    (("output",), "Q", "'output' is 'Q'; give a slider's joint"),
    (("output",), ["O", "A"], "'output' is ['O', 'A']; give a slider's joint"),
    (("plan",), 1.5, "'plan' is 1.5; give the label of a position"),
    (("load",), {"working": "up"}, "'load.working' is 'up'; choose one of away, towards"),
]


@pytest.mark.parametrize("path, value, fragment", CASES, ids=[f"{'.'.join(map(str, p))}={v!r}"[:60] for p, v, _ in CASES])
def test_bad_file_is_one_line_naming_the_key(path, value, fragment):
    with pytest.raises(TmmError) as exc:
        parse_mechanism(mutate(path, value), "m.toml")
    text = str(exc.value)
    assert "\n" not in text and text.startswith("m.toml: "), text
    assert fragment in text, text


def test_the_base_file_is_good():
    m = parse_mechanism(copy.deepcopy(BASE), "m.toml")
    assert [ln.name for ln in m.links] == ["OA", "AB", "BC", "DE", "E"]
    assert m.carrier["D"] == 3 and m.output.link == "E"
    assert [p.links for p in m.pairs] == [(0, 1), (1, 2), (2, 3), (0, 3), (3, 4), (4, 5), (0, 5)]
    cycle(m)


def test_a_point_on_no_link():
    data = copy.deepcopy(BASE)
    data["point"].append({"name": "S", "link": ["A", "C"], "along": 0.1})
    with pytest.raises(TmmError, match=r"m.toml: 'point\[2\].link': no moving link joins A and C; name a link by two"):
        parse_mechanism(data, "m.toml")


def test_not_a_table_at_all():
    with pytest.raises(TmmError, match="the file must hold TOML tables"):
        parse_mechanism([1, 2], "m.toml")


def test_a_misplaced_top_level_key_after_a_table_is_explained():
    text = 'positions = 12\n[frame]\nO = [0, 0]\n[crank]\npivot = "O"\njoint = "A"\nlength = 0.1\nrpm = 60\ngravity = true\n'
    with pytest.raises(TmmError, match="'gravity' is read as 'crank.gravity': a top-level key must come before"):
        parse_mechanism(tomllib.loads(text), "m.toml")


def test_a_point_of_a_slotted_link_is_measured_from_its_pivot():
    data = {"frame": {"O": [0, 0], "C": [0, -0.3]}, "crank": {"pivot": "O", "joint": "A", "length": 0.1, "rpm": 60},
            "group": [{"kind": "RPR", "joints": ["A", "C"]}], "point": [{"name": "B", "link": ["A", "C"], "along": 0.5}]}
    with pytest.raises(TmmError, match=r"measure a point of the slotted link AC from its pivot C: link = \[\"C\", \"A\"\]"):
        parse_mechanism(data, "m.toml")


# --- groups that cannot be assembled: the crank angle and the link ------------------------------


def _four_bar(a, b, c, d):
    return parse_mechanism({"frame": {"O": [0.0, 0.0], "C": [d, 0.0]},
                            "crank": {"pivot": "O", "joint": "A", "length": a, "rpm": 60},
                            "group": [{"kind": "RRR", "joints": ["A", "B", "C"], "lengths": [b, c], "branch": "left"}]},
                           "m.toml")


def test_rrr_too_short_says_where_and_by_how_much():
    # |AC| reaches d + a = 0.5 at φ = 180°; AB + BC = 0.45
    with pytest.raises(TmmError) as exc:
        cycle(_four_bar(0.1, 0.25, 0.20, 0.4), "m.toml")
    assert str(exc.value) == ("m.toml: group 1 (RRR A-B-C) cannot be assembled at φ = 180.0°: |AC| = 0.5 m but AB + BC = "
                              "0.45 m; make AB + BC longer than 0.5 m")


def test_rrr_difference_too_large_names_the_short_link():
    # |AC| falls to d − a = 0.3 at φ = 0°; AB − BC = 0.5 − 0.1 = 0.4 > 0.3: BC too short beside AB
    with pytest.raises(TmmError) as exc:
        cycle(_four_bar(0.1, 0.5, 0.1, 0.4), "m.toml")
    assert str(exc.value) == ("m.toml: group 1 (RRR A-B-C) cannot be assembled at φ = 0.0°: |AC| = 0.3 m but |AB − BC| = "
                              "0.4 m; BC is too short beside AB: make it longer than 0.2 m")


def test_rrr_dead_point_is_refused():
    # d + a = b + c exactly: the links fall in line at φ = 180° (a change-point mechanism)
    with pytest.raises(TmmError, match=r"cannot be assembled at φ = 180.0°: \|AC\| = 0.5 m but AB \+ BC = 0.5 m"):
        cycle(_four_bar(0.1, 0.3, 0.2, 0.4), "m.toml")


def test_a_narrow_failure_between_grid_points_is_found():
    # AB + BC exceeds the largest |AC| = 0.5 by less than a grid step's worth of |AC|
    with pytest.raises(TmmError, match=r"at φ = 180.0°: \|AC\| = 0.5 m but AB \+ BC = 0.4999999"):
        cycle(_four_bar(0.1, 0.3, 0.1999999, 0.4), "m.toml")


def test_rrp_rod_too_short():
    m = parse_mechanism({"frame": {"O": [0.0, 0.0]}, "crank": {"pivot": "O", "joint": "A", "length": 0.1, "rpm": 60},
                         "group": [{"kind": "RRP", "joints": ["A", "B"], "length": 0.12,
                                    "guide": {"through": [0.0, -0.05], "angle_deg": 0.0}, "branch": "ahead"}]}, "m.toml")
    with pytest.raises(TmmError) as exc:
        cycle(m, "m.toml")
    assert str(exc.value) == ("m.toml: group 1 (RRP A-B) cannot be assembled at φ = 90.0°: A comes 0.15 m from the guide "
                              "of B but AB = 0.12 m; make AB longer than 0.15 m")


def test_rpr_through_the_pivot():
    m = parse_mechanism({"frame": {"O": [0.0, 0.0], "C": [0.0, -0.1]},
                         "crank": {"pivot": "O", "joint": "A", "length": 0.1, "rpm": 60},
                         "group": [{"kind": "RPR", "joints": ["A", "C"]}]}, "m.toml")
    with pytest.raises(TmmError, match=r"group 1 \(RPR A-C\) cannot be assembled at φ = 270.0°: the block's joint A passes "
                                       r"through the pivot C"):
        cycle(m, "m.toml")


def test_unknown_plan_position():
    m = parse_mechanism(copy.deepcopy(BASE), "m.toml")
    with pytest.raises(TmmError, match=r"--plan 13: there is no such position; the positions are 0, 1, "):
        analyse_mechanism(m, plan="13")


def test_sheet2_tables_are_kept_as_read():
    data = copy.deepcopy(BASE)
    data.update({"gravity": True, "mass": [{"link": ["A", "B"], "m": 2.5}], "load": {"on": "E", "working": "away"},
                 "dynamics": {"delta": 0.04}})
    m = parse_mechanism(data, "m.toml")
    assert m.extra == {"gravity": True, "mass": [{"link": ["A", "B"], "m": 2.5}], "load": {"on": "E", "working": "away"},
                       "dynamics": {"delta": 0.04}}
    assert m.working == "away"


def test_plan_label_with_an_ascii_prime():
    m = parse_mechanism(copy.deepcopy(BASE) | {"plan": "2"}, "m.toml")
    s = analyse_mechanism(m)
    assert s.plans[0].position.label == "2"
    c = s.cycle
    primed = [p.label for p in c.positions if "′" in p.label]
    if primed:
        assert c.index(primed[0].replace("′", "'")) is not None


def _messages():
    """Every message the hostile cases above produce, and the assembly failures."""
    out = []
    for path, value, _ in CASES:
        try:
            parse_mechanism(mutate(path, value), "m.toml")
        except TmmError as exc:
            out.append(str(exc))
    for a, b, c, d in ((0.1, 0.25, 0.20, 0.4), (0.1, 0.5, 0.1, 0.4)):
        try:
            cycle(_four_bar(a, b, c, d), "m.toml")
        except TmmError as exc:
            out.append(str(exc))
    return out


def test_every_message_has_its_russian_line():
    import re

    from tmm_cli.i18n.errors import translate_error

    english = re.compile(r"\b[A-Za-z]{2,} [A-Za-z]{2,} [A-Za-z]{2,}\b")
    messages = _messages()
    assert len(messages) == len(CASES) + 2
    for text in messages:
        ru = translate_error(text)
        assert ru != text and re.search("[А-Яа-я]", ru) and not english.search(ru), (text, ru)
