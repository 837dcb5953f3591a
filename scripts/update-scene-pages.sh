#!/bin/sh
# Rewrites the generated reference block (camera, passes, parameter table) of every page under
# docs/scenes/ from `sdfreel scenes NAME --markdown`, so the pages say what the code does.
# The test SceneFiles.*HasAPageWhoseReferenceIsTheCodes fails until this has run after a change.
# Usage: scripts/update-scene-pages.sh [BUILD_DIR]   (default build/)
set -eu
cd "$(dirname "$0")/.."
sdfreel="${1:-build}/sdfreel"
for page in docs/scenes/*.md; do
  name=$(basename "$page" .md)
  block=$(mktemp)
  "$sdfreel" scenes "$name" --markdown >"$block"
  # Everything outside the markers stays; a page without them gets the block at its end.
  awk -v block="$block" '
    function put() { while ((getline line < block) > 0) print line; done = 1 }
    /^<!-- begin: sdfreel scenes / { put(); skip = 1; next }
    skip && /^<!-- end: sdfreel scenes / { skip = 0; next }
    !skip { print }
    END { if (!done) { print ""; put() } }' "$page" >"$page.new"
  mv "$page.new" "$page"
  rm -f "$block"
done
