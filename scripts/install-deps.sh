#!/usr/bin/env bash
# Installs, from Debian's own packages (Debian 13 "trixie" and Debian 12 "bookworm"), whatever
# sdfreel needs that this machine lacks. Names that differ between releases are resolved against
# the release's package lists (alternatives "a|b": the first one the release has).
#   (no option)  what building sdfreel and rendering need: compiler, libraries, the GL backend's
#                headers and its run-time drivers (EGL and Mesa's llvmpipe; OSMesa where the
#                release still ships it)
#   --test       also what scripts/test.sh needs: GoogleTest, stock ffmpeg, clang with its
#                sanitizer and libFuzzer runtime, git, cpack's dpkg tools, man
#   --embree     also Intel Embree 3, which only the optional mesh-method comparison uses
#                (tools/mesh_method_bench, docs/mesh-method.md)
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config
  libpng-dev libopenexr-dev libopencolorio-dev libglm-dev
  libopenimageio-dev   # image channels, frame formats beyond EXR/PNG: a module opened on use
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev libswresample-dev
  libtomlplusplus-dev libcli11-dev libfmt-dev libtbb-dev nlohmann-json3-dev
  libbenchmark-dev   # `sdfreel bench --micro`
  # The GL backend: headers only at build time (libEGL and libOSMesa are opened at run time).
  libgl-dev libegl-dev
  libegl1 libegl-mesa0 libgl1-mesa-dri   # EGL with Mesa's software device (llvmpipe)
  '?libosmesa6'       # the OSMesa platform (dlopened); Mesa 25.1 removed it, so it is skipped where it is gone
)
test_packages=(
  git libgtest-dev
  ffmpeg   # stock ffmpeg/ffprobe check our framemd5 and stream tags
  opencolorio-tools
  file dpkg-dev   # cpack -G DEB: dpkg-shlibdeps derives the package's library dependencies
  man-db   # the install test runs `man sdfreel` on the installed page
  # scripts/fuzz.sh (libFuzzer, ASan, UBSan) and scripts/build-matrix.sh: the release's default
  # clang and its runtime (libclang-rt-14-dev on Debian 12, libclang-rt-19-dev on Debian 13)
  clang 'libclang-rt-dev|libclang-rt-19-dev|libclang-rt-14-dev'
)
for arg in "$@"; do
  case "$arg" in
    --test) packages+=("${test_packages[@]}") ;;
    --embree) packages+=(libembree-dev) ;;
    *) echo "usage: scripts/install-deps.sh [--test] [--embree]" >&2; exit 2 ;;
  esac
done

installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }
available() { [ -n "$(apt-cache policy "$1" 2>/dev/null | awk '/Candidate:/ && $2 != "(none)"')" ]; }

# A package entry is satisfied when one of its alternatives is installed.
satisfied() {
  local alt
  IFS='|' read -ra alts <<<"${1#\?}"
  for alt in "${alts[@]}"; do installed "$alt" && return 0; done
  return 1
}
pending=()
for p in "${packages[@]}"; do satisfied "$p" || pending+=("$p"); done
((${#pending[@]})) || exit 0

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
$sudo apt-get update -qq
missing=()
for p in "${pending[@]}"; do
  optional=0
  [[ $p == \?* ]] && optional=1
  IFS='|' read -ra alts <<<"${p#\?}"
  chosen=""
  for alt in "${alts[@]}"; do
    if available "$alt"; then chosen=$alt; break; fi
  done
  if [ -n "$chosen" ]; then
    missing+=("$chosen")
  elif ((optional)); then
    echo "note: this release has no ${p#\?}; skipping it" >&2
  else
    echo "error: this release has none of: ${alts[*]} (scripts/install-deps.sh needs a new name)" >&2
    exit 1
  fi
done
echo "installing: ${missing[*]}" >&2
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
