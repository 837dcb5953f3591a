#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan, fuzz/) into build-fuzz/ and runs each one for
# SECONDS (default 25) on its corpus, seeded from tests/. A crash, hang (> 10 s an input), leak or
# sanitizer report fails the script; the reproducer lands in build-fuzz/findings/.
#   scripts/fuzz.sh                 # CI: 25 s a target
#   scripts/fuzz.sh 3600 fuzz_timeline   # a longer run of one target
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-25}
shift || true
targets=("$@")
((${#targets[@]})) || targets=(fuzz_timeline fuzz_manifest fuzz_cli_options fuzz_shadertoy_json
  fuzz_channel_tables fuzz_checkpoint)

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
# baseline ISA and -O1: the sanitizers' cost matters more here than vector width.
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" -DSDFREEL_FUZZ=ON \
  -DSDFREEL_ISA=baseline -DSDFREEL_WITH_OSMESA=OFF "${launcher[@]}" >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target "${targets[@]}"

seeds_for() {
  case "$1" in
    fuzz_timeline) ls tests/golden/*/*.toml tests/hard_cases/*/*.toml timelines/*.toml ;;
    fuzz_manifest) ls tests/fuzz_seeds/manifest/* ;;
    fuzz_cli_options) ls tests/fuzz_seeds/cli_options/* ;;
    fuzz_shadertoy_json) ls examples/shaders/*.json ;;
    fuzz_channel_tables) ls examples/shaders/*/channels.toml examples/shaders/*.toml tests/fuzz_seeds/channel_tables/* ;;
    fuzz_checkpoint) ls tests/fuzz_seeds/checkpoint/* ;;
  esac
}

mkdir -p build-fuzz/findings
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
for t in "${targets[@]}"; do
  corpus=build-fuzz/corpus/$t
  mkdir -p "$corpus"
  seeds_for "$t" | xargs -I{} cp {} "$corpus/"
  echo "== $t: ${seconds} s" >&2
  status=0
  build-fuzz/fuzz/"$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix=build-fuzz/findings/"$t"- "$corpus" \
    >build-fuzz/"$t".log 2>&1 || status=$?
  # Executions and coverage reached (cov: edges, ft: features), and any finding.
  grep -E "^#[0-9]+[[:space:]]+(INITED|DONE)|stat::number_of_executed_units|ERROR|SUMMARY|Test unit written" \
    build-fuzz/"$t".log >&2 || true
  if ((status != 0)); then
    echo "$t: FAILED (exit $status); reproducer in build-fuzz/findings/" >&2
    exit 1
  fi
done
