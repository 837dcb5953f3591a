#!/usr/bin/env bash
# Set-up plus the whole test suite (unit, integration, golden hashes): what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
cd build
ctest --output-on-failure -j "$(nproc)" --timeout 900
