#!/usr/bin/env bash
# test.sh - second command of the README (and what CI runs): installs what is missing, builds everything
# (library, program, tests, benchmarks) and runs the test suite with ctest; then builds the program with MPI
# (build-mpi, -DCDMPM_MPI=ON) and runs the distributed-run tests (ctest -L mpi), whose reference is build/cdmpm.
# Arguments go to the first ctest (e.g. -R NAME); CDMPM_SKIP_MPI=1 skips the MPI part.
# Each phase ends with a line "test.sh: PHASE took N s" (the CI budget, 20 minutes: docs/testing.md).
set -euo pipefail
cd "$(dirname "$0")/.."
phase() { echo "test.sh: $1 took $((SECONDS - start)) s"; start=$SECONDS; }
start=$SECONDS
bash tools/install_deps.sh
phase "installing dependencies"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
phase "building"
# Serial: each test runs cdmpm with all cores (OpenMP); parallel ctest would oversubscribe them.
(cd build && ctest --output-on-failure "$@")
phase "the test suite"
if [ "${CDMPM_SKIP_MPI:-0}" != 1 ]; then
  cmake -S . -B build-mpi -DCMAKE_BUILD_TYPE=Release -DCDMPM_MPI=ON -DCDMPM_BUILD_BENCH=OFF >/dev/null
  cmake --build build-mpi -j"$(nproc)" --target cdmpm
  phase "building with MPI"
  (cd build-mpi && ctest --output-on-failure -L mpi)
  phase "the MPI tests"
fi
