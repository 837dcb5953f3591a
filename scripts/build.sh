#!/usr/bin/env bash
# Configures and builds sdfreel (Release) into build/, or into $BUILD_DIR (another release's
# chroot sharing this tree keeps its own).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$(nproc)"
