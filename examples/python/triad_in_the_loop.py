#!/usr/bin/env python3
"""The on-board computer replaced by ten lines of numpy: TRIAD in the loop of the seed scenario.

The bundled seed_spin system runs twice: once as bundled (the attitude_estimator FMU: the difference
method of paper 000 eq. 5 for the sun and the Q-method), once with the estimator's component given to
a Python function sampled at the same 20 Hz. The function sees only what the FMU sees (the panels'
shunt currents and the magnetometer's voltages through the same 12-bit converters, the reference
vectors) and answers with the FMU's outputs q_est and A_est. Both runs' attitudes are compared with the environment's true attitude.

    PYTHONPATH=python python3 examples/python/triad_in_the_loop.py [--stop-time 10]
"""

import argparse
import math
import pathlib
import sys

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "python"))
import pvatt  # noqa: E402

I_SC0 = 0.84754  # A: one panel's short-circuit current at normal incidence (the estimator's i_sc_norm)
VOLTS_PER_TESLA = 1e4  # the HMC2003's 1 V/gauss


def unit(v):
    return v / np.sqrt(v @ v)


def cross(a, b):  # numpy's np.cross costs ~50 us on 3-vectors (axis handling); this 2 us
    return np.array([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]])


def adc(v, lo, hi, bits=12):
    """The estimator's converters (its adc_bits, i_adc_min/max, v_adc_min/max): what the FMU reads."""
    step = (hi - lo) / (2**bits - 1)
    if isinstance(v, float):
        return lo + round((min(max(v, lo), hi) - lo) / step) * step
    return lo + np.round((np.minimum(np.maximum(v, lo), hi) - lo) / step) * step


def triad(t, x):
    """TRIAD (Black 1964): the sun as the exact direction, the field fixing the rotation about it."""
    i_sh, v_mag, v_ref = adc(x["i_sh"], -1.2, 1.2), adc(x["v_mag"], 0.0, 5.0), adc(x["v_mag_ref"], 0.0, 5.0)
    b1, b2 = unit(i_sh / I_SC0), unit((v_mag - v_ref) / VOLTS_PER_TESLA)
    r1, r2 = unit(x["sun_ref"]), unit(x["mag_ref"])
    b3, r3 = unit(cross(b1, b2)), unit(cross(r1, r2))
    body = np.array([b1, b3, cross(b1, b3)]).T
    ref = np.array([r1, r3, cross(r1, r3)]).T
    A = body @ ref.T  # w_body = A v_ref
    return {"A_est": A.ravel(), "q_est": quaternion(A), "valid": 1.0}


def quaternion(A):
    """Scalar-last [x, y, z, w], w >= 0, of the attitude matrix A (w_body = A v_ref), as the FMU's."""
    trace = A[0, 0] + A[1, 1] + A[2, 2]
    if trace > -0.99:
        w4 = 2.0 * math.sqrt(1.0 + trace)  # 4 w
        return np.array([(A[1, 2] - A[2, 1]) / w4, (A[2, 0] - A[0, 2]) / w4, (A[0, 1] - A[1, 0]) / w4, w4 / 4.0])
    # Near a half-turn: from the largest diagonal term, 4 e_i^2 = 1 + 2 A_ii - trace, A_ij + A_ji = 4 e_i e_j.
    i = int(np.argmax(np.diag(A)))
    j, k = (i + 1) % 3, (i + 2) % 3
    e_i = 0.5 * math.sqrt(max(1.0 + 2.0 * A[i, i] - trace, 0.0))
    q = np.empty(4)
    q[i], q[j], q[k] = e_i, (A[i, j] + A[j, i]) / (4 * e_i), (A[i, k] + A[k, i]) / (4 * e_i)
    q[3] = (A[j, k] - A[k, j]) / (4 * e_i)
    return q if q[3] >= 0 else -q


def angle_deg(q_a, q_b):
    """The rotation between two attitudes given as (n, 4) quaternions, in degrees."""
    dot = np.abs(np.sum(q_a * q_b, axis=1))
    return np.degrees(2.0 * np.arccos(np.clip(dot, 0.0, 1.0)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--stop-time", type=float, default=10.0)
    parser.add_argument("--system", default=str(pathlib.Path(__file__).resolve().parents[2] / "harness/systems/seed_spin.ssd"))
    args = parser.parse_args()

    system = pvatt.System(args.system)
    period = float(system.get("est.sample_period"))
    outputs = ["est.q_est", "env.q_true", "est.valid"]
    # Rows at the estimator's samples: the held estimate beside the truth at the instant it was taken.
    qmethod = system.run(stop_time=args.stop_time, output_interval=period, outputs=outputs)
    system.replace("est", triad, sample_period=period)
    python = system.run(stop_time=args.stop_time, output_interval=period, outputs=outputs)

    print(f"seed_spin, {args.stop_time:g} s, {len(qmethod)} samples at {1 / period:g} Hz: attitude error (deg)")
    print("| on-board computer | median | p95 | max |")
    print("| --- | --- | --- | --- |")
    for name, r in (("attitude_estimator.fmu (Q-method)", qmethod), ("Python TRIAD (numpy, in the loop)", python)):
        ok = r["est.valid"] > 0.5
        e = angle_deg(r["est.q_est"][ok], r["env.q_true"][ok])
        print(f"| {name} | {np.median(e):.3f} | {np.percentile(e, 95):.3f} | {e.max():.3f} |")


if __name__ == "__main__":
    main()
