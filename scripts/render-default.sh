#!/usr/bin/env bash
# The main job on a fresh Debian 13 or 12 machine: install what is missing, build, render the default
# timeline into output/. Extra arguments go to `sdfreel render` (e.g. --resolution 640x360).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
exec build/sdfreel render timelines/lantern_festival.toml "$@"
