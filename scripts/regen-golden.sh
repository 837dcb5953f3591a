#!/usr/bin/env bash
# Regenerates the committed golden hashes (tests/golden/<scene>/<name>.framemd5) from the current
# build. GOLDEN_BACKENDS="gl" also renders on the GL backend and writes
# <name>.gl.framemd5 where a backend differs from the CPU's hashes (and removes it where it
# agrees: the golden test then holds that backend to the CPU's file). A <name>.gl.framemd5 names
# the Mesa release it was made on ("#mesa: 22.3"); on another Mesa the golden test holds GL frames
# that differ from it to the CPU's by Filament's rule (a mesh pass's rasteriser may change).
# A user's shader's goldens (tests/golden/shader_<example>/) render on GL only, and their
# <name>.framemd5 is the GL's. Look at the frames it leaves in build/golden/ ($BUILD_DIR/golden/ with BUILD_DIR)<scene>/<name>/out-<backend>/frames/ before
# committing the result.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
root=$PWD
build=$(realpath "${BUILD_DIR:-build}")
# Files sdfreel can remake (the lenticular card's source views) stay in the build tree, as in tests.
export SDFREEL_CACHE_DIR=${SDFREEL_CACHE_DIR:-$build/test-cache}
data_lines() { grep -v '^#' "$1"; }
for timeline in tests/golden/*/*.toml; do
  scene=$(basename "$(dirname "$timeline")")
  name=$(basename "$timeline" .toml)
  golden=tests/golden/$scene/$name
  work=$build/golden/$scene/$name
  rm -rf "$work" && mkdir -p "$work"
  # A user's shader (tests/golden/shader_*) has no CPU twin: its <name>.framemd5 is the GL's.
  first=cpu
  [[ $scene == shader_* ]] && first=gl
  backends=$first
  for b in ${GOLDEN_BACKENDS:-}; do [ "$b" = "$first" ] || backends+=" $b"; done
  for backend in $backends; do
    # In place, so that a shader is found beside the timeline where it names it.
    (cd "$work" && "$build/sdfreel" render "$root/$timeline" --backend "$backend" --out "out-$backend")
    hashes=$work/out-$backend/frames.framemd5
    if [[ $backend == "$first" ]]; then
      cp "$hashes" "$golden.framemd5"
    elif [ "$(data_lines "$hashes")" = "$(data_lines "$golden.framemd5")" ]; then
      rm -f "$golden.$backend.framemd5"
    else
      mesa=$(grep -o '"[a-z]*\.mesa": "[0-9]*\.[0-9]*' "$work/out-$backend/manifest.json" | grep -o '[0-9]*\.[0-9]*$')
      { grep '^#' "$hashes"; echo "#mesa: $mesa"; data_lines "$hashes"; } >"$golden.$backend.framemd5"
    fi
    echo "look at: $work/out-$backend/frames/"
  done
done
