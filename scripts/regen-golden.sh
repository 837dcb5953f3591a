#!/usr/bin/env bash
# Regenerates the committed golden hashes (tests/golden/*.framemd5) from the current build.
# Look at the frames it leaves in build/golden/<name>/out/frames/ before committing the result.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
# tests/golden/NAME.toml and the per-scene folders tests/golden/SCENE/NAME.toml.
for timeline in tests/golden/*.toml tests/golden/*/*.toml; do
  [ -e "$timeline" ] || continue
  name=${timeline#tests/golden/}
  name=${name%.toml}
  work=build/golden/$name
  rm -rf "$work" && mkdir -p "$work"
  cp "$timeline" "$work/t.toml"
  for backend in cpu ${GOLDEN_BACKENDS:-}; do
    (cd "$work" && "$OLDPWD/build/sdfreel" render t.toml --backend "$backend" --out "out-$backend")
    suffix=""; [ "$backend" = cpu ] || suffix=".$backend"
    cp "$work/out-$backend/frames.framemd5" "tests/golden/$name$suffix.framemd5"
    echo "look at: $work/out-$backend/frames/"
  done
done
