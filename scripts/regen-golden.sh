#!/usr/bin/env bash
# Regenerates the committed golden hashes (tests/golden/<scene>/<name>.framemd5) from the current
# build. GOLDEN_BACKENDS="gl" also renders on the GL backend and writes
# <name>.gl.framemd5 where a backend differs from the CPU's hashes (and removes it where it
# agrees: the golden test then holds that backend to the CPU's file).
# Look at the frames it leaves in build/golden/<scene>/<name>/out-<backend>/frames/ before
# committing the result.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
root=$PWD
# Files sdfreel can remake (the lenticular card's source views) stay in the build tree, as in tests.
export SDFREEL_CACHE_DIR=${SDFREEL_CACHE_DIR:-$root/build/test-cache}
data_lines() { grep -v '^#' "$1"; }
for timeline in tests/golden/*/*.toml; do
  scene=$(basename "$(dirname "$timeline")")
  name=$(basename "$timeline" .toml)
  golden=tests/golden/$scene/$name
  work=build/golden/$scene/$name
  rm -rf "$work" && mkdir -p "$work"
  cp "$timeline" "$work/t.toml"
  for backend in cpu ${GOLDEN_BACKENDS:-}; do
    (cd "$work" && "$root/build/sdfreel" render t.toml --backend "$backend" --out "out-$backend")
    hashes=$work/out-$backend/frames.framemd5
    if [ "$backend" = cpu ]; then
      cp "$hashes" "$golden.framemd5"
    elif [ "$(data_lines "$hashes")" = "$(data_lines "$golden.framemd5")" ]; then
      rm -f "$golden.$backend.framemd5"
    else
      cp "$hashes" "$golden.$backend.framemd5"
    fi
    echo "look at: $work/out-$backend/frames/"
  done
done
