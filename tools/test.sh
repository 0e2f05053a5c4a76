#!/usr/bin/env bash
# test.sh - second command of the README (and what CI runs): installs what is missing, builds everything
# (library, program, tests, benchmarks) and runs the test suite with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
# Serial: each test runs cdmpm with all cores (OpenMP); parallel ctest would oversubscribe them.
cd build && ctest --output-on-failure "$@"
