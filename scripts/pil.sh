#!/usr/bin/env bash
# Processor in the loop: the estimator as firmware on an emulated Cortex-M4F (QEMU's mps2-an386), swapped
# in for attitude_estimator.fmu through the hardware bridge, in the seed scenario.
#   bash scripts/pil.sh [cosim run options]   # default: --stop-time 2 --output results/pil.csv
#   bash scripts/pil.sh --bench               # the firmware's figures: instructions per sample, stack
# Installs what is missing (the cross toolchain and QEMU included), builds the firmware, the master and the
# seed system's FMUs, starts QEMU with the firmware's UART on a pseudo-terminal and runs
# harness/systems/seed_spin_pil.ssd with the bridge pointed at it. attitude_estimator/firmware/README.md
# says what runs where.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh --firmware
build=${PVATT_BUILD_DIR:-build}
cmake --preset firmware -B "$build" > /dev/null   # CMakePresets.json
if [ "${1:-}" = "--bench" ]; then
  cmake --build "$build" -j"$(nproc)" --target estimator_firmware
  # -icount shift=0: one instruction per virtual nanosecond, so the firmware's SysTick counts instructions.
  exec qemu-system-arm -M mps2-an386 -nographic -monitor none -serial stdio \
    -semihosting-config enable=on,target=native -icount shift=0 -kernel "$build/firmware/estimator_firmware_bench.elf"
fi
cmake --build "$build" -j"$(nproc)" --target estimator_firmware cosim environment_fmu ssr_plant_fmu magnetometer_fmu \
  attitude_estimator_fmu
log=$(mktemp)
qemu-system-arm -M mps2-an386 -nographic -monitor none -serial pty -kernel "$build/firmware/estimator_firmware.elf" \
  > "$log" 2>&1 < /dev/null &
qemu=$!
trap 'kill $qemu 2>/dev/null; rm -f "$log"' EXIT
pty=""
for _ in $(seq 100); do
  pty=$(grep -o '/dev/pts/[0-9]*' "$log" | head -1 || true)
  [ -n "$pty" ] && break
  sleep 0.05
done
[ -n "$pty" ] || { echo "pil: QEMU named no pseudo-terminal:" >&2; cat "$log" >&2; exit 1; }
echo "pil: the firmware runs on QEMU mps2-an386 (Cortex-M4F), UART0 on $pty"
if [ $# -eq 0 ]; then
  mkdir -p results
  set -- --stop-time 2 --output results/pil.csv
fi
"$build/bin/cosim" run harness/systems/seed_spin_pil.ssd --bridge-device "$pty" "$@"
