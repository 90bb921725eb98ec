#!/usr/bin/env bash
# Installs what rouleau needs, idempotently, and prints the CMake prefix of Kokkos.
#
#   scripts/bootstrap.sh            # Debian packages + Kokkos/KokkosKernels 3.4.01 if none is found
#   scripts/bootstrap.sh --cuda     # the same with CUDA: Debian's CUDA 11.8 toolkit, Kokkos for sm_80
#   scripts/bootstrap.sh --fuzz     # Debian packages and clang with libFuzzer only (scripts/fuzz.sh)
#   scripts/bootstrap.sh --paraview # also ParaView and Xvfb, to render runs (scripts/reproduce_paper.sh)
#   Kokkos_ROOT=/path scripts/bootstrap.sh   # use an existing Kokkos (Spack, modules, a site CUDA build)
#
# Debian packages come through apt (with sudo when not root). When no Kokkos is
# found, Kokkos and KokkosKernels 3.4.01 are built from the sources that Debian's
# `trilinos` source package carries, into .deps/ (ignored by git): Serial and OpenMP
# backends into .deps/install, and with --cuda also CUDA into .deps/install-cuda. The
# deb-src entries are derived from this machine's own apt configuration and kept in a
# private apt state under .deps/apt, so the system's sources are not touched; only
# --cuda adds the contrib/non-free components (derived the same way) to the system's
# sources, because the toolkit must be installed system-wide. The orig tarball's SHA-256
# is checked against a pinned value. A second run does nothing but checks and returns in
# seconds.
#
# For --cuda: ROULEAU_CUDA_ARCH picks the Kokkos architecture (default AMPERE80, with
# ROULEAU_CUDA_SM=sm_80 to match). Every build against the CUDA Kokkos needs the
# environment that scripts/cuda-env.sh sets (Debian's nvcc, not another toolkit on PATH).
set -euo pipefail

root_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
deps="${ROULEAU_DEPS_DIR:-$root_dir/.deps}"
jobs="${ROULEAU_JOBS:-$(nproc)}"
cuda=0
fuzz=0
paraview=0
for argument in "$@"; do
  case "$argument" in
    --cuda) cuda=1 ;;
    --fuzz) fuzz=1 ;;
    --paraview) paraview=1 ;;
    *) printf 'bootstrap: unknown argument %s (usage: bootstrap.sh [--cuda | --fuzz | --paraview])\n' "$argument" >&2
       exit 2 ;;
  esac
done
prefix="$deps/install"
[ "$cuda" = 1 ] && prefix="$deps/install-cuda"

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
codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
[ -n "$codename" ] || die "cannot read VERSION_CODENAME from /etc/os-release"

# This machine's Debian apt entries (those whose suite names this release's codename),
# printed in one-line format as TYPE entries; COMPONENTS replaces their components when
# given. Reads /etc/apt/sources.list, *.list and deb822 *.sources.
derive_debian_entries() { # $1: type (deb, deb-src)  $2: components or ""
  local type=$1 components=$2 f
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [ -f "$f" ] || continue
    awk -v cn="$codename" -v type="$type" -v comps="$components" '
      $1=="deb" { opt=""; i=2; if ($2 ~ /^\[/) { while ($i !~ /\]$/) { opt=opt $i " "; i++ } opt=opt $i " "; i++ }
        uri=$i; suite=$(i+1); c=""; for (k=i+2;k<=NF;k++) c=c (c==""?"":" ") $k
        if (suite==cn || index(suite, cn"-")==1) print type " " opt uri " " suite " " (comps=="" ? c : comps) }' "$f"
  done
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] || continue
    awk -v cn="$codename" -v type="$type" -v comps="$components" 'BEGIN{RS=""; FS="\n"}
      { types=""; uris=""; suites=""; c=""; signed=""; enabled="yes"
        for (i=1;i<=NF;i++) { l=$i; if (l ~ /^#/) continue
          k=l; sub(/:.*/, "", k); v=l; sub(/^[^:]*:[ \t]*/, "", v)
          if (k=="Types") types=v; else if (k=="URIs") uris=v; else if (k=="Suites") suites=v
          else if (k=="Components") c=v; else if (k=="Signed-By") signed=v; else if (k=="Enabled") enabled=v }
        if (enabled=="no" || types !~ /(^| )deb( |$)/) next
        n=split(suites, s, " "); split(uris, u, " ")
        for (j=1;j<=n;j++) if (s[j]==cn || index(s[j], cn"-")==1) {
          opt = (signed != "" && signed !~ /\n/) ? "[signed-by=" signed "] " : ""
          print type " " opt u[1] " " s[j] " " (comps=="" ? c : comps) } }' "$f"
  done
}

installed() { [ "$(dpkg-query -W -f='${Status}' "$1" 2>/dev/null || true)" = "install ok installed" ]; }

# ---------------------------------------------------------------- Debian packages
packages=(
  g++ cmake make pkg-config dpkg-dev ca-certificates tar gzip xz-utils
  libeigen3-dev libhdf5-dev libtomlplusplus-dev libcli11-dev libspdlog-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev libgmsh-dev python3 python3-matplotlib python3-h5py
  libopenmpi-dev openmpi-bin libmetis-dev libfftw3-dev liblapack-dev
)
# The fuzzing build: clang and its runtime libraries (libFuzzer, AddressSanitizer, UBSan).
[ "$fuzz" = 1 ] && packages+=(clang libclang-rt-dev)
# Pictures of runs: ParaView's pvpython under a virtual X server (Debian's ParaView has no
# offscreen build).
[ "$paraview" = 1 ] && packages+=(paraview python3-paraview xvfb)
if [ "$cuda" = 1 ]; then
  packages+=(nvidia-cuda-toolkit g++-11 gcc-11)
  # The toolkit lives in contrib/non-free: add those components of this machine's own
  # Debian entries, once.
  contrib_list=/etc/apt/sources.list.d/rouleau-contrib-non-free.list
  if ! installed nvidia-cuda-toolkit && [ ! -f "$contrib_list" ]; then
    entries=$(derive_debian_entries deb "contrib non-free non-free-firmware")
    [ -n "$entries" ] || die "no Debian '$codename' entry found in /etc/apt to derive contrib/non-free from"
    log "adding the contrib and non-free components of this machine's Debian entries ($contrib_list)"
    printf '%s\n' "$entries" | "${sudo_cmd[@]}" tee "$contrib_list" >/dev/null
  fi
fi
missing=()
for p in "${packages[@]}"; do installed "$p" || missing+=("$p"); done
if [ ${#missing[@]} -gt 0 ]; then
  log "installing Debian packages: ${missing[*]}"
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# The fuzzing build compiles only the host-only library: no Kokkos needed.
[ "$fuzz" = 1 ] && exit 0

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
# Debian entries.
apt_dir="$deps/apt"
mkdir -p "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial" "$deps/src"
src_list="$apt_dir/sources.list"
derive_debian_entries deb-src "" >"$src_list"
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

# The variant: backends, compiler, and the environment its builds run in.
kokkos_options=(-DKokkos_ENABLE_SERIAL=ON -DKokkos_ENABLE_OPENMP=ON)
kernels_options=()
build_env=()
variant="Serial, OpenMP"
if [ "$cuda" = 1 ]; then
  # shellcheck source=scripts/cuda-env.sh
  . "$root_dir/scripts/cuda-env.sh"
  build_env=(env "PATH=$PATH" "CUDA_ROOT=$CUDA_ROOT" "NVCC_WRAPPER_DEFAULT_COMPILER=$NVCC_WRAPPER_DEFAULT_COMPILER"
             "NVCC_WRAPPER_DEFAULT_ARCH=$NVCC_WRAPPER_DEFAULT_ARCH")
  arch="${ROULEAU_CUDA_ARCH:-AMPERE80}"
  wrapper="$srcdir/packages/kokkos/bin/nvcc_wrapper"
  kokkos_options+=(-DKokkos_ENABLE_CUDA=ON -DKokkos_ENABLE_CUDA_LAMBDA=ON "-DKokkos_ARCH_$arch=ON"
                   "-DCMAKE_CXX_COMPILER=$wrapper")
  kernels_options+=("-DCMAKE_CXX_COMPILER=$wrapper" -DKokkosKernels_ENABLE_TPL_CUBLAS=OFF
                    -DKokkosKernels_ENABLE_TPL_CUSPARSE=OFF)
  variant="Serial, OpenMP, CUDA $arch"
fi
extra=()
[ -n "${ROULEAU_KOKKOS_CMAKE_ARGS:-}" ] && read -r -a extra <<<"$ROULEAU_KOKKOS_CMAKE_ARGS"
builds="$deps/build" logs="$deps/logs"
[ "$cuda" = 1 ] && builds="$deps/build-cuda" logs="$deps/logs-cuda"
mkdir -p "$logs"

# configure + build + install one package; $1 name, $2 source dir, rest: CMake options
build_package() {
  local name=$1 source=$2
  shift 2
  "${build_env[@]}" cmake -S "$source" -B "$builds/$name" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_INSTALL_PREFIX="$prefix" -DCMAKE_CXX_STANDARD=17 -DBUILD_SHARED_LIBS=ON "$@" \
    >"$logs/$name-configure.log" 2>&1 || die "$name configure failed: $logs/$name-configure.log"
  "${build_env[@]}" cmake --build "$builds/$name" -j "$jobs" >"$logs/$name-build.log" 2>&1 ||
    die "$name build failed: $logs/$name-build.log"
  "${build_env[@]}" cmake --install "$builds/$name" >/dev/null
}

log "building Kokkos $kokkos_version ($variant) into $prefix"
build_package kokkos "$srcdir/packages/kokkos" "${kokkos_options[@]}" "${extra[@]}"

# KokkosKernels without default instantiation: rouleau instantiates what it uses.
log "building KokkosKernels $kokkos_version (no default instantiation)"
eti_off=()
for v in INST_DOUBLE INST_FLOAT INST_ORDINAL_INT INST_ORDINAL_INT64_T INST_OFFSET_INT INST_OFFSET_SIZE_T \
         INST_LAYOUTLEFT INST_LAYOUTRIGHT INST_EXECSPACE_OPENMP INST_EXECSPACE_SERIAL INST_MEMSPACE_HOSTSPACE \
         INST_EXECSPACE_CUDA INST_MEMSPACE_CUDASPACE INST_MEMSPACE_CUDAUVMSPACE; do
  eti_off+=("-DKokkosKernels_$v=OFF")
done
build_package kokkos-kernels "$srcdir/packages/kokkos-kernels" -DKokkos_ROOT="$prefix" \
  -DKokkosKernels_ENABLE_TPL_BLAS=OFF "${eti_off[@]}" "${kernels_options[@]}"

echo "Kokkos $kokkos_version ($variant) from Debian trilinos $trilinos_version ($trilinos_orig_sha256)" >"$stamp"
log "done: $prefix"
echo "$prefix"
