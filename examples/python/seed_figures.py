#!/usr/bin/env python3
"""The seed run's figures (scripts/run_seed.sh, `cosim plot`) drawn from Python with matplotlib:
the sun vector in body axes, real and acquired (seed 000 fig. 8), the sun and attitude errors at the
estimator's samples, the bus voltage (000 fig. 9) and its 5 kHz ripple, the battery's state of charge.

    PYTHONPATH=python python3 examples/python/seed_figures.py [--stop-time 10] [--out-dir results/python]
"""

import argparse
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "python"))
import pvatt  # noqa: E402


def sample_rows(r):
    """The rows at which the estimator took a new sample (its `samples` count went up) while valid."""
    n = r["est.samples"]
    return np.flatnonzero((np.diff(n, prepend=n[0] - 1) > 0) & (r["est.valid"] > 0.5))


def angle_deg(a, b):
    """The angle between rows of two (n, 3) vector arrays, in degrees."""
    c = np.sum(a * b, axis=1) / (np.linalg.norm(a, axis=1) * np.linalg.norm(b, axis=1))
    return np.degrees(np.arccos(np.clip(c, -1.0, 1.0)))


def quaternion_angle_deg(p, q):
    return np.degrees(2.0 * np.arccos(np.clip(np.abs(np.sum(p * q, axis=1)), 0.0, 1.0)))


def save(fig, out_dir, name):
    path = out_dir / f"{name}.png"
    fig.savefig(path, dpi=100)
    plt.close(fig)
    print(path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--stop-time", type=float, default=10.0)
    parser.add_argument("--out-dir", default=str(ROOT / "results" / "python"))
    args = parser.parse_args()
    out_dir = pathlib.Path(args.out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)

    system = pvatt.System(ROOT / "harness/systems/seed_spin.ssd")
    r = system.run(
        stop_time=args.stop_time,
        output_interval=0.01,
        outputs=["env.sun_body", "est.sun_meas", "est.sun_valid", "est.valid", "est.samples", "env.q_true",
                 "est.q_est", "plant.v_bus", "plant.soc"],
    )
    t, rows = r.time, sample_rows(r)

    real, acquired = r["env.sun_body"], r["est.sun_meas"]
    for k, axis in enumerate("xyz"):
        fig, ax = plt.subplots(figsize=(11, 6))
        ax.plot(t, real[:, k], label=f"real s{axis}")
        ax.plot(t[rows], acquired[rows, k], ".", label=f"acquired s{axis}")
        ax.set(title=f"Sun vector, body {axis}: real and acquired (seed 000 fig. 8)", xlabel="time (s)",
               ylabel="component")
        ax.legend()
        save(fig, out_dir, f"sun_vector_{axis}")

    for name, title, error in (
        ("sun_error", "Sun vector error at the estimator samples (while valid)",
         angle_deg(acquired[rows], real[rows])),
        ("attitude_error", "Attitude error at the estimator samples (while valid)",
         quaternion_angle_deg(r["est.q_est"][rows], r["env.q_true"][rows])),
    ):
        fig, ax = plt.subplots(figsize=(11, 6))
        ax.plot(t[rows], error, ".", label=f"median {np.median(error):.3f} deg, p95 {np.percentile(error, 95):.3f} deg")
        ax.set(title=title, xlabel="time (s)", ylabel="degrees")
        ax.legend()
        save(fig, out_dir, name)

    fig, ax = plt.subplots(figsize=(11, 6))
    ax.plot(t, r["plant.v_bus"])
    ax.set(title="Bus voltage (seed 000 fig. 9)", xlabel="time (s)", ylabel="V")
    save(fig, out_dir, "bus_voltage")

    # The ripple: the switching plant in Model Exchange (the reference execution) every 5 us for 0.2 s,
    # the last millisecond drawn, as scripts/run_seed.sh's close-up.
    ripple = system.run(stop_time=0.2, output_interval=5e-6, outputs=["plant.v_bus"], reference=True)
    last = ripple.time >= ripple.time[-1] - 1e-3
    fig, ax = plt.subplots(figsize=(11, 6))
    ax.plot(ripple.time[last] * 1e3, ripple["plant.v_bus"][last])
    ax.set(title="Bus voltage ripple over the last millisecond (PWM at 5 kHz)", xlabel="time (ms)", ylabel="V")
    save(fig, out_dir, "bus_ripple")

    fig, ax = plt.subplots(figsize=(11, 6))
    ax.plot(t, r["plant.soc"])
    ax.set(title="Battery state of charge", xlabel="time (s)", ylabel="1")
    save(fig, out_dir, "battery_soc")


if __name__ == "__main__":
    main()
