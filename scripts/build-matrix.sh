#!/usr/bin/env bash
# The same bits from every build. Builds sdfreel with g++ and clang++, at -O0, -O2 and -O3, for the
# avx2 and baseline instruction sets (build-matrix/<compiler>-<opt>-<isa>/), renders only the golden
# timelines (tests/golden/SCENE/NAME.toml) with each, and compares every frame's hash with the
# committed tests/golden/SCENE/NAME.framemd5. Any difference fails, naming the build, the frame and the first
# differing pixel (against the same frame from the reference build in build/).
#   scripts/build-matrix.sh            # all 12 builds, one at a time
#   scripts/build-matrix.sh --jobs 3   # 3 builds at once, each with nproc/3 compile jobs
#   scripts/build-matrix.sh --ci       # the cheap subset CI runs: clang++ -O2 baseline (another
#                                      # compiler and another instruction set in one build)
# Each build is checked as soon as it is built, in an order that varies compiler, level and
# instruction set from one build to the next (the build most like the reference comes last), so
# that a run cut short on a busy machine has still covered every axis. Each result line gives the
# seconds that build took (compile and renders).
set -euo pipefail
cd "$(dirname "$0")/.."

configs=()
jobs=1
while (($#)); do
  case "$1" in
    --ci) configs=("clang++ -O2 baseline") ;;
    --jobs) jobs=$2; shift ;;
    *) echo "usage: $0 [--ci] [--jobs N]" >&2; exit 2 ;;
  esac
  shift
done
if ((${#configs[@]} == 0)); then
  configs=("g++ -O0 avx2" "clang++ -O3 baseline" "clang++ -O0 avx2" "g++ -O3 baseline"
           "g++ -O2 avx2" "clang++ -O2 baseline" "g++ -O0 baseline" "clang++ -O3 avx2"
           "clang++ -O2 avx2" "g++ -O2 baseline" "clang++ -O0 baseline" "g++ -O3 avx2")
fi
per_build=$(( $(nproc) / jobs )); ((per_build >= 1)) || per_build=1
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)

# The reference: the normal build, which the golden tests already hold to the committed hashes.
[ -f build/build.ninja ] || cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)" --target sdfreel first_pixel_diff >/dev/null
mkdir -p build-matrix

build_one() {  # "CXX OPT ISA" -> build-matrix/NAME/sdfreel
  read -r cxx opt isa <<<"$1"
  local cc=gcc; [ "$cxx" = clang++ ] && cc=clang
  local dir=build-matrix/${cxx}${opt}-${isa}
  cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$cxx" \
    -DCMAKE_C_COMPILER="$cc" -DCMAKE_CXX_FLAGS_RELEASE="$opt -DNDEBUG" \
    -DCMAKE_C_FLAGS_RELEASE="$opt -DNDEBUG" -DSDFREEL_ISA="$isa" -DSDFREEL_WITH_OSMESA=OFF \
    "${launcher[@]}" >"$dir.log" 2>&1 &&
    cmake --build "$dir" -j "$per_build" --target sdfreel >>"$dir.log" 2>&1 ||
    { echo "BUILD FAILED: $cxx $opt $isa (see $dir.log)"; return 1; }
}

data_lines() { grep -v '^#' "$1"; }

# Renders every golden timeline with build DIR; prints one line per mismatching frame.
check_one() {
  local dir=$1 failed=0
  for toml in tests/golden/*/*.toml; do
    local name=${toml#tests/golden/}; name=${name%.toml}  # SCENE/NAME
    [ -f "tests/golden/$name.framemd5" ] || continue
    # A user's shader runs on GL (llvmpipe): our compiler and its flags do not touch its pixels.
    [[ $name == shader_* ]] && continue
    local out=$dir/golden/$name
    rm -rf "$out"
    mkdir -p "$(dirname "$out")"
    "$dir/sdfreel" render "$toml" --out "$out" --no-video >"$out.log" 2>&1 ||
      { echo "RENDER FAILED: $dir $name (see $out.log)"; failed=1; continue; }
    local line=0
    while IFS= read -r got && IFS= read -r want <&3; do
      if [ "$got" != "$want" ]; then
        local frame; frame=$(echo "$got" | cut -d, -f2 | tr -d ' ')
        local png; png=$(printf 'frames/%05d.png' "$frame")
        local ref=build-matrix/reference/$name
        [ -f "$ref/$png" ] || build/sdfreel render "$toml" --out "$ref" --no-video >/dev/null 2>&1
        echo "MISMATCH: $dir $name frame $frame: md5 ${got##* } (golden ${want##* }); $(build/first_pixel_diff "$out/$png" "$ref/$png")"
        failed=1
      fi
      line=$((line + 1))
    done < <(data_lines "$out/frames.framemd5") 3< <(data_lines "tests/golden/$name.framemd5")
    if [ "$line" -ne "$(data_lines "tests/golden/$name.framemd5" | wc -l)" ]; then
      echo "MISMATCH: $dir $name has $line frames, the golden file $(data_lines "tests/golden/$name.framemd5" | wc -l)"
      failed=1
    fi
  done
  return $failed
}

# Builds one configuration and checks it at once; one result line.
build_and_check() {
  local start=$SECONDS cxx opt isa
  read -r cxx opt isa <<<"$1"
  build_one "$1" || return 1
  if check_one "build-matrix/${cxx}${opt}-${isa}"; then
    echo "same bits: $1 ($((SECONDS - start)) s)"
  else
    echo "DIFFERENT: $1 ($((SECONDS - start)) s)"
    return 1
  fi
}

status=0
running=0
for c in "${configs[@]}"; do
  build_and_check "$c" &
  running=$((running + 1))
  if ((running >= jobs)); then wait -n || status=1; running=$((running - 1)); fi
done
while ((running > 0)); do wait -n || status=1; running=$((running - 1)); done
echo "build matrix: ${#configs[@]} builds in ${SECONDS} s, $([ $status = 0 ] && echo "all the same bits" || echo "FAILED")"
exit $status
