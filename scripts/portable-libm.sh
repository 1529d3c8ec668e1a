#!/usr/bin/env bash
# musl's libm as a static archive whose every symbol is prefixed smpl_m_
# (smpl_m_sin, smpl_m_atan2, ...), so that it links beside glibc's or mingw's
# libm without a clash (core/math/libm.h calls it): one implementation of the
# transcendental functions on every platform and CPU, so that outputs are
# byte-identical between the Linux and Windows builds (glibc and mingw-w64
# differ in the last bit of 3% of sin/cos/atan2/... values; glibc also
# picks FMA code paths by CPU).
#   --target linux  Debian's musl-dev (the library Debian ships for this
#                   target): the members of /usr/lib/x86_64-linux-musl/libc.a
#                   that define the functions below, linked into one object
#                   (ld -r) and renamed. No download. Run by CMake at configure.
#   --target mingw  Debian's source package musl (Debian ships no musl for
#                   mingw-w64), src/math/*.c compiled with
#                   x86_64-w64-mingw32-gcc-posix (generic C, no asm; the
#                   x86_64 asm files are long-double functions and sqrt, which
#                   is exact either way). Debian sources through
#                   scripts/debian-source.sh (nothing in /etc/apt changes).
# Both are musl 1.2.3 in bookworm; that they agree bit for bit is what the
# wine test checks (tests/package/windows_wine_test.sh: outputs byte-identical).
#
# Usage: scripts/portable-libm.sh [--target linux|mingw] PREFIX
#   -> PREFIX/lib/libsmpl_m.a, PREFIX/include/smpl_m.h
# --help: the comment block above, then exit without doing anything.
case "${1:-}" in -h | --help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;; esac
set -euo pipefail
TARGET=mingw; PREFIX=""
while [ $# -gt 0 ]; do
  case "$1" in
    --target) TARGET="$2"; shift ;;
    --target=*) TARGET="${1#*=}" ;;
    -*) echo "portable-libm: unknown option $1" >&2; exit 2 ;;
    *) PREFIX="$1" ;;
  esac
  shift
done
[ -n "$PREFIX" ] || { echo "usage: $0 [--target linux|mingw] PREFIX" >&2; exit 2; }
case "$TARGET" in
  linux) CC=gcc; AR=ar; NM=nm; OBJCOPY=objcopy; LD=ld ;;
  mingw) T=x86_64-w64-mingw32; CC=$T-gcc-posix; AR=$T-ar; NM=$T-nm; OBJCOPY=$T-objcopy ;;
  # WebAssembly objects cannot be renamed by objcopy: the names are defined
  # to their smpl_m_ forms and the sources compiled again (-include).
  wasm) CC=emcc; AR=emar; NM=llvm-nm-14; OBJCOPY=true; export NODE_PATH=${NODE_PATH:-/usr/share/nodejs} ;;
  *) echo "portable-libm: --target linux, mingw or wasm" >&2; exit 2 ;;
esac
mkdir -p "$PREFIX"; PREFIX="$(cd "$PREFIX" && pwd)"
WORK="$PREFIX/.src"; STAMP="$PREFIX/share/smpl-win-deps/musl-libm.version"
step() { echo "portable-libm: $*"; }
die() { echo "portable-libm: error: $*" >&2; exit 1; }
# The functions core/math/libm.h offers (and their float forms on mingw).
FUNCS1=(sin cos tan asin acos atan exp log)
FUNCS2=(atan2 pow hypot)

write_header() {  # write_header VERSION
  {
    echo "/* Written by scripts/portable-libm.sh: musl $1 libm, symbols prefixed smpl_m_. */"
    echo "#pragma once"
    echo "#ifdef __cplusplus"; echo 'extern "C" {'; echo "#endif"
    for f in "${FUNCS1[@]}"; do echo "double smpl_m_$f(double);"; done
    for f in "${FUNCS2[@]}"; do echo "double smpl_m_$f(double, double);"; done
    echo "#ifdef __cplusplus"; echo "}"; echo "#endif"
  } >"$PREFIX/include/smpl_m.h"
}

if [ "$TARGET" = linux ]; then
  LIBC=/usr/lib/x86_64-linux-musl/libc.a
  [ -f "$LIBC" ] || die "$LIBC not found (Debian package musl-dev; scripts/setup-deps.sh installs it)"
  VER="$(dpkg-query -W -f='${Version}' musl-dev 2>/dev/null || echo unknown)"
  if [ -f "$PREFIX/lib/libsmpl_m.a" ] && [ -f "$STAMP" ] && [ "$(cat "$STAMP")" = "$VER $TARGET" ]; then
    exit 0  # up to date (configure runs this every time)
  fi
  D="$WORK/musl-dev"; rm -rf "$D"; mkdir -p "$D" "$PREFIX/lib" "$PREFIX/include" "$(dirname "$STAMP")"
  undefined=(); for f in "${FUNCS1[@]}" "${FUNCS2[@]}"; do undefined+=(-u "$f"); done
  "$LD" -r -o "$D/musl_m.o" "${undefined[@]}" "$LIBC" || die "ld -r of $LIBC failed"
  left="$("$NM" -u "$D/musl_m.o" | awk '$2 != "_GLOBAL_OFFSET_TABLE_" {print $2}')"
  [ -z "$left" ] || die "musl's math members need symbols outside libm: $left"
  "$NM" --defined-only -g "$D/musl_m.o" | awk 'NF==3 {print $3" smpl_m_"$3}' | sort -u >"$D/redefine.txt"
  "$OBJCOPY" --redefine-syms="$D/redefine.txt" "$D/musl_m.o"
  rm -f "$PREFIX/lib/libsmpl_m.a"; "$AR" rcs "$PREFIX/lib/libsmpl_m.a" "$D/musl_m.o"
  write_header "$VER (musl-dev)"
  echo "$VER $TARGET" >"$STAMP"
  step "musl-dev $VER: $PREFIX/lib/libsmpl_m.a ($(wc -l <"$D/redefine.txt") symbols)"
  exit 0
fi

for tool in "$CC" "$AR" "$NM" "$OBJCOPY" apt-get apt-cache dpkg-source; do
  command -v "$tool" >/dev/null || die "$tool not found"
done

# shellcheck source=scripts/debian-source.sh
source "$(dirname "$0")/debian-source.sh"
mkdir -p "$(dirname "$STAMP")"
debsrc_init "$WORK"
VER="$(debsrc_version musl)"
if [ -f "$PREFIX/lib/libsmpl_m.a" ] && [ -f "$STAMP" ] && { [ -z "$VER" ] || [ "$(cat "$STAMP")" = "$VER $TARGET" ]; }; then
  step "musl libm $(cat "$STAMP") already in $PREFIX/lib/libsmpl_m.a, skipped"; exit 0
fi
[ -n "$VER" ] || die "apt knows no source package musl"
D="$WORK/musl"
step "musl $VER: downloading the Debian source package"
M="$(debsrc_fetch musl "$VER")" || die "cannot get the source of musl=$VER"
step "musl $VER: unpacked in $M"

# musl's x86_64 types, with 64-bit types spelled 'long long' and LONG_MAX
# taken from the compiler, so that the same headers are right for LP64
# (Linux) and LLP64 (Windows, 32-bit long).
mkdir -p "$D/gen/bits" "$D/obj"
sed -e 's/^#define _Addr long$/#define _Addr long long/' -e 's/^#define _Int64 long$/#define _Int64 long long/' \
    -e 's/^#define _Reg long$/#define _Reg long long/' -e 's/^#define __LONG_MAX .*/#define __LONG_MAX __LONG_MAX__/' \
    "$M/arch/x86_64/bits/alltypes.h.in" >"$D/gen/alltypes.h.in"
sed -f "$M/tools/mkalltypes.sed" "$D/gen/alltypes.h.in" "$M/include/alltypes.h.in" >"$D/gen/bits/alltypes.h"
FLAGS=(-std=c99 -nostdinc -ffreestanding -fno-builtin -fexcess-precision=standard -frounding-math
       -ffp-contract=off -O2 -fno-stack-protector -w -D_XOPEN_SOURCE=700 -I"$D/gen" -I"$M/arch/x86_64"
       -I"$M/arch/generic" -I"$M/src/include" -I"$M/src/internal" -I"$M/include")
n=0
skipped=""
for c in "$M"/src/math/*.c; do  # generic C only (no src/math/x86_64 asm)
  if [ "$TARGET" = wasm ] && ! "$CC" "${FLAGS[@]}" -c "$c" -o "$D/obj/$(basename "$c" .c).o" 2>/dev/null; then
    # x86 inline asm in musl's arch headers (fma, long-double helpers): not
    # needed by the functions core/math/libm.h calls, checked below.
    skipped="$skipped $(basename "$c")"
    continue
  fi
  [ "$TARGET" = wasm ] || "$CC" "${FLAGS[@]}" -c "$c" -o "$D/obj/$(basename "$c" .c).o" || die "compiling $c failed"
  n=$((n + 1))
done
[ -z "$skipped" ] || step "musl $VER: skipped for $TARGET (x86 asm):$skipped"
step "musl $VER: compiled $n files of src/math with $CC"
"$NM" --defined-only -g "$D"/obj/*.o | awk 'NF==3 {print $3" smpl_m_"$3}' | sort -u >"$D/redefine.txt"
if [ "$TARGET" = wasm ]; then
  awk '{print "#define "$1" "$2}' "$D/redefine.txt" >"$D/rename.h"
  for o in "$D"/obj/*.o; do
    c="$M/src/math/$(basename "$o" .o).c"
    "$CC" "${FLAGS[@]}" -include "$D/rename.h" -c "$c" -o "$o" 2>/dev/null || rm -f "$o"  # aliases
  done
  "$NM" --defined-only -g "$D"/obj/*.o >"$D/defined.txt"
  for f in "${FUNCS1[@]}" "${FUNCS2[@]}"; do
    grep -q " smpl_m_$f\$" "$D/defined.txt" || die "musl's $f was not built for $TARGET"
  done
  left=$("$NM" --defined-only -g "$D"/obj/*.o | awk 'NF==3 && $3 !~ /^smpl_m_/ {print $3}' | sort -u | tr '\n' ' ')
  [ -z "$left" ] || die "symbols not renamed: $left"
else
  for o in "$D"/obj/*.o; do "$OBJCOPY" --redefine-syms="$D/redefine.txt" "$o"; done
fi
mkdir -p "$PREFIX/lib" "$PREFIX/include"
rm -f "$PREFIX/lib/libsmpl_m.a"; "$AR" rcs "$PREFIX/lib/libsmpl_m.a" "$D"/obj/*.o
write_header "$VER"
echo "$VER $TARGET" >"$STAMP"
step "musl $VER: installed $PREFIX/lib/libsmpl_m.a ($(wc -l <"$D/redefine.txt") symbols) and include/smpl_m.h"
