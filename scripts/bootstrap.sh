#!/usr/bin/env bash
# Installs what rouleau needs, idempotently, and prints the CMake prefix of Kokkos.
#
#   scripts/bootstrap.sh            # Debian packages + Kokkos/KokkosKernels 3.4.01 if none is found
#   Kokkos_ROOT=/path scripts/bootstrap.sh   # use an existing Kokkos (Spack, modules, CUDA build)
#
# Debian packages come through apt (with sudo when not root). When no Kokkos is
# found, Kokkos and KokkosKernels 3.4.01 are built with the Serial and OpenMP
# backends from the sources that Debian's `trilinos` source package carries, into
# .deps/ (ignored by git). The deb-src entry is derived from this machine's own apt
# configuration and kept in a private apt state under .deps/apt, so the system's
# sources are not touched. The orig tarball's SHA-256 is checked against a pinned
# value. A second run does nothing but checks and returns in seconds.
set -euo pipefail

root_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
deps="${ROULEAU_DEPS_DIR:-$root_dir/.deps}"
prefix="$deps/install"
jobs="${ROULEAU_JOBS:-$(nproc)}"

trilinos_version="13.2.0"
trilinos_orig="trilinos_${trilinos_version}.orig.tar.gz"
trilinos_orig_sha256="0ddb47784ba7b8a6b9a07a4822b33be508feb4ccd54301b2a5d10c9e54524b90"
kokkos_version="3.4.01"

log() { printf 'bootstrap: %s\n' "$*" >&2; }
die() { printf 'bootstrap: error: %s\n' "$*" >&2; exit 1; }

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || die "not root and no sudo: install the packages listed in scripts/bootstrap.sh by hand"
  sudo_cmd=(sudo)
fi

# ---------------------------------------------------------------- Debian packages
packages=(
  g++ cmake make pkg-config dpkg-dev ca-certificates tar gzip xz-utils
  libeigen3-dev libhdf5-dev libtomlplusplus-dev libcli11-dev libspdlog-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev python3 python3-matplotlib
)
missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [ "$status" = "install ok installed" ] || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  log "installing Debian packages: ${missing[*]}"
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# ---------------------------------------------------------------- Kokkos
has_kokkos() { # $1: a prefix
  compgen -G "$1/lib*/cmake/Kokkos/KokkosConfig.cmake" >/dev/null &&
    compgen -G "$1/lib*/cmake/KokkosKernels/KokkosKernelsConfig.cmake" >/dev/null
}
cpp="${CMAKE_PREFIX_PATH:-}"
for candidate in "${Kokkos_ROOT:-}" ${cpp//:/ }; do
  if [ -n "$candidate" ] && has_kokkos "$candidate"; then
    log "using the Kokkos found in $candidate"
    echo "$candidate"
    exit 0
  fi
done

stamp="$prefix/.rouleau-kokkos-$kokkos_version"
if [ -f "$stamp" ] && has_kokkos "$prefix"; then
  echo "$prefix"
  exit 0
fi

# A private apt state whose only sources are the deb-src twins of this machine's
# Debian entries (those whose suite names this release's codename).
codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
[ -n "$codename" ] || die "cannot read VERSION_CODENAME from /etc/os-release"
apt_dir="$deps/apt"
mkdir -p "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial" "$deps/src"
src_list="$apt_dir/sources.list"
: >"$src_list"
# one-line format: "deb [opts] URI suite components..."
for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
  [ -f "$f" ] || continue
  awk -v cn="$codename" '$1=="deb" { line=$0; sub(/^deb/, "deb-src", line);
      for (i=2;i<=NF;i++) if ($i==cn || index($i, cn"-")==1) { print line; break } }' "$f" >>"$src_list"
done
# deb822 format: paragraphs with Types/URIs/Suites/Components
for f in /etc/apt/sources.list.d/*.sources; do
  [ -f "$f" ] || continue
  awk -v cn="$codename" 'BEGIN{RS=""; FS="\n"}
    { types=""; uris=""; suites=""; comps=""; signed=""; enabled="yes"
      for (i=1;i<=NF;i++) { l=$i; if (l ~ /^#/) continue
        k=l; sub(/:.*/, "", k); v=l; sub(/^[^:]*:[ \t]*/, "", v)
        if (k=="Types") types=v; else if (k=="URIs") uris=v; else if (k=="Suites") suites=v
        else if (k=="Components") comps=v; else if (k=="Signed-By") signed=v; else if (k=="Enabled") enabled=v }
      if (enabled=="no" || types !~ /(^| )deb( |$)/) next
      n=split(suites, s, " "); split(uris, u, " ")
      for (j=1;j<=n;j++) if (s[j]==cn || index(s[j], cn"-")==1) {
        opt = (signed != "" && signed !~ /\n/) ? "[signed-by=" signed "] " : ""
        print "deb-src " opt u[1] " " s[j] " " comps } }' "$f" >>"$src_list"
done
[ -s "$src_list" ] || die "no Debian '$codename' entry found in /etc/apt to derive a deb-src line from"

apt_opts=(-o "Dir::Etc::SourceList=$src_list" -o "Dir::Etc::SourceParts=/nonexistent"
          -o "Dir::State::Lists=$apt_dir/lists" -o "Dir::Cache=$apt_dir/cache"
          -o "Debug::NoLocking=1" -o "APT::Sandbox::User=$(id -un)")
tarball="$deps/src/$trilinos_orig"
verify() { echo "$trilinos_orig_sha256  $tarball" | sha256sum -c --status; }
if ! { [ -f "$tarball" ] && verify; }; then
  log "fetching Debian's trilinos $trilinos_version source package (it carries Kokkos $kokkos_version)"
  apt-get "${apt_opts[@]}" -qq update
  (cd "$deps/src" && apt-get "${apt_opts[@]}" -qq source --download-only "trilinos" >/dev/null)
  [ -f "$tarball" ] || die "apt-get source did not produce $trilinos_orig (is trilinos $trilinos_version in this release?)"
  verify || die "$tarball: SHA-256 does not match the pinned $trilinos_orig_sha256"
fi
log "checksum ok: $trilinos_orig"

srcdir="$deps/src/trilinos-$trilinos_version"
if [ ! -d "$srcdir/packages/kokkos-kernels" ]; then
  rm -rf "$srcdir" && mkdir -p "$srcdir"
  tar -xzf "$tarball" -C "$srcdir" --strip-components=1 --wildcards '*/packages/kokkos/*' '*/packages/kokkos-kernels/*'
fi
grep -q "set(Kokkos_VERSION_PATCH 01)" "$srcdir/packages/kokkos/CMakeLists.txt" ||
  die "the trilinos tarball does not carry Kokkos $kokkos_version"

backends=(-DKokkos_ENABLE_SERIAL=ON -DKokkos_ENABLE_OPENMP=ON)
extra=()
[ -n "${ROULEAU_KOKKOS_CMAKE_ARGS:-}" ] && read -r -a extra <<<"$ROULEAU_KOKKOS_CMAKE_ARGS"

log "building Kokkos $kokkos_version (Serial, OpenMP) into $prefix"
cmake -S "$srcdir/packages/kokkos" -B "$deps/build/kokkos" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_INSTALL_PREFIX="$prefix" -DCMAKE_CXX_STANDARD=17 -DBUILD_SHARED_LIBS=ON \
  "${backends[@]}" "${extra[@]}" >"$deps/kokkos-configure.log" 2>&1 || die "Kokkos configure failed: $deps/kokkos-configure.log"
cmake --build "$deps/build/kokkos" -j "$jobs" >"$deps/kokkos-build.log" 2>&1 || die "Kokkos build failed: $deps/kokkos-build.log"
cmake --install "$deps/build/kokkos" >/dev/null

# KokkosKernels without default instantiation: rouleau instantiates what it uses.
log "building KokkosKernels $kokkos_version (no default instantiation)"
eti_off=()
for v in INST_DOUBLE INST_FLOAT INST_ORDINAL_INT INST_ORDINAL_INT64_T INST_OFFSET_INT INST_OFFSET_SIZE_T \
         INST_LAYOUTLEFT INST_LAYOUTRIGHT INST_EXECSPACE_OPENMP INST_EXECSPACE_SERIAL INST_MEMSPACE_HOSTSPACE; do
  eti_off+=("-DKokkosKernels_$v=OFF")
done
cmake -S "$srcdir/packages/kokkos-kernels" -B "$deps/build/kokkos-kernels" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_INSTALL_PREFIX="$prefix" -DKokkos_ROOT="$prefix" -DBUILD_SHARED_LIBS=ON \
  -DKokkosKernels_ENABLE_TPL_BLAS=OFF "${eti_off[@]}" >"$deps/kokkoskernels-configure.log" 2>&1 ||
  die "KokkosKernels configure failed: $deps/kokkoskernels-configure.log"
cmake --build "$deps/build/kokkos-kernels" -j "$jobs" >"$deps/kokkoskernels-build.log" 2>&1 ||
  die "KokkosKernels build failed: $deps/kokkoskernels-build.log"
cmake --install "$deps/build/kokkos-kernels" >/dev/null

echo "Kokkos $kokkos_version from Debian trilinos $trilinos_version ($trilinos_orig_sha256)" >"$stamp"
log "done: $prefix"
echo "$prefix"
