# Sourced by the scripts that build libraries from Debian's source packages
# (scripts/wasm-deps.sh): a private apt state with a deb-src entry, so the
# system's apt configuration never changes.
#   debsrc_init WORKDIR        private sources list, lists and cache; apt-get update
#   debsrc_version PKG         the source version apt offers ("" if none)
#   debsrc_fetch PKG VERSION   downloads, checks (dpkg-source) and unpacks it;
#                              prints the unpacked folder
# Environment: SMPL_DEB_SUITE (bookworm), SMPL_DEB_MIRROR, SMPL_DEB_KEYRING.
# --help: the comment block above, then exit without doing anything.
case "${1:-}" in -h | --help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;; esac
debsrc_init() {
  DEBSRC_WORK=$1
  local apt=$DEBSRC_WORK/apt suite=${SMPL_DEB_SUITE:-bookworm}
  local mirror=${SMPL_DEB_MIRROR:-http://deb.debian.org/debian}
  local keyring=${SMPL_DEB_KEYRING:-/usr/share/keyrings/debian-archive-keyring.gpg}
  mkdir -p "$apt/lists/partial" "$apt/cache/archives/partial"
  echo "deb-src [signed-by=$keyring] $mirror $suite main" >"$apt/sources.list"
  DEBSRC_OPTS=(-o "Dir::Etc::SourceList=$apt/sources.list" -o "Dir::Etc::SourceParts=/dev/null"
               -o "Dir::State::Lists=$apt/lists" -o "Dir::Cache=$apt/cache"
               -o "APT::Sandbox::User=root" -qq)
  apt-get "${DEBSRC_OPTS[@]}" update >"$DEBSRC_WORK/apt-update.log" 2>&1 ||
    echo "debian-source: apt source index update failed ($DEBSRC_WORK/apt-update.log); using the stored index" >&2
}

debsrc_version() {
  apt-cache "${DEBSRC_OPTS[@]}" showsrc "$1" 2>/dev/null | awk '/^Version:/ {print $2; exit}'
}

debsrc_fetch() {
  local pkg=$1 ver=$2 dir=$DEBSRC_WORK/$1
  local upstream=${ver#*:}
  upstream=${upstream%-*}
  rm -rf "$dir" && mkdir -p "$dir"
  (cd "$dir" && apt-get "${DEBSRC_OPTS[@]}" source --download-only "$pkg=$ver" >download.log 2>&1) || {
    echo "debian-source: apt-get source $pkg=$ver failed ($dir/download.log)" >&2
    return 1
  }
  # dpkg-source checks the files against the .dsc, whose checksum apt checked
  # against the signed Release file.
  (cd "$dir" && dpkg-source -x ./*.dsc "$pkg-$upstream" >unpack.log 2>&1) || {
    echo "debian-source: dpkg-source -x failed ($dir/unpack.log)" >&2
    return 1
  }
  echo "$dir/$pkg-$upstream"
}
