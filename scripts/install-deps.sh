#!/usr/bin/env bash
# Installs, from Debian 12's packages, whatever sdfreel needs that this machine lacks.
# --embree: also Intel Embree 3, which only the optional mesh-method comparison uses
# (tools/mesh_method_bench, docs/mesh-method.md); sdfreel and its tests never need it.
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config git
  libpng-dev libopenexr-dev libopencolorio-dev opencolorio-tools libglm-dev
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev
  libosmesa6-dev libtomlplusplus-dev libcli11-dev libfmt-dev libtbb-dev
  nlohmann-json3-dev libgtest-dev libbenchmark-dev
  ffmpeg   # tests only: stock ffmpeg/ffprobe check our framemd5 and stream tags
  file dpkg-dev   # cpack -G DEB: dpkg-shlibdeps derives the package's library dependencies
  clang libclang-rt-14-dev   # scripts/fuzz.sh (libFuzzer, ASan, UBSan), scripts/build-matrix.sh
)
for arg in "$@"; do
  case "$arg" in
    --embree) packages+=(libembree-dev) ;;
    *) echo "usage: scripts/install-deps.sh [--embree]" >&2; exit 2 ;;
  esac
done
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}" >&2
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
