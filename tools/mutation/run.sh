#!/bin/bash
# Mutation testing of the core chapters (a developer's tool, not CI, not the test extra):
#   pip install cosmic-ray            # in your own venv
#   tools/mutation/run.sh cam 60      # a chapter, how many mutants to sample (default 60)
# It copies the repository's HEAD to a scratch folder (cosmic-ray mutates files in place), samples
# mutants of the formula operators (tools/mutation/sample.py), runs the chapter's tests per mutant
# and prints the kill rate and the survivors' diffs. Minutes per chapter; see docs/architecture.md.
set -euo pipefail
chapter=${1:?cam, gears, linkage or accuracy}; n=${2:-60}
repo=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
work=$(mktemp -d)
git -C "$repo" archive HEAD | tar -x -C "$work"
cd "$work"
skip=""
case $chapter in
  accuracy) skip="chain_input.py,card.py" ;;
  linkage) skip="mechanism_file.py,sheet2_file.py,inputs.py" ;;
  cam) skip="drawing.py" ;;
esac
cosmic-ray init "tools/mutation/cr-$chapter.toml" s.sqlite
python tools/mutation/sample.py s.sqlite "$n" "$skip"
cosmic-ray exec "tools/mutation/cr-$chapter.toml" s.sqlite
cr-rate s.sqlite | sed 's/^/survival rate (%): /'
python -c "import sqlite3; [print(d) for (d,) in sqlite3.connect('s.sqlite').execute(\"select diff from work_results where test_outcome = 'SURVIVED'\")]"
echo "scratch copy: $work"
