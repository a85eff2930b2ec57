#!/usr/bin/env python3
"""The calibrated field's error against the truth per phase, and the white-noise sigma it is worth.

From a CSV of a leo_orbit run (1 s rows, columns time, est.mag_field[1..3], est.mag_cal_valid, env.mag_body[1..3],
env.irradiance): over the rows from --from on where the in-flight calibration applies, per phase (env.irradiance
> 0: sunlit), the error est.mag_field - env.mag_body per body axis: its mean, rms, and 1/e correlation time tau
(of the error less its mean), and the white noise of the same information at the filter's --dt, sigma
sqrt(2 tau / dt) with sigma the rms (docs/filter.md, "Consistency"). Needs numpy.
"""
import argparse
import csv

import numpy as np


def normalized_autocorrelation(x, unbiased=False):
    """The autocorrelation of x less its mean at lags 0..n-1, 1 at lag 0 (None for a constant or short x);
    unbiased: each lag's sum divided by its number of products."""
    x = x - x.mean()
    n = len(x)
    if n < 3 or not np.any(x):
        return None
    f = np.fft.rfft(x, 2 * n)
    acf = np.fft.irfft(f * np.conj(f))[:n]
    if unbiased:
        acf = acf / np.arange(n, 0, -1)
    return acf / acf[0]


def correlation_time(x, dt_row):
    acf = normalized_autocorrelation(x)
    if acf is None:
        return 0.0
    below = np.nonzero(acf < np.exp(-1.0))[0]
    return float(below[0]) * dt_row if len(below) else float(len(x)) * dt_row


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv")
    parser.add_argument("--from", dest="start", type=float, default=5764.0)
    parser.add_argument("--dt", type=float, default=0.05, help="the filter's field update period, s")
    parser.add_argument("--smooth", type=int, default=10, help="rows in the slow part's running mean")
    args = parser.parse_args()
    rows = list(csv.reader(open(args.csv, newline="")))
    head = rows[0]
    data = np.array([[float(x) if x not in ("", "nan") else np.nan for x in r] for r in rows[1:]])
    col = lambda name: data[:, head.index(name)]
    vec = lambda name: np.stack([col(f"{name}[{k}]") for k in (1, 2, 3)], 1)
    t = col("time")
    error = vec("est.mag_field") - vec("env.mag_body")
    usable = (t >= args.start) & (col("est.mag_cal_valid") > 0) & np.isfinite(error).all(1)
    sunlit = col("env.irradiance") > 0
    dt_row = float(np.median(np.diff(t)))
    for phase, keep in (("sunlit", sunlit), ("eclipse", ~sunlit)):
        r = usable & keep
        # The longest run of consecutive rows for the correlation time (a phase comes in spans).
        idx = np.nonzero(r)[0]
        if len(idx) == 0:
            print(f"{phase}: no rows")
            continue
        breaks = np.nonzero(np.diff(idx) > 1)[0]
        spans = np.split(idx, breaks + 1)
        e = error[r] * 1e9
        mean, rms = e.mean(0), np.sqrt((e * e).mean(0))
        taus = []
        for k in range(3):
            w = [len(s) for s in spans]
            taus.append(sum(correlation_time(error[s, k], dt_row) * len(s) for s in spans) / sum(w))
        white = [rms[k] * 1e-3 * np.sqrt(2 * taus[k] / args.dt) for k in range(3)]
        print(f"{phase}: {r.sum()} rows in {len(spans)} spans; mean " + ", ".join(f"{v:.0f}" for v in mean) +
              " nT; rms " + ", ".join(f"{v:.0f}" for v in rms) + " nT; tau " + ", ".join(f"{v:.0f}" for v in taus) +
              " s; white-equivalent " + ", ".join(f"{v:.1f}" for v in white) + " uT")
        # The same split into a slow part (the mean over --smooth rows, within each span) and the rest (the
        # sensor's noise, white at the rows' rate): the slow part's white equivalent is what the weight is for.
        slow = np.full_like(error, np.nan)
        kernel = np.ones(args.smooth) / args.smooth
        for s in spans:
            if len(s) < args.smooth:
                continue
            for k in range(3):
                slow[s, k] = np.convolve(error[s, k], kernel, mode="same")
        ok = r & np.isfinite(slow).all(1)
        fast = (error[ok] - slow[ok]) * 1e9
        rms_slow = np.sqrt(((slow[ok] * 1e9) ** 2).mean(0))
        tau_slow = []
        for k in range(3):
            parts = [s[np.isfinite(slow[s, k])] for s in spans if len(s) >= args.smooth]
            tau_slow.append(sum(correlation_time(slow[p, k], dt_row) * len(p) for p in parts) /
                            sum(len(p) for p in parts))
        white_slow = [rms_slow[k] * 1e-3 * np.sqrt(2 * tau_slow[k] / args.dt) for k in range(3)]
        print(f"  slow part ({args.smooth} s mean): rms " + ", ".join(f"{v:.0f}" for v in rms_slow) + " nT, tau " +
              ", ".join(f"{v:.0f}" for v in tau_slow) + " s, white-equivalent " +
              ", ".join(f"{v:.1f}" for v in white_slow) + " uT; the rest rms " +
              ", ".join(f"{v:.0f}" for v in np.sqrt((fast ** 2).mean(0))) + " nT")


if __name__ == "__main__":
    main()
