#!/usr/bin/env bash
# Installs this build's package, builds examples/battery_heater and examples/run_system against it out of
# the tree, runs examples/run_system/heater.ssd (the heater's pack, heat capacity bound to 900 J/K by the
# .ssd) on the installed engine and checks the pack's temperature against the closed form of its cooling
# (the block's and the engine's numbers play no part in the expectation).
# Arguments: BUILD_DIR SOURCE_DIR WORK_DIR SANITIZE(ON/OFF)
set -euo pipefail
build=$1 src=$2 work=$3 sanitize=$4
rm -rf "$work"
cmake --install "$build" --prefix "$work/prefix" > "$work.install.log" 2>&1 || { cat "$work.install.log"; exit 1; }
flags="-Wall -Wextra -Werror"
[ "$sanitize" = ON ] && flags="$flags -fsanitize=address,undefined -fno-sanitize-recover=undefined"
for example in battery_heater run_system; do
  cmake -S "$src/examples/$example" -B "$work/$example" -DCMAKE_PREFIX_PATH="$work/prefix" \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS="$flags" > "$work.$example.configure.log" 2>&1 ||
    { cat "$work.$example.configure.log"; exit 1; }
  cmake --build "$work/$example" -j2 > "$work.$example.build.log" 2>&1 || { cat "$work.$example.build.log"; exit 1; }
done

# Cooling from 8 C towards the body's -20 C with tau = C/G = 900/0.05 = 18000 s, the heater off until
# 5 C (t = tau ln(28/25) = 2040 s): T(1000 s) = -20 + 28 exp(-1000/18000) C, to the integrator's
# tolerance (1e-6 relative of ~278 K).
out=$("$work/run_system/run_system" "$src/examples/run_system/heater.ssd" 1000 heater.temperature \
  "$work/battery_heater/fmus")
echo "$out"
python3 - "$out" <<'PY'
import math, sys
value = float(sys.argv[1].split("=")[1])
closed = 273.15 - 20 + 28 * math.exp(-1000 / 18000)
assert abs(value - closed) < 2e-3, f"{value} K at 1000 s, closed form {closed} K"
print(f"temperature at 1000 s {value:.6f} K (closed form {closed:.6f} K)")
PY
