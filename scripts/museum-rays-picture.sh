#!/usr/bin/env bash
# docs/museum_rays.png: seed 004's comparison picture, the museum's default shot at 2 s without
# the crepuscular rays (rays_strength = 0) beside it with them, at 640x360 each.
#   scripts/museum-rays-picture.sh [OUT.png]   (build first: scripts/build.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/museum_rays.png}
sdfreel=${SDFREEL:-build/sdfreel}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The same timeline with the rays off: rays_strength added under [params].
sed 's/^\[params\]$/[params]\nrays_strength = 0.0/' timelines/museum.toml > "$work/no_rays.toml"
"$sdfreel" still "$work/no_rays.toml" --time 2 --resolution 640x360 -o "$work/without.png"
"$sdfreel" still timelines/museum.toml --time 2 --resolution 640x360 -o "$work/with.png"
ffmpeg -loglevel error -y -i "$work/without.png" -i "$work/with.png" \
  -filter_complex hstack -pix_fmt rgb24 "$out"
echo "wrote $out"
