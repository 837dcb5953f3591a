#!/usr/bin/env bash
# Set-up plus the whole test suite (unit, integration, golden hashes, fault injection), a short
# fuzzing run of each libFuzzer target and the cheap subset of the build matrix: what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --test
# The Slurm test's daemons (munge, slurmctld, slurmd); the test starts and stops its own cluster.
scripts/slurm-local.sh install
scripts/build.sh
cd build
ctest --output-on-failure -j "$(nproc)" --timeout 900
cd ..
# About 3 minutes of clang builds plus 25 s a target: crashes, hangs and sanitizer reports fail CI.
scripts/fuzz.sh 25
# clang++ -O2 on the baseline instruction set must render the golden timelines bit for bit.
scripts/build-matrix.sh --ci
