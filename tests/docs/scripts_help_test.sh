#!/bin/sh
# Every script in scripts/ answers --help with its usage and exit 0, and does
# nothing else: it runs in an empty folder with apt-get, sudo, cmake, cpack,
# dpkg, mkdocs, npm, ctest, make, clang-format and git replaced by stubs that
# record any call; the folder must stay empty and no stub may be called.
# cli_help.py is a module other scripts import (no command line of its own).
# usage: scripts_help_test.sh PYTHON SOURCE_DIR
set -u
python=$1 src=$(cd "$2" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/bin" "$work/cwd"
for tool in apt-get sudo cmake cpack dpkg dpkg-query mkdocs npm ctest make clang-format git emcc blender; do
  printf '#!/bin/sh\necho "%s $*" >>"%s/calls"\n' "$tool" "$work" >"$work/bin/$tool"
  chmod +x "$work/bin/$tool"
done
failed=0 count=0
for script in "$src"/scripts/*.sh "$src"/scripts/*.py; do
  name=$(basename "$script")
  [ "$name" = cli_help.py ] && continue
  count=$((count + 1))
  case $name in *.py) run=$python ;; *) run=bash ;; esac
  out=$(cd "$work/cwd" && PATH="$work/bin:$PATH" "$run" "$script" --help 2>&1)
  rc=$?
  problem=""
  [ "$rc" = 0 ] || problem="exit $rc"
  [ "$(printf '%s\n' "$out" | grep -c .)" -ge 2 ] || problem="$problem; no usage text"
  [ -z "$(ls -A "$work/cwd")" ] || problem="$problem; wrote $(ls -A "$work/cwd" | head -3 | tr '\n' ' ')"
  [ ! -f "$work/calls" ] || problem="$problem; ran $(head -3 "$work/calls" | tr '\n' ';')"
  rm -rf "$work/calls" "$work/cwd" && mkdir "$work/cwd"
  if [ -n "$problem" ]; then
    echo "FAIL scripts/$name --help: $problem"
    printf '%s\n' "$out" | head -5 | sed 's/^/     /'
    failed=$((failed + 1))
  else
    echo "ok   scripts/$name --help"
  fi
done
echo "$count scripts, $failed failed"
[ "$count" -ge 20 ] || { echo "FAIL: expected at least 20 scripts"; exit 1; }
[ "$failed" = 0 ]
