#!/bin/sh
# The docs site builds with `mkdocs build --strict` (mkdocs.yml: every nav page
# exists, every link between pages resolves), and a page linking to a missing
# page makes the same build fail.
# usage: mkdocs_test.sh MKDOCS SOURCE_DIR
set -u
mkdocs=$1 src=$(cd "$2" && pwd)
command -v "$mkdocs" >/dev/null 2>&1 || { echo "FAIL: no mkdocs ($mkdocs): scripts/setup-deps.sh --build installs it"; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$src/mkdocs.yml" "$work/" && cp -r "$src/docs" "$work/docs"
(cd "$work" && "$mkdocs" build --strict -q -d "$work/site") >"$work/clean.txt" 2>&1 ||
  { cat "$work/clean.txt"; echo "FAIL: mkdocs build --strict failed"; exit 1; }
[ -f "$work/site/getting-started.html" ] || { echo "FAIL: the site has no getting-started.html"; exit 1; }
printf '\nSee [gone](no-such-page.md).\n' >>"$work/docs/getting-started.md"
(cd "$work" && "$mkdocs" build --strict -d "$work/site2") >"$work/out.txt" 2>&1
rc=$?
[ "$rc" != 0 ] || { cat "$work/out.txt"; echo "FAIL: mkdocs build --strict passed a link to a missing page"; exit 1; }
grep -q 'no-such-page.md' "$work/out.txt" || { cat "$work/out.txt"; echo "FAIL: the missing page is not named"; exit 1; }
echo "ok: mkdocs build --strict passes, and fails on a link to a missing page"
