#!/bin/sh
# scripts/check-doc-links.py must fail on a dead link: a copy of README.md and
# docs/ with one link to a missing page, one to a missing heading, and one
# prose citation of a missing section must make it exit 1 and name all three;
# the unmodified copy passes.
# usage: links_breakage_test.sh PYTHON SOURCE_DIR
set -u
python=$1 src=$(cd "$2" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$src/README.md" "$src/CONTRIBUTING.md" "$src/CHANGELOG.md" "$src/LICENSE" "$work/" && cp -r "$src/docs" "$work/docs"
"$python" "$src/scripts/check-doc-links.py" "$work" >"$work/clean.txt" 2>&1 ||
  { cat "$work/clean.txt"; echo "FAIL: the unmodified copy does not pass"; exit 1; }
printf '\nSee [gone](no-such-page.md), [there](motions.md#no-such-heading) and docs/cli.md "No such section".\n' \
  >>"$work/docs/getting-started.md"
"$python" "$src/scripts/check-doc-links.py" "$work" >"$work/out.txt" 2>&1
rc=$?
cat "$work/out.txt"
[ "$rc" = 1 ] || { echo "FAIL: expected exit 1 for dead links, got $rc"; exit 1; }
grep -q 'getting-started.md:.*no-such-page.md: no such file' "$work/out.txt" || { echo "FAIL: the missing page is not named"; exit 1; }
grep -q 'motions.md#no-such-heading: no such heading' "$work/out.txt" || { echo "FAIL: the missing anchor is not named"; exit 1; }
grep -q 'cites docs/cli.md "No such section": no such heading' "$work/out.txt" || { echo "FAIL: the dead citation is not named"; exit 1; }
echo "ok: a dead link, a dead anchor and a dead section citation fail check-doc-links.py"
