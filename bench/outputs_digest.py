"""Digest of everything `tmm project` writes, for every variant: proof that a refactoring changed
no output.

    python bench/outputs_digest.py record  DIGEST.json   # before the change
    python bench/outputs_digest.py compare DIGEST.json   # after it: lists every file that differs

Runs ``tmm project --variant N`` for the 68 variants of Table 1.2 in Russian (and three of them in
English) with the default outputs (figures, the two sheets, the note) and hashes each file. What
differs from run to run by design is normalised first: creation dates and document ids of the PDFs,
the DXF's dates and GUIDs (and its object order: its lines are compared as a sorted list), and the
random clip-path ids and date of matplotlib's SVGs, and the manifest's hashes of those files (it
hashes the bytes as written). Everything else must be byte for byte the same.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

RUNS = [(n, "ru") for n in range(1, 69)] + [(n, "en") for n in (3, 17, 65)]

_PDF = [
    (re.compile(rb"D:\d{14}[^)>\s]*"), b"D:0"),
    (re.compile(rb"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d(\.\d+)?(Z|[+-]\d\d:\d\d)?"), b"T"),
    (re.compile(rb"/ID\s*\[\s*[<(][^>)]*[>)]\s*[<(][^>)]*[>)]\s*\]"), b"/ID[]"),
    (re.compile(rb"uuid:[0-9a-fA-F-]{36}"), b"uuid"),
    (re.compile(rb"<xmpMM:(InstanceID|DocumentID)>[^<]*<"), rb"<xmpMM:\1><"),
]
_SVG = [
    (re.compile(rb"<dc:date>[^<]*</dc:date>"), b"<dc:date/>"),
    (re.compile(rb"\b([pm])[0-9a-f]{10}\b"), rb"\1id"),
]
_DXF_VOLATILE = re.compile(rb"^(\{[0-9A-Fa-f-]{36}\}|24\d{5}\.\d+|\d+\.\d+\.\d+ @ .*)$")


def normalised(path: Path) -> bytes:
    data = path.read_bytes()
    suffix = path.suffix.lower()
    if suffix == ".pdf":
        for pattern, repl in _PDF:
            data = pattern.sub(repl, data)
    elif suffix == ".svg":
        for pattern, repl in _SVG:
            data = pattern.sub(repl, data)
    elif suffix == ".dxf":
        lines = [ln.strip() for ln in data.splitlines()]
        data = b"\n".join(sorted(ln for ln in lines if not _DXF_VOLATILE.match(ln)))
    elif path.name == ".tmm-files.json":  # the manifest: the hashes of the files above are of their raw bytes
        manifest = json.loads(data)
        for name, entry in manifest.get("files", {}).items() if isinstance(manifest.get("files"), dict) else ():
            if Path(name).suffix.lower() in (".pdf", ".svg", ".dxf"):
                entry.pop("sha256", None)
        data = json.dumps(manifest, sort_keys=True).encode()
    return data


def run_one(out: Path, number: int, lang: str) -> dict[str, str]:
    folder = out / f"{lang}"
    cmd = [sys.executable, "-m", "tmm_cli", "project", "--variant", str(number), "--lang", lang,
           "--out", lang, "--format", "svg" if number % 5 == 0 else "png"]
    env = dict(os.environ, MPLBACKEND="Agg", SOURCE_DATE_EPOCH="0", COLUMNS="120")
    res = subprocess.run(cmd, capture_output=True, env=env, cwd=out)
    digests = {"exit": str(res.returncode), "stdout": hashlib.sha256(res.stdout).hexdigest(),
               "stderr": hashlib.sha256(res.stderr).hexdigest()}
    variant = folder / f"variant-{number:02d}"
    for path in sorted(variant.rglob("*")):
        if path.is_file():
            digests[path.relative_to(variant).as_posix()] = hashlib.sha256(normalised(path)).hexdigest()
    return digests


def digest_all(jobs: int = 2) -> dict[str, dict[str, str]]:
    with tempfile.TemporaryDirectory() as tmp, ThreadPoolExecutor(jobs) as pool:
        results = pool.map(lambda run: run_one(Path(tmp), *run), RUNS)
        return {f"{lang}-{n:02d}": d for (n, lang), d in zip(RUNS, results)}


def main(argv: list[str]) -> int:
    if len(argv) != 2 or argv[0] not in ("record", "compare"):
        print(__doc__)
        return 2
    mode, target = argv
    now = digest_all()
    if mode == "record":
        Path(target).write_text(json.dumps(now, indent=1, sort_keys=True), encoding="utf-8")
        print(f"recorded {sum(len(d) for d in now.values())} digests of {len(now)} runs in {target}")
        return 0
    before = json.loads(Path(target).read_text(encoding="utf-8"))
    differ = [f"{run}/{name}" for run in sorted(set(before) | set(now))
              for name in sorted(set(before.get(run, {})) | set(now.get(run, {})))
              if before.get(run, {}).get(name) != now.get(run, {}).get(name)]
    for line in differ:
        print("differs:", line)
    print(f"{len(differ)} of {sum(len(d) for d in now.values())} outputs differ")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
