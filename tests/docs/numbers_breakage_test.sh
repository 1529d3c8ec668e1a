#!/bin/sh
# scripts/check-doc-numbers.py must fail on a number typed by hand: in a copy
# of the sources, one digit changed inside a recorded benchmark table of
# docs/performance.md makes it exit 1 naming the page and the table, and a
# recording that no page shows is named too; the unmodified copy passes.
# usage: numbers_breakage_test.sh PYTHON SOURCE_DIR
set -u
python=$1 src=$(cd "$2" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$src/README.md" "$work/" && cp -r "$src/docs" "$work/docs" && mkdir -p "$work/bench" &&
  cp -r "$src/bench/results" "$work/bench/results"
"$python" "$src/scripts/check-doc-numbers.py" "$work" >"$work/clean.txt" 2>&1 ||
  { cat "$work/clean.txt"; echo "FAIL: the unmodified copy does not pass"; exit 1; }
grep -q '<!-- bench:presets -->' "$work/docs/performance.md" ||
  { echo "FAIL: docs/performance.md shows no recorded table 'presets'"; exit 1; }
# Change the first digit after the presets marker (a size or a time in the table).
"$python" - "$work/docs/performance.md" <<'PY'
import re, sys
p = sys.argv[1]
s = open(p).read()
at = s.index("<!-- bench:presets -->")
m = re.compile(r"\| [0-9]+\.[0-9]+ MB").search(s, at)
s = s[:m.start()] + "| 9" + s[m.start() + 3:]
open(p, "w").write(s)
PY
printf 'Recorded nowhere.\n\n| a |\n' >"$work/bench/results/orphan.md"
"$python" "$src/scripts/check-doc-numbers.py" "$work" >"$work/out.txt" 2>&1
rc=$?
cat "$work/out.txt"
[ "$rc" = 1 ] || { echo "FAIL: expected exit 1 for an edited number, got $rc"; exit 1; }
grep -q "docs/performance.md: table 'presets' differs" "$work/out.txt" || { echo "FAIL: the edited table is not named"; exit 1; }
grep -q 'bench/results/orphan.md: no page shows it' "$work/out.txt" || { echo "FAIL: the unshown recording is not named"; exit 1; }
echo "ok: an edited number in a recorded table and an unshown recording fail check-doc-numbers.py"
