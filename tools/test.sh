#!/usr/bin/env bash
# test.sh - second command of the README (and what CI runs): installs what is missing, builds everything
# (library, program, tests, benchmarks) and runs the test suite with ctest; then builds the program with MPI
# (build-mpi, -DCDMPM_MPI=ON) and runs the distributed-run tests (ctest -L mpi), whose reference is build/cdmpm.
# Arguments go to the first ctest (e.g. -R NAME); CDMPM_SKIP_MPI=1 skips the MPI part.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
# Serial: each test runs cdmpm with all cores (OpenMP); parallel ctest would oversubscribe them.
(cd build && ctest --output-on-failure "$@")
if [ "${CDMPM_SKIP_MPI:-0}" != 1 ]; then
  cmake -S . -B build-mpi -DCMAKE_BUILD_TYPE=Release -DCDMPM_MPI=ON -DCDMPM_BUILD_BENCH=OFF >/dev/null
  cmake --build build-mpi -j"$(nproc)" --target cdmpm
  (cd build-mpi && ctest --output-on-failure -L mpi)
fi
