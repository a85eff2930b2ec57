#!/usr/bin/env python3
"""What calling the engine through Python costs (a benchmark, not a test; numbers in README's Speed).

1. seed_spin as bundled (10 s) from Python against `cosim run` (with its CSV, and without output),
   best of --repeat runs each, wall and CPU time. Python's time includes opening the system.
2. leo_orbit with a Python component at 20 Hz in place of the on-board computer (115,280 calls an orbit):
   a function doing nothing (what the bridge itself costs) and the TRIAD of
   examples/python/triad_in_the_loop.py, against the bundled run from Python.

    PYTHONPATH=python python3 python/bench/speed.py [--repeat 3] [--orbit-stop 5764]
"""

import argparse
import os
import pathlib
import resource
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "python"))
sys.path.insert(0, str(ROOT / "examples" / "python"))
import pvatt  # noqa: E402
from triad_in_the_loop import triad  # noqa: E402

COSIM = pathlib.Path(os.environ.get("PVATT_COSIM", ROOT / "build" / "bin" / "cosim"))
SEED = ROOT / "harness/systems/seed_spin.ssd"
ORBIT = ROOT / "harness/systems/leo_orbit.ssd"


def children_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def timed_command(args):
    cpu0, wall0 = children_cpu(), time.perf_counter()
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - wall0, children_cpu() - cpu0


def timed_python(body):
    cpu0, wall0 = time.process_time(), time.perf_counter()
    body()
    return time.perf_counter() - wall0, time.process_time() - cpu0


def best(n, f):
    runs = [f() for _ in range(n)]
    return min(r[0] for r in runs), min(r[1] for r in runs)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--orbit-stop", type=float, default=5764.0)
    args = parser.parse_args()

    with tempfile.TemporaryDirectory() as tmp:
        csv = pathlib.Path(tmp) / "seed.csv"
        cli_csv = best(args.repeat, lambda: timed_command([str(COSIM), "run", str(SEED), "--output", str(csv)]))
        cli_bare = best(args.repeat, lambda: timed_command([str(COSIM), "run", str(SEED)]))
    py_seed = best(args.repeat, lambda: timed_python(lambda: pvatt.System(SEED).run()))
    system = pvatt.System(SEED)
    py_again = best(args.repeat, lambda: timed_python(lambda: system.run()))

    print("seed_spin as bundled, 10 s, every output at the .ssd's interval (best of %d)" % args.repeat)
    print("| run | wall (s) | CPU (s) |")
    print("| --- | --- | --- |")
    for name, (w, c) in (("cosim run --output seed.csv", cli_csv), ("cosim run (no output)", cli_bare),
                         ("Python: System(path).run()", py_seed), ("Python: system.run() again", py_again)):
        print(f"| {name} | {w:.3f} | {c:.3f} |")
    print(f"Python open+run / cosim with CSV: wall {py_seed[0] / cli_csv[0]:.3f}, CPU {py_seed[1] / cli_csv[1]:.3f}")
    print(f"Python open+run / cosim without output: wall {py_seed[0] / cli_bare[0]:.3f}, CPU {py_seed[1] / cli_bare[1]:.3f}")

    orbit = pvatt.System(ORBIT)
    period = float(orbit.get("est.sample_period"))
    runs = [("bundled (attitude_estimator.fmu)", None)]
    runs.append(("Python component doing nothing (the bridge's own cost)", lambda t, x: None))
    runs.append(("Python TRIAD (examples/python/triad_in_the_loop.py)", triad))
    print()
    print(f"leo_orbit, {args.orbit_stop:g} s, the on-board computer's component at {1 / period:g} Hz")
    print("| run | wall (s) | CPU (s) | real-time factor (wall / CPU) | CPU per sample (us) |")
    print("| --- | --- | --- | --- | --- |")
    for name, function in runs:
        calls = [0]
        if function is not None:

            def counted(t, x, function=function):
                calls[0] += 1
                return function(t, x)

            orbit.replace("est", counted, sample_period=period)
        w, c = timed_python(lambda: orbit.run(stop_time=args.orbit_stop))
        per_sample = 1e6 * c / (args.orbit_stop / period)
        print(f"| {name} | {w:.2f} | {c:.2f} | {args.orbit_stop / w:.0f} / {args.orbit_stop / c:.0f} | {per_sample:.0f} |")


if __name__ == "__main__":
    main()
