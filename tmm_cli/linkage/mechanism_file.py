"""The mechanism file (a dict from tomllib) → a checked :class:`~.mechanism.Mechanism`.

The form (issue 24; SI units, angles in degrees from +x counter-clockwise)::

    name = "Кривошипно-ползунный механизм компрессора"
    positions = 12                      # evenly spaced crank positions (2 … 360, default 12)
    [frame]                             # fixed joints [m]
    O = [0.0, 0.0]
    [crank]
    pivot = "O"                         # a frame joint
    joint = "A"
    length = 0.06                       # [m]
    rpm = 1500                          # or omega [rad/s]; mean speed, positive
    sense = "ccw"                       # ccw | cw
    start_deg = 90                      # optional: the crank angle of position 0
    [[group]]                           # class II groups in the structural formula's order
    kind = "RRP"
    joints = ["A", "B"]
    length = 0.25
    guide = { through = [0.0, 0.0], angle_deg = 0.0 }
    branch = "ahead"
    [[point]]
    name = "S2"
    link = ["A", "B"]                   # a link by two of its joints
    along = 0.08                        # [m] from the first towards the second
    across = 0.0                        # [m] to the left

Optional: ``output`` (a slider's joint, or a link by two joints; default: the last group's
output link) and ``plan`` (the label of the position of the plans). The sheet-2 tables
(``gravity``, ``[[mass]]``, ``[load]``, ``[dynamics]``) and ``[synthesis]`` (the task of `tmm synth`,
docs/synthesis.md) are kept as read, unchecked, in ``Mechanism.extra``; only ``load.working`` ("away" | "towards") is read here, because it says
which stroke is the working one (position 0 is its start).

Errors: one :class:`TmmError` line that names the key as a path (``crank.length``,
``group[2].lengths``, ``point[1].link``) and the problem.
"""

from __future__ import annotations

import math

from ..errors import TmmError
from .mechanism import FRAME, KINDS, Crank, Group, Guide, Link, Mechanism, Output, Pair, Point

LENGTH_MAX = 100.0  # [m]: any length or coordinate
LENGTH_MIN = 1.0e-4  # [m]: a link shorter than 0.1 mm is no machine's (and divides by nearly zero)
RPM_MAX = 100_000.0
MAX_GROUPS = 20
MAX_POINTS = 100
MAX_FRAME = 50
NAME_MAX = 12
TOP_KEYS = ("name", "positions", "frame", "crank", "group", "point", "output", "plan")
SHEET2_KEYS = ("gravity", "mass", "load", "dynamics")
RECORD_KEYS = ("synthesis",)  # the task `tmm synth` found the mechanism from (kept as read, for the note)
CRANK_KEYS = ("pivot", "joint", "length", "rpm", "omega", "sense", "start_deg")
GROUP_KEYS = {
    "RRR": ("kind", "joints", "lengths", "branch"),
    "RRP": ("kind", "joints", "length", "guide", "branch"),
    "RPR": ("kind", "joints", "offset"),
    "PRP": ("kind", "joints", "guides"),
    "RPP": ("kind", "joints", "guide", "slot_deg"),
}
POINT_KEYS = ("name", "link", "along", "across")
BRANCHES = {"RRR": {"left": 1, "right": -1}, "RRP": {"ahead": 1, "behind": -1}}
EXAMPLES = {
    "crank.pivot": 'pivot = "O"', "crank.joint": 'joint = "A"', "crank.length": "length = 0.06",
    "crank.rpm": "rpm = 1500", "crank.sense": 'sense = "ccw"', "RRR.joints": 'joints = ["A", "B", "C"]',
    "RRP.joints": 'joints = ["A", "B"]', "RPR.joints": 'joints = ["A", "C"]', "PRP.joints": 'joints = ["B"]',
    "RPP.joints": 'joints = ["A", "Y"]', "lengths": "lengths = [0.20, 0.15]",
    "length": "length = 0.25", "guide": "guide = { through = [0.0, 0.0], angle_deg = 0.0 }",
    "RRR.branch": 'branch = "left"', "RRP.branch": 'branch = "ahead"', "kind": 'kind = "RRR"',
    "point.name": 'name = "S2"', "point.link": 'link = ["A", "B"]', "point.along": "along = 0.1",
    "frame": "O = [0.0, 0.0]", "name": 'name = "Механизм"', "positions": "positions = 12",
}


class _Reader:
    """Checks values and words its errors with the file's name."""

    def __init__(self, source: str):
        self.src = source

    def fail(self, text: str):
        raise TmmError(f"{self.src}: {text}")

    def table(self, value, key: str, allowed: tuple[str, ...]) -> dict:
        if not isinstance(value, dict):
            self.fail(f"'{key}' must be a table, e.g. [{key}]")
        for k in value:
            if k in TOP_KEYS + SHEET2_KEYS and k not in allowed:
                self.fail(f"'{k}' is read as '{key}.{k}': a top-level key must come before the first [table] "
                          "of the file")
            if k not in allowed:
                self.fail(f"unknown key '{key}.{k}'; known keys here: {', '.join(allowed)}")
        return value

    def number(self, value, key: str, example: str) -> float:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            self.fail(f"'{key}' must be a number, e.g. {example}")
        x = float(value)
        if not math.isfinite(x):
            self.fail(f"'{key}' is {value}; give a finite number, e.g. {example}")
        return x

    def length(self, value, key: str, example: str) -> float:
        x = self.number(value, key, example)
        if not 0.0 < x <= LENGTH_MAX:
            self.fail(f"'{key}' is {x:g}; a length must lie in (0, {LENGTH_MAX:g}] m")
        if x < LENGTH_MIN:
            self.fail(f"'{key}' is {x:g} m, shorter than {LENGTH_MIN:g} m (0.1 mm): no link of a machine is; give "
                      f"lengths in metres, e.g. {example}")
        return x

    def coordinate(self, value, key: str, example: str) -> float:
        x = self.number(value, key, example)
        if abs(x) > LENGTH_MAX:
            self.fail(f"'{key}' is {x:g}; a coordinate must lie in [−{LENGTH_MAX:g}, {LENGTH_MAX:g}] m")
        return x

    def xy(self, value, key: str, example: str) -> complex:
        if not isinstance(value, list) or len(value) != 2:
            self.fail(f"'{key}' must be a list of two numbers [x, y] in metres, e.g. {example}")
        return complex(self.coordinate(value[0], key, example), self.coordinate(value[1], key, example))

    def text(self, value, key: str, example: str) -> str:
        if not isinstance(value, str):
            self.fail(f"'{key}' must be text in quotes, e.g. {example}")
        return value.strip()

    def choice(self, value, key: str, choices: tuple[str, ...], example: str) -> str:
        word = self.text(value, key, example).lower()
        if word not in choices:
            self.fail(f"'{key}' is {value!r}; choose one of {', '.join(choices)}")
        return word

    def name(self, value, key: str, example: str) -> str:
        word = self.text(value, key, example)
        ok = 0 < len(word) <= NAME_MAX and word[0].isalpha() and all(c.isalnum() or c in "_'′" for c in word)
        if not ok:
            self.fail(f"'{key}' is {value!r}; a name is a letter followed by letters, digits or _ "
                      f"(at most {NAME_MAX}), e.g. \"B\" or \"O1\"")
        return word

    def names(self, value, key: str, count: int, example: str) -> tuple[str, ...]:
        if not isinstance(value, list) or len(value) != count:
            self.fail(f"'{key}' must be a list of {count} joint names, e.g. {example}")
        out = tuple(self.name(v, key, example) for v in value)
        if len(set(out)) != len(out):
            self.fail(f"'{key}' names a joint twice ({', '.join(out)})")
        return out

    def required(self, table: dict, key: str, path: str, example: str):
        if key not in table:
            self.fail(f"'{path}' is missing, e.g. {example}")
        return table[key]


class _Builder:
    """Places the crank, the groups and the points in order, keeping the topology."""

    def __init__(self, r: _Reader, frame: dict[str, complex]):
        self.r = r
        self.frame = frame
        self.carrier = {name: FRAME for name in frame}  # joint → link number it is a pin of
        self.taken = {name: "frame" for name in frame}  # every name in use (joints, points, links)
        self.links: list[Link] = []
        self.pairs: list[Pair] = []
        self.points: dict[str, tuple[str, str]] = {}  # declared points not yet on a link → their link's joints

    def claim(self, name: str, key: str):
        if name in self.taken:
            self.r.fail(f"'{key}': the name {name} is taken; give each joint, point and link its own name")
        self.taken[name] = key

    def add_link(self, link: Link, key: str):
        if link.kind in ("crank", "bar", "slotted"):
            self.claim(link.name, key)
        elif any(ln.name == link.name for ln in self.links):  # a slider's or block's name is its joint's
            self.r.fail(f"'{key}': the joint {link.name} already carries a slider or a block; "
                        "give each joint, point and link its own name")
        self.links.append(link)

    def known(self, name: str, key: str):
        if name in self.points:
            j1, j2 = self.points[name]
            self.r.fail(f"'{key}': joint {name} is the [[point]] of the link {j1}–{j2}, which is not placed before "
                        "this group")
        if name not in self.carrier:
            self.r.fail(f"'{key}': joint {name} is not placed before this group; define it in [frame], as the "
                        "crank's joint, in an earlier group or as a [[point]] of an earlier link")


def _crank(r: _Reader, b: _Builder, data) -> Crank:
    t = r.table(data, "crank", CRANK_KEYS)
    pivot = r.name(r.required(t, "pivot", "crank.pivot", EXAMPLES["crank.pivot"]), "crank.pivot", EXAMPLES["crank.pivot"])
    if pivot not in b.frame:
        r.fail(f"'crank.pivot' is {pivot!r}, not a joint of [frame]; the crank turns about a fixed joint")
    joint = r.name(r.required(t, "joint", "crank.joint", EXAMPLES["crank.joint"]), "crank.joint", EXAMPLES["crank.joint"])
    b.claim(joint, "crank.joint")
    length = r.length(r.required(t, "length", "crank.length", EXAMPLES["crank.length"]), "crank.length",
                      EXAMPLES["crank.length"])
    if "rpm" in t and "omega" in t:
        r.fail("give the crank's speed once: 'crank.rpm' or 'crank.omega', not both")
    if "rpm" in t:
        n = r.number(t["rpm"], "crank.rpm", EXAMPLES["crank.rpm"])
        if not 0.0 < n <= RPM_MAX:
            r.fail(f"'crank.rpm' is {n:g}; the mean speed must lie in (0, {RPM_MAX:g}] rpm (the sense is 'crank.sense')")
        omega = n * math.pi / 30.0
    elif "omega" in t:
        omega = r.number(t["omega"], "crank.omega", "omega = 157.08")
        if not 0.0 < omega <= RPM_MAX * math.pi / 30.0:
            r.fail(f"'crank.omega' is {omega:g}; the mean speed must lie in (0, {RPM_MAX * math.pi / 30.0:.6g}] rad/s "
                   "(the sense is 'crank.sense')")
    else:
        r.fail(f"'crank.rpm' is missing, e.g. {EXAMPLES['crank.rpm']} (or omega in rad/s)")
    sense = r.choice(t.get("sense", "ccw"), "crank.sense", ("ccw", "cw"), EXAMPLES["crank.sense"])
    start = None
    if "start_deg" in t:
        start = math.radians(r.number(t["start_deg"], "crank.start_deg", "start_deg = 90") % 360.0)
    b.carrier[joint] = 1
    b.add_link(Link(pivot + joint, 1, "crank", 0, (pivot, joint), (pivot, joint)), "crank")
    b.pairs.append(Pair(pivot, "R", (FRAME, 1), 0))
    return Crank(pivot, joint, length, omega if sense == "ccw" else -omega, start)


def _moving_guide(r: _Reader, b: "_Builder", t: dict, key: str) -> Guide:
    """A guide on a link placed before the group: ``{ link = [j1, j2], along, across, angle_deg }``."""
    ex = 'guide = { link = ["O2", "B"], along = 0.0, across = 0.0, angle_deg = 0.0 }'
    j1, j2 = r.names(t["link"], f"{key}.link", 2, ex)
    ln = next((x for x in b.links if x.axis is not None and x.kind != "block" and set(x.axis) == {j1, j2}), None)
    if ln is None:
        r.fail(f"'{key}.link': no link joining {j1} and {j2} is placed before this group; a guide rides on the crank "
               "or on a bar or slotted link of an earlier group, named by two of its joints")
    if j1 not in ln.pins:
        r.fail(f"'{key}.link': measure a guide on the slotted link {ln.name} from its pivot {j2}: "
               f"link = [\"{j2}\", \"{j1}\"]")
    along = r.coordinate(t.get("along", 0.0), f"{key}.along", "along = 0.0")
    across = r.coordinate(t.get("across", 0.0), f"{key}.across", "across = 0.0")
    angle = r.number(t.get("angle_deg", 0.0), f"{key}.angle_deg", "angle_deg = 0.0")
    return Guide(0j, math.radians(angle % 360.0), ln.name, j1, j2, along, across)


def _guide(r: _Reader, value, key: str, b: "_Builder | None" = None) -> Guide:
    if isinstance(value, dict) and "link" in value and b is not None:
        return _moving_guide(r, b, r.table(value, key, ("link", "along", "across", "angle_deg")), key)
    t = r.table(value, key, ("through", "angle_deg", "link", "along", "across"))
    for k in ("along", "across"):
        if k in t:
            r.fail(f"'{key}.{k}' places a guide on a moving link; give link = [\"O2\", \"B\"] with it, or a fixed "
                   "guide by through = [x, y] and angle_deg")
    through = r.xy(r.required(t, "through", f"{key}.through", EXAMPLES["guide"]), f"{key}.through", EXAMPLES["guide"])
    angle = r.number(r.required(t, "angle_deg", f"{key}.angle_deg", EXAMPLES["guide"]), f"{key}.angle_deg",
                     EXAMPLES["guide"])
    return Guide(through, math.radians(angle % 360.0))


def _group(r: _Reader, b: _Builder, data, index: int) -> Group:
    key = f"group[{index}]"
    if not isinstance(data, dict):
        r.fail(f"'{key}' must be a table [[group]]")
    raw_kind = r.text(r.required(data, "kind", f"{key}.kind", EXAMPLES["kind"]), f"{key}.kind", EXAMPLES["kind"])
    kind = raw_kind.upper()
    if kind not in KINDS:
        r.fail(f"'{key}.kind' is {raw_kind!r}; the kinds are RRR, RRP, RPR, PRP and RPP (class II groups of kinds 1–5; "
               "class III groups and two inputs are not supported)")
    r.table(data, key, GROUP_KEYS[kind])
    ex = EXAMPLES[f"{kind}.joints"]
    joints = r.names(r.required(data, "joints", f"{key}.joints", ex), f"{key}.joints",
                     {"RRR": 3, "PRP": 1}.get(kind, 2), ex)
    k, n2, n3 = index, 2 * index, 2 * index + 1
    guide, branch, lengths, offset, guides, slot = None, 0, (), 0.0, (), 0.0
    if kind == "RRR":
        a, bj, c = joints
        known, new = (a, c), (bj,)
        ex_l = EXAMPLES["lengths"]
        raw = r.required(data, "lengths", f"{key}.lengths", ex_l)
        if not isinstance(raw, list) or len(raw) != 2:
            r.fail(f"'{key}.lengths' must be a list of two lengths [AB, BC] in metres, e.g. {ex_l}")
        lengths = tuple(r.length(v, f"{key}.lengths", ex_l) for v in raw)
    elif kind == "RRP":
        a, bj = joints
        known, new = (a,), (bj,)
        lengths = (r.length(r.required(data, "length", f"{key}.length", EXAMPLES["length"]), f"{key}.length",
                            EXAMPLES["length"]),)
        guide = _guide(r, r.required(data, "guide", f"{key}.guide", EXAMPLES["guide"]), f"{key}.guide", b)
    elif kind == "PRP":
        (bj,) = joints
        known, new = (), (bj,)
        ex_g = 'guides = [{ link = ["O", "A"], angle_deg = 0.0 }, { through = [0.0, 0.3], angle_deg = 0.0 }]'
        raw = r.required(data, "guides", f"{key}.guides", ex_g)
        if not isinstance(raw, list) or len(raw) != 2:
            r.fail(f"'{key}.guides' must be a list of the two blocks' guides [G1, G2], e.g. {ex_g}")
        guides = tuple(_guide(r, x, f"{key}.guides[{i + 1}]", b) for i, x in enumerate(raw))
        if not any(gd.moving for gd in guides):
            r.fail(f"group {index} (PRP {bj}) has both guides fixed; it would not move: put a guide on the crank or a "
                   "moving link (link = [\"O\", \"A\"] in the guide's table)")
    elif kind == "RPP":
        a, bj = joints
        known, new = (a,), (bj,)
        guide = _guide(r, r.required(data, "guide", f"{key}.guide", EXAMPLES["guide"]), f"{key}.guide", b)
        slot_deg = r.number(data.get("slot_deg", 90.0), f"{key}.slot_deg", "slot_deg = 90")
        if abs(math.remainder(slot_deg, 180.0)) < 1.0:
            r.fail(f"'{key}.slot_deg' is {slot_deg:g}: the yoke's slot would run along its guide (the yoke could not "
                   "be driven); give an angle at least 1° away from it, e.g. slot_deg = 90")
        slot = math.radians(slot_deg % 360.0)
    else:
        a, c = joints
        known, new = (a, c), ()
        offset = r.coordinate(data.get("offset", 0.0), f"{key}.offset", "offset = 0.05")
    if kind in BRANCHES:
        ex_b = EXAMPLES[f"{kind}.branch"]
        word = r.choice(r.required(data, "branch", f"{key}.branch", ex_b), f"{key}.branch", tuple(BRANCHES[kind]), ex_b)
        branch = BRANCHES[kind][word]
    for j in known:
        b.known(j, f"{key}.joints")
    if known and all(b.carrier[j] == FRAME for j in known) and (guide is None or not guide.moving):
        r.fail(f"group {index} ({kind} {'-'.join(joints)}) hangs on fixed joints only ({', '.join(known)}); it would "
               "not move: hang it on the crank or a moving link")
    for j in new:
        b.claim(j, f"{key}.joints")
    cr = b.carrier
    if kind == "RRR":
        names = (a + bj, bj + c)
        b.add_link(Link(names[0], n2, "bar", k, (a, bj), (a, bj)), key)
        b.add_link(Link(names[1], n3, "bar", k, (bj, c), (bj, c)), key)
        pairs = (Pair(a, "R", (cr[a], n2), k), Pair(bj, "R", (n2, n3), k), Pair(c, "R", (cr[c], n3), k))
        cr[bj] = n3
    elif kind == "RRP":
        names = (a + bj, bj)
        b.add_link(Link(names[0], n2, "bar", k, (a, bj), (a, bj)), key)
        b.add_link(Link(bj, n3, "slider", k, None, (bj,)), key)
        carrier = FRAME if not guide.moving else next(x.number for x in b.links if x.name == guide.link)
        pairs = (Pair(a, "R", (cr[a], n2), k), Pair(bj, "R", (n2, n3), k), Pair(bj, "P", (carrier, n3), k))
        cr[bj] = n3
    elif kind == "PRP":
        first = bj + "′"  # the block on G1 (the block on G2 is named by the joint)
        b.claim(first, f"{key}.joints")
        names = (first, bj)
        b.add_link(Link(first, n2, "slider", k, None, (bj,)), key)
        b.add_link(Link(bj, n3, "slider", k, None, (bj,)), key)
        c1, c2 = (FRAME if not gd.moving else next(x.number for x in b.links if x.name == gd.link) for gd in guides)
        pairs = (Pair(bj, "P", (c1, n2), k), Pair(bj, "R", (n2, n3), k), Pair(bj, "P", (c2, n3), k))
        cr[bj] = n3
    elif kind == "RPP":
        names = (a, bj)
        b.add_link(Link(a, n2, "slider", k, None, (a,)), key)
        b.add_link(Link(bj, n3, "slider", k, None, (bj,)), key)
        carrier = FRAME if not guide.moving else next(x.number for x in b.links if x.name == guide.link)
        pairs = (Pair(a, "R", (cr[a], n2), k), Pair(a, "P", (n2, n3), k), Pair(bj, "P", (carrier, n3), k))
        cr[bj] = n3
    else:
        names = (a, a + c)
        b.add_link(Link(a, n2, "block", k, (a, c), (a,)), key)
        b.add_link(Link(a + c, n3, "slotted", k, (a, c), (c,)), key)
        pairs = (Pair(a, "R", (cr[a], n2), k), Pair(a, "P", (n2, n3), k), Pair(c, "R", (cr[c], n3), k))
    return Group(index, kind, joints, lengths, branch, guide, known, new, names, pairs, offset, guides, slot)


def _raw_point(r: _Reader, b: _Builder, data, index: int):
    key = f"point[{index}]"
    t = r.table(data, key, POINT_KEYS)
    name = r.name(r.required(t, "name", f"{key}.name", EXAMPLES["point.name"]), f"{key}.name", EXAMPLES["point.name"])
    b.claim(name, f"{key}.name")
    ends = r.names(r.required(t, "link", f"{key}.link", EXAMPLES["point.link"]), f"{key}.link", 2, EXAMPLES["point.link"])
    along = r.coordinate(r.required(t, "along", f"{key}.along", EXAMPLES["point.along"]), f"{key}.along",
                         EXAMPLES["point.along"])
    across = r.coordinate(t.get("across", 0.0), f"{key}.across", "across = 0.0")
    return key, name, ends, along, across


def _attach_points(r: _Reader, b: _Builder, raw: list, done: dict, group: int):
    """Points whose link belongs to `group` become pins of that link (known to later groups)."""
    for key, name, (j1, j2), along, across in raw:
        if name in done:
            continue
        for ln in b.links:
            if ln.group != group or ln.axis is None or ln.kind == "block" or {j1, j2} != set(ln.axis):
                continue
            if j1 not in ln.pins:
                r.fail(f"'{key}.link': measure a point of the slotted link {ln.name} from its pivot {j2}: "
                       f"link = [\"{j2}\", \"{j1}\"]")
            done[name] = Point(name, ln.name, j1, j2, along, across)
            b.points.pop(name, None)
            b.carrier[name] = ln.number
            break


def _output(r: _Reader, b: _Builder, groups: tuple[Group, ...], value) -> Output:
    last = groups[-1]
    if value is None:
        if last.kind == "RRR":
            return Output("rocker", last.links[1], last.joints[1], last.index)
        if last.kind == "RRP":
            if last.guide.moving:
                r.fail(f"'output' is missing: the slider {last.joints[1]} of the last group slides on a moving guide "
                       f"(on the link {last.guide.link}), which has no default stroke; give the output link at the top "
                       "of the file, e.g. output = [\"D\", \"B\"] (a turning link) or output = \"B\" (a slider)")
            return Output("slider", last.links[1], last.joints[1], last.index)
        if last.kind in ("PRP", "RPP"):  # B along G2; the yoke Y along its guide
            gd = last.guides[1] if last.kind == "PRP" else last.guide
            if gd.moving:
                r.fail(f"'output' is missing: the block {last.links[1]} of the last group slides on a moving guide (on "
                       f"the link {gd.link}), which has no default stroke; give the output link at the top of the file, "
                       f"e.g. output = \"{last.links[1]}\"")
            return Output("slider", last.links[1], last.links[1], last.index)
        return Output("rocker", last.links[1], last.joints[0], last.index)
    bad = (f"'output' is {value!r}; give a slider's joint (e.g. \"B\") or a moving link by two joints "
           "(e.g. [\"C\", \"B\"])")
    if isinstance(value, str):
        for ln in b.links:
            if ln.kind == "slider" and ln.name == value.strip():
                return Output("slider", ln.name, ln.name, ln.group)
        r.fail(bad)
    if isinstance(value, list) and len(value) == 2 and all(isinstance(v, str) for v in value):
        for ln in b.links:
            if ln.axis is not None and ln.kind not in ("crank", "block") and set(ln.axis) == {value[0].strip(),
                                                                                            value[1].strip()}:
                end = value[1].strip() if value[1].strip() not in b.frame else value[0].strip()  # the end that moves
                return Output("rocker", ln.name, end, ln.group)
    r.fail(bad)


def _gas_head(r: _Reader, b: _Builder, load) -> tuple[str, complex] | None:
    """The first [[load]]'s piston and cylinder head when it is a gas load (position 0 is its dead
    centre nearest the head); checked in full by :func:`.gas.parse_gas`."""
    if not isinstance(load, list) or not load or not isinstance(load[0], dict) or "head" not in load[0]:
        return None
    on = load[0].get("on")
    if not isinstance(on, str) or not any(x.kind == "slider" and x.name == on.strip() for x in b.links):
        r.fail(f"'load[1].on' is {on!r}: a gas force acts on a piston, a slider of an RRP group or the yoke of an RPP "
               "group; give its joint, e.g. on = \"B\"")
    return on.strip(), r.xy(load[0]["head"], "load[1].head", "head = [0.0, 0.45]")


def _on_output(on, links, output: Output) -> bool:
    """Whether a load's `on` (a slider's joint, or a link by two joints) names the output link."""
    if isinstance(on, str):
        return on.strip() == output.link
    ln = next((x for x in links if x.name == output.link), None)
    return (isinstance(on, list) and len(on) == 2 and all(isinstance(v, str) for v in on) and ln is not None
            and ln.axis is not None and set(ln.axis) == {on[0].strip(), on[1].strip()})


def _working(r: _Reader, extra: dict, links=(), output: Output | None = None) -> str | None:
    load = extra.get("load")
    key = "load.working"
    if isinstance(load, list):  # [[load]]: the table load's on the output (else the first's; gas loads have both
        tables = [(i, x) for i, x in enumerate(load, start=1) if isinstance(x, dict) and "head" not in x]  # strokes)
        i, load = next(((i, x) for i, x in tables if output is not None and _on_output(x.get("on"), links, output)),
                       tables[0] if tables else (0, None))
        if len(tables) > 1:
            key = f"load[{i}].working"
    if isinstance(load, dict) and "working" in load:
        return r.choice(load["working"], key, ("away", "towards"), 'working = "away"')
    return None


def parse_mechanism(data: dict, source: str = "mechanism") -> Mechanism:
    """Check a mechanism file read by tomllib and return the :class:`Mechanism`.

    `source` (the file's name) starts every error message. Whether each group can be assembled
    at every crank angle is not checked here (see :func:`.assembly.check_assembly`).

    >>> m = parse_mechanism({"frame": {"O": [0, 0]},
    ...     "crank": {"pivot": "O", "joint": "A", "length": 0.06, "rpm": 1500},
    ...     "group": [{"kind": "RRP", "joints": ["A", "B"], "length": 0.25,
    ...                "guide": {"through": [0, 0], "angle_deg": 0}, "branch": "ahead"}]})
    >>> [ln.name for ln in m.links], m.output.kind, [p.joint + p.kind for p in m.pairs]
    (['OA', 'AB', 'B'], 'slider', ['OR', 'AR', 'BR', 'BP'])
    >>> parse_mechanism({"frame": {"O": [0, 0]}}, "m.toml")
    Traceback (most recent call last):
    ...
    tmm_cli.errors.TmmError: m.toml: '[crank]' is missing, e.g. pivot = "O"
    """
    r = _Reader(source)
    if not isinstance(data, dict):
        r.fail("the file must hold TOML tables")
    for k in data:
        if k not in TOP_KEYS and k not in SHEET2_KEYS and k not in RECORD_KEYS:
            r.fail(f"unknown key '{k}'; known keys here: {', '.join(TOP_KEYS + SHEET2_KEYS + RECORD_KEYS)}")
    name = r.text(data.get("name", ""), "name", EXAMPLES["name"])[:200]  # one line already (inputs/mechanism.py)
    positions = data.get("positions", 12)
    if isinstance(positions, bool) or not isinstance(positions, int) or not 2 <= positions <= 360:
        r.fail(f"'positions' is {positions!r}; give a whole number of crank positions from 2 to 360, e.g. positions = 12")
    frame_t = r.required(data, "frame", "[frame]", EXAMPLES["frame"])
    if not isinstance(frame_t, dict) or not frame_t:
        r.fail(f"'[frame]' must be a table of fixed joints, e.g. {EXAMPLES['frame']}")
    if len(frame_t) > MAX_FRAME:
        r.fail(f"'[frame]' has {len(frame_t)} entries; at most {MAX_FRAME} are read")
    frame = {}
    for k, v in frame_t.items():
        frame[r.name(k, f"frame.{k}", EXAMPLES["frame"])] = r.xy(v, f"frame.{k}", EXAMPLES["frame"])
    b = _Builder(r, frame)
    crank = _crank(r, b, r.required(data, "crank", "[crank]", EXAMPLES["crank.pivot"]))

    groups_raw = data.get("group", [])
    if not isinstance(groups_raw, list) or not groups_raw:
        r.fail("the mechanism has no [[group]]; add the class II groups in the order of the structural formula")
    if len(groups_raw) > MAX_GROUPS:
        r.fail(f"'group' has {len(groups_raw)} entries; at most {MAX_GROUPS} are read")
    points_raw = data.get("point", [])
    if not isinstance(points_raw, list):
        r.fail("'point' must be tables [[point]]")
    if len(points_raw) > MAX_POINTS:
        r.fail(f"'point' has {len(points_raw)} entries; at most {MAX_POINTS} are read")
    raw = [_raw_point(r, b, p, i + 1) for i, p in enumerate(points_raw)]
    b.points = {name: ends for _, name, ends, _, _ in raw}
    done: dict[str, Point] = {}
    _attach_points(r, b, raw, done, 0)
    groups = []
    for i, g in enumerate(groups_raw):
        groups.append(_group(r, b, g, i + 1))
        _attach_points(r, b, raw, done, i + 1)
    for key, point, (j1, j2), _, _ in raw:
        if point not in done:
            r.fail(f"'{key}.link': no moving link joins {j1} and {j2}; name a link by two of its joints, "
                   "e.g. [\"A\", \"B\"]")
    groups = tuple(groups)
    gas_head = _gas_head(r, b, data.get("load"))
    if gas_head is not None and data.get("output") is None:  # the first gas load's piston is the output
        ln = next(x for x in b.links if x.name == gas_head[0])
        output = Output("slider", ln.name, ln.pins[0], ln.group)
    else:
        output = _output(r, b, groups, data.get("output"))
    plan = data.get("plan")
    if plan is not None:
        if isinstance(plan, bool) or not isinstance(plan, (int, str)):
            r.fail(f"'plan' is {plan!r}; give the label of a position, e.g. plan = 3")
        plan = str(plan).strip().replace("'", "′")
    extra = {k: data[k] for k in SHEET2_KEYS + RECORD_KEYS if k in data}
    points = tuple(done[point] for _, point, _, _, _ in raw)
    return Mechanism(name, positions, frame, crank, groups, points, tuple(b.links), tuple(b.pairs + [
        p for g in groups for p in g.pairs]), dict(b.carrier), output, _working(r, extra, b.links, output), plan, extra, gas_head)
