#!/usr/bin/env bash
# Regenerates the committed golden hashes (tests/golden/*.framemd5) from the current build.
# Look at the frames it leaves in build/golden/<name>/out/frames/ before committing the result.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
for timeline in tests/golden/*.toml; do
  name=$(basename "$timeline" .toml)
  work=build/golden/$name
  rm -rf "$work" && mkdir -p "$work"
  cp "$timeline" "$work/t.toml"
  for backend in cpu ${GOLDEN_BACKENDS:-}; do
    (cd "$work" && ../../sdfreel render t.toml --backend "$backend" --out "out-$backend")
    suffix=""; [ "$backend" = cpu ] || suffix=".$backend"
    cp "$work/out-$backend/frames.framemd5" "tests/golden/$name$suffix.framemd5"
    echo "look at: $work/out-$backend/frames/"
  done
done
