#!/usr/bin/env bash
# quickstart.sh - first command of the README: installs what is missing, builds cdmpm (Release) and runs the
# default scene. Extra arguments go to `cdmpm run` (e.g. --threads 2 --set time.end=0.1).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target cdmpm
./build/cdmpm run scenes/calving_front_2d.json --out output/calving_front_2d "$@"
echo "Open output/calving_front_2d/particles.pvd in ParaView (colour the ice by damage); the wave gauges are in"
echo "output/calving_front_2d/probes.csv, the icebergs in icebergs.csv and the first one in summary.json."
