#!/usr/bin/env bash
# The mesh-method comparison in one command (docs/mesh-method.md): installs Embree 3 from Debian
# besides sdfreel's own packages, builds tools/mesh_method_bench into build/ and runs it with the
# arguments given (mesh_method_bench --help lists them; none: docs/mesh-method.md's full table).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --embree
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DSDFREEL_WITH_EMBREE=ON >/dev/null
cmake --build build --target mesh_method_bench -j "$(nproc)"
exec build/tools/mesh_method_bench/mesh_method_bench "$@"
