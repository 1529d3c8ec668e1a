#!/usr/bin/env bash
# The release packages of a static build (SMPL_STATIC=ON), made by cpack as
# scripts/release.sh makes them, installed and run as a user would:
#  .tar.gz  smpl-export-<version>-linux-x86_64/bin/smpl-export, static, with
#           share/ (man page, completions, add-ons) beside it; unpacked into an
#           empty root and run there (chroot);
#  .deb     control fields (no Depends: the binary is static); installed with
#           dpkg --root into a fresh root holding only an empty dpkg database,
#           then the quick start's export (--model builtin --out body.glb) run
#           from the installed /usr/bin/smpl-export in that root (chroot);
#           removed again with dpkg -r, leaving none of its files.
# Each export is compared byte for byte with the Debian (dynamic) build's.
#   cpack_test.sh STATIC_BUILD_DIR DYNAMIC_EXE VERSION WORK
set -euo pipefail
build=$1 dynamic=$2 version=$3 work=$4
fail() { echo "FAIL: $*" >&2; exit 1; }
[[ -f $build/CPackConfig.cmake ]] || fail "no CPack configuration in '$build' (configure the tests with -DSMPL_STATIC_BUILD_DIR=<a SMPL_STATIC=ON build>; scripts/test.sh builds build-static)"
grep -q '^SMPL_STATIC:BOOL=ON' "$build/CMakeCache.txt" || fail "$build is not a SMPL_STATIC=ON build"
if [[ $(id -u) -eq 0 ]]; then chroot_cmd=(chroot); else chroot_cmd=(unshare -r chroot); fi
rm -rf "$work" && mkdir -p "$work/pkg" "$work/host"
(cd "$work/host" && "$dynamic" --model builtin --out body.glb --quiet)

(cd "$work/pkg" && cpack -G "TGZ;DEB" --config "$build/CPackConfig.cmake" -B "$work/pkg" >cpack.log 2>&1) ||
  fail "cpack: $(tail -5 "$work/pkg/cpack.log")"
name=smpl-export-$version-linux-x86_64
tgz=$work/pkg/$name.tar.gz deb=$work/pkg/smpl-export_${version}_amd64.deb
[[ -f $tgz && -f $deb ]] || fail "cpack wrote $(ls "$work/pkg" | tr '\n' ' '), expected $name.tar.gz and smpl-export_${version}_amd64.deb"

# The tarball: layout, a static binary, and it runs in an empty root.
tar -tzf "$tgz" >"$work/tgz.list"
for f in bin/smpl-export share/man/man1/smpl-export.1 share/bash-completion/completions/smpl-export \
         share/smpl-export/blender/smpl_correctives.zip share/doc/smpl-export/LICENSE; do
  grep -qx "$name/$f" "$work/tgz.list" || fail "$tgz lacks $name/$f"
done
mkdir -p "$work/troot" && tar -xzf "$tgz" -C "$work/troot"
if readelf -lW "$work/troot/$name/bin/smpl-export" | grep "program interpreter"; then
  fail "$name/bin/smpl-export is not static"
fi
"${chroot_cmd[@]}" "$work/troot" "/$name/bin/smpl-export" --model builtin --out body.glb --quiet ||
  fail "$name/bin/smpl-export in an empty root: exit $?"
cmp "$work/troot/body.glb" "$work/host/body.glb" || fail "tarball binary: body.glb differs from the dynamic build's"

# The .deb: control fields.
field() { dpkg-deb -f "$deb" "$1"; }
[[ $(field Package) == smpl-export ]] || fail "$deb: Package is '$(field Package)'"
[[ $(field Version) == "$version" ]] || fail "$deb: Version is '$(field Version)', expected $version"
[[ $(field Architecture) == amd64 ]] || fail "$deb: Architecture is '$(field Architecture)'"
[[ -z $(field Depends) ]] || fail "$deb: Depends '$(field Depends)' (the binary is static)"

# Installed by dpkg into a fresh root, then the quick start run from it.
root=$work/root
mkdir -p "$root/var/lib/dpkg/info" "$root/var/lib/dpkg/updates" "$root/tmp"
: >"$root/var/lib/dpkg/status"
dpkg --root="$root" --log=/dev/null -i "$deb" >"$work/dpkg.log" 2>&1 || fail "dpkg -i: $(tail -5 "$work/dpkg.log")"
dpkg --root="$root" -s smpl-export >"$work/dpkg.status" || fail "dpkg -s: smpl-export not installed"
grep -qx "Status: install ok installed" "$work/dpkg.status" || fail "dpkg: $(grep Status "$work/dpkg.status")"
for f in usr/bin/smpl-export usr/share/man/man1/smpl-export.1 usr/share/bash-completion/completions/smpl-export \
         usr/share/zsh/vendor-completions/_smpl-export usr/share/fish/vendor_completions.d/smpl-export.fish \
         usr/share/doc/smpl-export/LICENSE usr/share/smpl-export/blender/smpl_correctives.zip \
         usr/share/smpl-export/maya/smpl_maya.mod usr/share/smpl-export/unity/com.smpl-export.correctives/package.json \
         usr/share/smpl-export/web/smpl-correctives/package.json; do
  [[ -f $root/$f ]] || fail "the .deb did not install /$f"
done
"${chroot_cmd[@]}" "$root" /usr/bin/smpl-export --model builtin --out body.glb >"$work/quickstart.out" 2>&1 ||
  fail "quick start from the .deb: exit $?: $(tail -3 "$work/quickstart.out")"
for g in body.glb body.glb.smpl.json; do
  cmp "$root/$g" "$work/host/$g" || fail ".deb binary: $g differs from the dynamic build's"
done
dpkg --root="$root" --log=/dev/null -r smpl-export >>"$work/dpkg.log" 2>&1 || fail "dpkg -r: $(tail -5 "$work/dpkg.log")"
left=$(cd "$root" && find . -type f -not -path './var/lib/dpkg/*' -not -name 'body.glb*' | sort | tr '\n' ' ')
[[ -z $left ]] || fail "dpkg -r left files: $left"
echo "cpack: $name.tar.gz ($(stat -c %s "$tgz") bytes) runs in an empty root; smpl-export_${version}_amd64.deb" \
     "($(stat -c %s "$deb") bytes) installs with dpkg into a fresh root, its quick start writes the dynamic build's bytes, dpkg -r removes it"
