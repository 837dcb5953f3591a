#!/usr/bin/env bash
# Set-up plus the whole test suite (unit, integration, golden hashes): what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
# The Slurm test's daemons (munge, slurmctld, slurmd); the test starts and stops its own cluster.
scripts/slurm-local.sh install
scripts/build.sh
cd build
ctest --output-on-failure -j "$(nproc)" --timeout 900
