#!/usr/bin/env bash
# Installs what is missing, builds everything, and runs the main job.
# Until the master's seed system lands (issue 6), the main job simulates the HMC2003 magnetometer FMU
# for three seconds in a constant field (Earth-like, 44 µT) with set/reset every second, and prints
# the table of its outputs.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPVATT_BENCHMARKS=OFF > /dev/null
cmake --build build -j"$(nproc)"
echo
./build/bin/cosim info build/fmus/magnetometer.fmu
echo
./build/bin/cosim simulate build/fmus/magnetometer.fmu --stop-time 3 --output-interval 0.25 \
  --set 'mag_body[1]=2.1e-5' --set 'mag_body[2]=-0.5e-5' --set 'mag_body[3]=3.9e-5' --set set_reset_period=1
