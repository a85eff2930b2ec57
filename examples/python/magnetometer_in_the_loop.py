#!/usr/bin/env python3
"""A stateful Python sensor in the loop: the HMC2003 magnetometer of leo_orbit as a Python class.

The bundled orbit's `mag` component is given to a Python object sampled at the on-board computer's 20 Hz.
The object keeps state between calls (what a Python component must do itself: the component is stateless
to the master, docs/python.md): a first-order filter of the field (the sensor's bandwidth, here a time
constant), seeded noise drawn once per sample, and the set/reset polarity. The on-board computer pulses
set/reset every sample and reads the field in the polarity it commanded at that instant, so the sensor is
replaced with current_inputs=True: called again once the computer has commanded (docs/python.md, "Order at
a shared instant"); with one call per instant it would answer with the previous command and the field
would come out reversed. The run prints the angle between the computer's measured field and the truth.

    PYTHONPATH=python python3 examples/python/magnetometer_in_the_loop.py [--stop-time 60] [--once]
"""

import argparse
import pathlib
import sys

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "python"))
import pvatt  # noqa: E402

VOLTS_PER_TESLA = 1e4  # the HMC2003's 1 V/gauss


class Magnetometer:
    """Each axis 2.5 V + polarity x 1 V/gauss x (filtered field + noise); the polarity follows the
    set/reset command (true: set, +1), as the FMU's does."""

    def __init__(self, time_constant=0.01, noise_tesla=20e-9, seed=1):
        self.tau = time_constant
        self.rng = np.random.default_rng(seed)
        self.noise_tesla = noise_tesla
        self.field = None  # the filter's state, tesla
        self.last_t = None
        self.noise = np.zeros(3)

    def step(self, t, x):
        b = np.asarray(x["mag_body"])
        if self.field is None:
            self.field = b.copy()
        elif t != self.last_t:  # a new instant: advance the filter and draw new noise (not on a repeat call)
            a = np.exp(-(t - self.last_t) / self.tau)
            self.field = a * self.field + (1.0 - a) * b
            self.noise = self.rng.normal(0.0, self.noise_tesla, 3)
        self.last_t = t
        polarity = 1.0 if x["set_reset_command"] > 0.5 else -1.0
        return {"v_out": 2.5 + polarity * VOLTS_PER_TESLA * (self.field + self.noise), "v_ref": 2.5}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--stop-time", type=float, default=60.0)
    ap.add_argument("--once", action="store_true", help="one call per instant (shows the reversed field)")
    args = ap.parse_args()
    system = pvatt.System(ROOT / "harness" / "systems" / "leo_orbit.ssd")
    # This sensor reads the earth's field alone, without the spacecraft's own (the FMU adds the residual
    # dipole's 7.3 uT at the sensor). The scenario's dipole_moment feeds the truth's magnetic torque and the
    # computer's uplinked ground calibration, which would take out 7.3 uT that is not there (12 deg off):
    # the spacecraft flown here has no residual dipole. Nor does it read the cell strings' field, which the
    # computer would otherwise take out of its reading (est.mag_string_field; about 1 uT in sunlight).
    system.set("dipole_moment", [0.0, 0.0, 0.0])
    system.set("est.mag_string_field", False)
    sensor = Magnetometer()
    system.replace("mag", sensor, sample_period=0.05, current_inputs=not args.once)
    r = system.run(stop_time=args.stop_time, output_interval=0.05, outputs=["est.mag_field", "env.mag_body"])
    b_est, b_true = r["est.mag_field"][1:], r["env.mag_body"][1:]
    cosine = np.sum(b_est * b_true, axis=1) / (np.linalg.norm(b_est, axis=1) * np.linalg.norm(b_true, axis=1))
    angle = np.degrees(np.arccos(np.clip(cosine, -1.0, 1.0)))
    print(f"{len(angle)} samples over {args.stop_time:g} s, {'one call' if args.once else 'current inputs'}: "
          f"measured field against the truth median {np.median(angle):.3f} deg, max {angle.max():.3f} deg")


if __name__ == "__main__":
    main()
