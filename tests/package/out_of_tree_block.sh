#!/usr/bin/env bash
# Installs this build's runtime package, builds examples/battery_heater against it out of the tree, runs
# the FMI 2.0 and FMI 3.0 conformance suites over the two archives it makes, and checks the heater's first switch-on against
# the closed form of the pack's cooling (the block's own numbers play no part in the expectation).
# Arguments: BUILD_DIR SOURCE_DIR CONFORMANCE_EXE COSIM_EXE WORK_DIR SANITIZE(ON/OFF) CONFORMANCE3_EXE
set -euo pipefail
build=$1 src=$2 conformance=$3 cosim=$4 work=$5 sanitize=$6 conformance3=$7
rm -rf "$work"
cmake --install "$build" --prefix "$work/prefix" > "$work.install.log" 2>&1 || { cat "$work.install.log"; exit 1; }
flags="-Wall -Wextra -Werror"
[ "$sanitize" = ON ] && flags="$flags -fsanitize=address,undefined -fno-sanitize-recover=undefined"
cmake -S "$src/examples/battery_heater" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS="$flags" > "$work.configure.log" 2>&1 ||
  { cat "$work.configure.log"; exit 1; }
cmake --build "$work/build" -j2 > "$work.build.log" 2>&1 || { cat "$work.build.log"; exit 1; }
fmu="$work/build/fmus/battery_heater.fmu"
[ -f "$fmu" ] || { echo "no $fmu"; exit 1; }

PVATT_FMU_DIR="$work/build/fmus" "$conformance" --gtest_brief=1
[ -f "$work/build/fmus3/battery_heater.fmu" ] || { echo "no FMI 3.0 archive in $work/build/fmus3"; exit 1; }
PVATT_FMU_DIR="$work/build/fmus" PVATT_FMU3_DIR="$work/build/fmus3" "$conformance3" --gtest_brief=1

# Cooling from 8 C towards the body's -20 C with tau = C/G = 450/0.05 = 9000 s: T(t) = -20 + 28 exp(-t/tau) C,
# reaching t_on = 5 C at t1 = tau ln(28/25) = 1019.96 s. The run must follow the curve (to the integrator's
# tolerance, 1e-6 relative of ~278 K) and switch the heater on within the output interval after t1.
"$cosim" simulate "$fmu" --stop-time 1100 --output-interval 1 --columns heater_on temperature \
  --output "$work/heater.csv" > /dev/null
python3 - "$work/heater.csv" <<'PY'
import csv, math, sys
rows = [(float(r["time"]), r["heater_on"].strip() in ("1", "true"), float(r["temperature"]))
        for r in csv.DictReader(open(sys.argv[1]))]
tau, t1 = 9000.0, 9000.0 * math.log(28 / 25)
for t, on, temperature in rows:
    if t < t1 - 1:
        closed = 273.15 - 20 + 28 * math.exp(-t / tau)
        assert abs(temperature - closed) < 2e-3, f"t = {t}: {temperature} K, closed form {closed} K"
        assert not on, f"heater on at {t} s, before the closed form's {t1:.2f} s"
first_on = next(t for t, on, _ in rows if on)
assert 0 < first_on - t1 <= 2, f"heater on at {first_on} s, closed form {t1:.2f} s"
print(f"heater on at {first_on} s (closed form {t1:.2f} s)")
PY
