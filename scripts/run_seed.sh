#!/usr/bin/env bash
# Installs what is missing, builds what the seed run needs (the master and the four FMUs of the seed
# system, not the tests and benchmarks), and runs the seed scenario end to end: the environment
# (seed spin), the six panels with the Sequential Shunt Regulator switching at 5 kHz, the HMC2003 and
# the on-board computer, wired by harness/systems/seed_spin.ssd and run by the master for 10 s.
# Results: results/seed_spin.csv, and the figures in results/ (sun vector real vs acquired, bus
# voltage, attitude error, battery state of charge).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
cmake --preset release > /dev/null   # CMakePresets.json
cmake --build build -j"$(nproc)" --target cosim environment_fmu ssr_plant_fmu magnetometer_fmu attitude_estimator_fmu pvatt_cosim
mkdir -p results
# The run, its statistics and parameters kept for results/index.html.
./build/bin/cosim run harness/systems/seed_spin.ssd --stop-time "${SEED_STOP_TIME:-10}" --output results/seed_spin.csv \
  --output-interval 0.01 | tee results/run_statistics.txt
{ echo; echo "The system (each component's bound parameters; the FMUs' defaults otherwise):"
  ./build/bin/cosim info harness/systems/seed_spin.ssd
} >> results/run_statistics.txt
# A close-up of the bus over its first 0.2 s, every 5 us: the ripple of the 5 kHz PWM (results/ripple/). The
# reference execution runs the plant in Model Exchange: the bundled one steps it in 1 ms Co-Simulation steps,
# and its outputs between them are held.
./build/bin/cosim run harness/systems/seed_spin.ssd --reference --stop-time 0.2 --output results/seed_spin_ripple.csv \
  --output-interval 5e-6 --columns plant.v_bus > /dev/null
./build/bin/cosim plot results/seed_spin_ripple.csv --out-dir results/ripple
# The system as a picture (Graphviz): results/system_diagram.svg, shown on the page with the figures.
./build/bin/cosim info harness/systems/seed_spin.ssd --diagram results/system_diagram > /dev/null
./build/bin/cosim plot results/seed_spin.csv --out-dir results   # last: its index.html lists every figure
