#!/usr/bin/env bash
# The operations one evaluation of a scene's distance function costs in lanes, counted from the
# machine code that runs: `sdfreel bench --micro SCENE --only FUNCTION` under callgrind, collecting
# only inside the lanes' timed pass (evaluate_lanes_pass in src/bench/micro_bench.cpp), every
# executed instruction weighed by how often it ran and classified by its mnemonic from objdump.
# Counts, not seconds: the same binary gives the same numbers on a busy machine.
#
#   scripts/count-flops.sh [--build DIR] SCENE FUNCTION [SCENE FUNCTION ...]
#
# Prints one Markdown row per function, all per evaluation (per point: an eight-lane instruction
# counts an eighth): instructions; floating-point operations (add, sub, mul, div, sqrt, each lane
# counted; an FMA would count two), of which divisions and square roots; min/max lanes; and other
# vector instructions (compares, selects, logic, conversions, shuffles).
# Needs valgrind and objdump (binutils).
set -euo pipefail

build=build
if [[ "${1:-}" == --build ]]; then
  build=$2
  shift 2
fi
if (($# == 0 || $# % 2 != 0)); then
  echo "usage: $0 [--build DIR] SCENE FUNCTION [SCENE FUNCTION ...]" >&2
  exit 2
fi
binary=$(realpath "$build/sdfreel")
for tool in valgrind objdump; do
  command -v "$tool" >/dev/null || {
    echo "$0: needs $tool" >&2
    exit 2
  }
done

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Each instruction's address and mnemonic, with its operands (the width comes from the registers).
objdump -d --no-show-raw-insn "$binary" |
  awk -F'\t' '/^ +[0-9a-f]+:\t/ { sub(/^ +/, "", $1); sub(/:$/, "", $1); print $1 "\t" $2 }' \
    >"$work/instructions.tsv"

echo "| scene | function | instructions | flops | of which div | sqrt | min, max | other vector |"
echo "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |"
while (($# > 0)); do
  scene=$1 function=$2
  shift 2
  valgrind --tool=callgrind --dump-instr=yes --compress-pos=no --compress-strings=no \
    --collect-atstart=no '--toggle-collect=*evaluate_lanes_pass*' \
    --callgrind-out-file="$work/callgrind.out" \
    "$binary" bench --micro "$scene" --only "$function" --repetitions 1 --micro-min-time 0.001 \
    --out "$work/bench" >"$work/bench.log" 2>&1 || {
    cat "$work/bench.log" >&2
    exit 1
  }
  points=$(sed -n 's/.* \([0-9]*\) points$/\1/p' "$work/bench.log" | head -1)
  # callgrind's lines for the binary: "0xADDR LINE COUNT"; the line after "calls=" is a call's
  # inclusive cost, already counted inside the callee, so it is skipped.
  awk -v bin="ob=$binary" '
    /^ob=/ { in_bin = ($0 == bin) }
    /^calls=/ { skip = 1; next }
    /^0x/ { if (skip) { skip = 0; next } if (in_bin) count[substr($1, 3)] += $3; next }
    END { for (a in count) print a "\t" count[a] }
  ' "$work/callgrind.out" >"$work/counts.tsv"
  passes=$(awk '/^fn=.*evaluate_lanes_pass/ { getline; print $3; exit }' "$work/callgrind.out")
  awk -F'\t' -v scene="$scene" -v fn="$function" -v evals=$((passes * points)) '
    FNR == NR { count[$1] = $2; next }
    !($1 in count) { next }
    {
      n = count[$1]; split($2, part, / +/); m = part[1]; ops = $2
      instructions += n
      lanes = 1
      if (m ~ /ps$/) lanes = (ops ~ /%ymm/) ? 8 : 4
      else if (m ~ /pd$/) lanes = (ops ~ /%ymm/) ? 4 : 2
      if (m ~ /^v?(add|sub|mul|div|sqrt)(ps|pd|ss|sd)$/) flops += n * lanes
      else if (m ~ /^vf(n?)m(add|sub)/) flops += 2 * n * lanes
      else if (m ~ /^v?(min|max)(ps|pd|ss|sd)$/) minmax += n * lanes
      else if (ops ~ /%[xy]mm/) other += n
      if (m ~ /^v?div(ps|pd|ss|sd)$/) div += n * lanes
      if (m ~ /^v?sqrt(ps|pd|ss|sd)$/) sqrt_ += n * lanes
    }
    END {
      printf "| %s | %s | %.1f | %.1f | %.2f | %.2f | %.1f | %.1f |\n", scene, fn,
        instructions / evals, flops / evals, div / evals, sqrt_ / evals, minmax / evals,
        other / evals
    }
  ' "$work/counts.tsv" "$work/instructions.tsv"
done
