#!/usr/bin/env python3
"""The sun vector's error against the tumble: its rms and correlation time per body axis, and 1/|rate|.

From the full CSV of a robustness run (`cosim campaign harness/campaigns/robustness.toml --run N`, 1 s rows: time,
est.sun_valid, est.sun_meas[1..3], env.sun_body[1..3], env.omega_body[1..3]): over the longest span of consecutive
rows from --from on with a valid sun vector, the error est.sun_meas - env.sun_body per body axis, its rms and its
correlation time tau (the integral of its normalized autocorrelation up to the first zero crossing, as the bundled
orbit's 51 s was measured; docs/filter.md, "Consistency"), against the span's mean |rate|: MekfConfig's
sun_turn_correlation takes tau = 1/|rate| (docs/filter.md, "The sun's correlation from the tumble"). Needs numpy.
"""
import argparse
import csv
import math

import numpy as np

from calibrated_field_error import normalized_autocorrelation  # one autocorrelation for the study's scripts


def correlation_time(x, dt_row):
    """The integral of the normalized autocorrelation up to its first zero crossing (trapezoid from lag 0)."""
    acf = normalized_autocorrelation(x, unbiased=True)
    if acf is None:
        return 0.0
    below = np.nonzero(acf < 0)[0]
    end = below[0] if len(below) else len(acf)
    return float(acf[:end].sum() * dt_row - 0.5 * dt_row)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv", nargs="+")
    parser.add_argument("--from", dest="start", type=float, default=5900.0, help="s (the campaign's second orbit)")
    args = parser.parse_args()
    print("| run | span (s) | mean rate (deg/s) | 1/rate (s) | rms per axis (rad) | tau per axis (s) | tau x rate |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for name in args.csv:
        rows = list(csv.reader(open(name, newline="")))
        head = rows[0]
        cols = ["time", "est.sun_valid"] + [f"{v}[{k}]" for v in ("est.sun_meas", "env.sun_body", "env.omega_body")
                                            for k in (1, 2, 3)]
        idx = [head.index(c) for c in cols]
        data = np.array([[float(r[i]) if r[i] not in ("", "nan") else np.nan for i in idx] for r in rows[1:]])
        t = data[:, 0]
        ok = (data[:, 1] > 0.5) & (t >= args.start) & np.isfinite(data[:, 2:8]).all(1)
        spans = np.split(np.nonzero(ok)[0], np.nonzero(np.diff(np.nonzero(ok)[0]) > 1)[0] + 1)
        span = max(spans, key=len)
        if len(span) < 3:
            print(f"| {name} | no sunlit span | | | | | |")
            continue
        error = data[span, 2:5] - data[span, 5:8]
        rate = float(np.linalg.norm(data[span, 8:11], axis=1).mean())
        dt_row = float(np.median(np.diff(t[span])))
        rms = np.sqrt(((error - error.mean(0)) ** 2).mean(0))
        taus = [correlation_time(error[:, k], dt_row) for k in range(3)]
        print(f"| {name} | {t[span[0]]:.0f}-{t[span[-1]]:.0f} | {math.degrees(rate):.2f} | {1 / rate:.0f} | " +
              ", ".join(f"{v:.3f}" for v in rms) + " | " + ", ".join(f"{v:.0f}" for v in taus) + " | " +
              ", ".join(f"{v * rate:.2f}" for v in taus) + " |")


if __name__ == "__main__":
    main()
