"""Tell a broken dependency release from a broken change (a developer's and CI's tool).

    python tools/deps.py report     # one line: the releases in use that differ from the known-good ones
    python tools/deps.py freeze     # write tools/known-good.txt from this environment (after a green suite)

``tools/known-good.txt`` pins every distribution the package and its test extra pulled in when the
suite last passed in full. ``.ci/run`` installs the newest releases (the README's command, word for
word); when that suite fails, it installs the known-good releases in a second venv and reruns the
failed tests there: passing there means a new release broke them, not the change (see
docs/architecture.md, Dependencies).
"""

from __future__ import annotations

import re
import sys
from importlib import metadata
from pathlib import Path

KNOWN_GOOD = Path(__file__).resolve().with_name("known-good.txt")
OURS = {"tmm"}


def _name(text: str) -> str:
    """PEP 503's normal form of a distribution's name.

    >>> _name("Typing_Extensions")
    'typing-extensions'
    """
    return re.sub(r"[-_.]+", "-", text).lower()


def installed() -> dict[str, str]:
    """{name: version} of the distributions in this environment, ours and the installers aside."""
    skip = OURS | {"pip", "setuptools", "wheel"}
    return {_name(d.metadata["Name"]): d.version for d in metadata.distributions()
            if d.metadata["Name"] and _name(d.metadata["Name"]) not in skip}


def known_good(text: str | None = None) -> dict[str, str]:
    """{name: version} of known-good.txt (``name==version`` lines, ``#`` comments).

    >>> known_good("# tested\\nbabel==2.18.0\\nNumPy==2.4.6  # x\\n")
    {'babel': '2.18.0', 'numpy': '2.4.6'}
    """
    text = KNOWN_GOOD.read_text(encoding="utf-8") if text is None else text
    pins = {}
    for line in text.splitlines():
        line = line.split("#", 1)[0].strip()
        if "==" in line:
            name, version = line.split("==", 1)
            pins[_name(name)] = version.strip()
    return pins


def differences(now: dict[str, str], good: dict[str, str]) -> list[str]:
    """Each release in use that is not the known-good one, as «name now (known good: v)».

    >>> differences({"babel": "2.19.0", "numpy": "2.4.6", "new": "1.0"}, {"babel": "2.18.0", "numpy": "2.4.6"})
    ['babel 2.19.0 (known good: 2.18.0)', 'new 1.0 (not in the known-good set)']
    """
    out = []
    for name in sorted(now):
        if name not in good:
            out.append(f"{name} {now[name]} (not in the known-good set)")
        elif now[name] != good[name]:
            out.append(f"{name} {now[name]} (known good: {good[name]})")
    return out


def main(argv: list[str]) -> int:
    if argv[:1] == ["freeze"]:
        lines = [f"{n}=={v}" for n, v in sorted(installed().items())]
        KNOWN_GOOD.write_text("# The releases the whole suite last passed with (python tools/deps.py freeze).\n"
                              + "\n".join(lines) + "\n", encoding="utf-8")
        return 0
    if argv[:1] == ["report"]:
        diff = differences(installed(), known_good())
        print("dependencies: " + ("the known-good releases" if not diff else
                                  "releases newer or other than the known-good ones: " + "; ".join(diff)))
        return 0
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
