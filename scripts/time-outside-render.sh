#!/usr/bin/env bash
# Time outside the render, measured side by side (docs/startup-and-io.md): for each sdfreel binary
# given, a still of a 64x36 frame and a short preview render (PNG + EXR frames, 1 sample) on each
# backend, repeated with the runs interleaved; prints medians of wall and CPU (user + system)
# seconds, and of the frames' own render seconds (manifest.json).
#   scripts/time-outside-render.sh [--reps N] [--timeline T] [--frames 0-23] [--resolution 480x270]
#                                  [--backends cpu,osmesa] BINARY...
# Each binary has a cache folder of its own, warmed by one untimed still first (SDFREEL_CACHE_DIR/N,
# N its place on the command line; by default under a scratch folder here).
set -euo pipefail
reps=3 timeline=timelines/lantern_festival.toml frames=0-23 resolution=480x270 backends=cpu,osmesa
while [[ $# -gt 0 && $1 == --* ]]; do
  case $1 in
    --reps) reps=$2 ;; --timeline) timeline=$2 ;; --frames) frames=$2 ;;
    --resolution) resolution=$2 ;; --backends) backends=$2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
  shift 2
done
[[ $# -ge 1 ]] || { echo "usage: $0 [options] BINARY..." >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
trap 'echo "failed: $BASH_COMMAND" >&2' ERR
# Builds do not share cached textures: in one folder each binary's still rebuilt the other's
# (0.35 s for a still of 0.1).
cache_root=${SDFREEL_CACHE_DIR:-$work/cache}
IFS=, read -r -a backend_list <<< "$backends"

timed() {  # LOG COMMAND...: appends "wall cpu" of one run to LOG
  local log=$1; shift
  /usr/bin/time -f "%e %U %S" -o "$work/t" "$@" > /dev/null 2>&1
  awk '{printf "%s %.3f\n", $1, $2 + $3}' "$work/t" >> "$log"
}
median() {  # column of a file
  sort -n | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'
}

cache_of() { echo "$cache_root/$1"; }
for i in $(seq 1 $#); do
  b=${!i}
  for be in "${backend_list[@]}"; do
    SDFREEL_CACHE_DIR=$(cache_of "$i") "$b" still "$timeline" --time 0 --resolution 64x36 \
      --backend "$be" -o "$work/warm.png" 2>/dev/null
  done
done
for ((r = 0; r < reps; ++r)); do
  for i in $(seq 1 $#); do
    b=${!i}
    for be in "${backend_list[@]}"; do
      SDFREEL_CACHE_DIR=$(cache_of "$i")
      export SDFREEL_CACHE_DIR
      timed "$work/still-$i-$be" "$b" still "$timeline" --time 0 --resolution 64x36 --backend "$be" \
        -o "$work/s.png"
      rm -rf "$work/out"
      timed "$work/run-$i-$be" "$b" render "$timeline" --frames "$frames" --resolution "$resolution" \
        --samples 1 --backend "$be" --out "$work/out"
      python3 -c "import json,sys; m=json.load(open(sys.argv[1]))
for f in m['frames']: print(f['render_seconds'])" "$work/out/manifest.json" >> "$work/frame-$i-$be"
    done
  done
done

echo "timeline $timeline, frames $frames at $resolution, 1 sample, PNG + EXR; medians of $reps runs"
echo
echo "| binary | backend | still 64x36 wall s | still CPU s | run wall s | run CPU s | render s/frame |"
echo "| --- | --- | ---: | ---: | ---: | ---: | ---: |"
for i in $(seq 1 $#); do
  for be in "${backend_list[@]}"; do
    printf "| %s | %s | %s | %s | %s | %s | %s |\n" "${!i}" "$be" \
      "$(cut -d' ' -f1 "$work/still-$i-$be" | median)" "$(cut -d' ' -f2 "$work/still-$i-$be" | median)" \
      "$(cut -d' ' -f1 "$work/run-$i-$be" | median)" "$(cut -d' ' -f2 "$work/run-$i-$be" | median)" \
      "$(median < "$work/frame-$i-$be")"
  done
done
