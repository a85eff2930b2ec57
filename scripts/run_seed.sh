#!/usr/bin/env bash
# Installs what is missing, builds everything, and runs the seed scenario end to end: the environment
# (seed spin), the six panels with the Sequential Shunt Regulator switching at 5 kHz, the HMC2003 and
# the on-board computer, wired by harness/systems/seed_spin.ssd and run by the master for 10 s.
# Results: results/seed_spin.csv, and the figures in results/ (sun vector real vs acquired, bus
# voltage, attitude error, battery state of charge).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo > /dev/null
cmake --build build -j"$(nproc)"
mkdir -p results
./build/bin/cosim run harness/systems/seed_spin.ssd --stop-time "${SEED_STOP_TIME:-10}" --output results/seed_spin.csv \
  --output-interval 0.01
./build/bin/cosim plot results/seed_spin.csv --out-dir results
