#!/usr/bin/env python3
"""The `--set` arguments that move leo_orbit.ssd to another orbit, date and start, consistently (issue 39).

The truth's element set (a synthetic near-circular set: inclination, node from a local time of the ascending
node or given, mean motion from the altitude, at the argument of latitude 0 at its epoch), the environment's
epoch at the set's epoch, the on-board computer's set 24 h older (older_tle.py), its clock in step and its
`orbit_altitude` over its 6371 km Earth from the set's semi-major axis; the start attitude uniform over all
rotations and the tumble in a uniform direction, from a seed. Prints one `--set` argument a line. Standard
library only.

  scene.py --inclination sso --ltan 12 --date 2026-06-21 --altitude 550 --tumble 2.9 --seed 1
"""
import argparse
import datetime
import math
import os
import random
import subprocess
import sys

MU = 398600.4418  # km^3/s^2
RE = 6378.137  # km, WGS-84 equatorial
J2 = 1.08262668e-3
EARTH_SPHERE = 6371.0  # km: the on-board computer's Earth (harness/systems/README.md)


def checksum(line):
    return sum(int(c) if c.isdigit() else (1 if c == "-" else 0) for c in line[:68]) % 10


def sun_right_ascension(when):
    """Low-precision solar right ascension (deg), Astronomical Almanac, good to 0.01 deg."""
    jd = (when - datetime.datetime(2000, 1, 1, 12)).total_seconds() / 86400.0
    l = math.radians((280.460 + 0.9856474 * jd) % 360)
    g = math.radians((357.528 + 0.9856003 * jd) % 360)
    lam = l + math.radians(1.915) * math.sin(g) + math.radians(0.020) * math.sin(2 * g)
    eps = math.radians(23.439 - 4e-7 * jd)
    return math.degrees(math.atan2(math.cos(eps) * math.sin(lam), math.cos(lam))) % 360


def sso_inclination(a):
    """The inclination whose J2 node rate follows the mean sun (360 deg per 365.2422 days)."""
    rate = 2 * math.pi / (365.2422 * 86400)
    n = math.sqrt(MU / a**3)
    c = -rate / (1.5 * J2 * (RE / a) ** 2 * n)
    return math.degrees(math.acos(c))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--inclination", default="64.9", help="deg, or 'sso'")
    ap.add_argument("--ltan", type=float, help="local time of the ascending node (h); else --raan")
    ap.add_argument("--raan", type=float, default=0.0, help="deg")
    ap.add_argument("--date", default="2026-03-20", help="UTC epoch, YYYY-MM-DD[THH:MM]")
    ap.add_argument("--altitude", type=float, default=570.0, help="km above 6378.137 km")
    ap.add_argument("--tumble", type=float, help="deg/s, uniform direction (default: keep env.omega0)")
    ap.add_argument("--seed", type=int, help="random start attitude (and tumble direction) from this seed")
    ap.add_argument("--noise-seed", type=int, help="mag.noise_seed")
    a = ap.parse_args()
    when = datetime.datetime.fromisoformat(a.date)
    r = RE + a.altitude
    inc = sso_inclination(r) if a.inclination == "sso" else float(a.inclination)
    raan = a.raan if a.ltan is None else (sun_right_ascension(when) + (a.ltan - 12.0) * 15.0) % 360
    n = math.sqrt(MU / r**3) * 86400 / (2 * math.pi)  # rev/day
    year = when.year % 100
    doy = when.timetuple().tm_yday + (when.hour * 3600 + when.minute * 60 + when.second) / 86400.0
    l1 = f"1 90001U          {year:02d}{doy:012.8f}  .00002000  00000-0  15000-3 0  999"
    l2 = f"2 90001 {inc:8.4f} {raan:8.4f} 0012000  90.0000 270.0000 {n:11.8f}  100"
    l1 += str(checksum(l1))
    l2 += str(checksum(l2))
    here = os.path.dirname(os.path.abspath(__file__))
    older = subprocess.run([sys.executable, os.path.join(here, "older_tle.py"), l1, l2, "--hours", "24"],
                           check=True, capture_output=True, text=True).stdout.split("\n")
    out = [f"env.tle_line1={l1}", f"env.tle_line2={l2}", f"est.tle_line1={older[0]}", f"est.tle_line2={older[1]}"]
    for side, prefix in (("env", "epoch"), ("est", "clock_epoch")):
        out += [f"{side}.{prefix}_year={when.year}", f"{side}.{prefix}_month={when.month}",
                f"{side}.{prefix}_day={when.day}", f"{side}.{prefix}_hour={when.hour}",
                f"{side}.{prefix}_minute={when.minute}"]
    out.append(f"est.orbit_altitude={(r - EARTH_SPHERE) * 1e3:.0f}")
    if a.seed is not None:
        g = random.Random(a.seed)
        u1, u2, u3 = g.random(), g.random(), g.random()  # Shoemake's uniform rotation
        q = (math.sqrt(1 - u1) * math.sin(2 * math.pi * u2), math.sqrt(1 - u1) * math.cos(2 * math.pi * u2),
             math.sqrt(u1) * math.sin(2 * math.pi * u3), math.sqrt(u1) * math.cos(2 * math.pi * u3))
        out += [f"env.q0[{i + 1}]={q[i]!r}" for i in range(4)]
        if a.tumble is not None:
            z = 2 * g.random() - 1
            phi = 2 * math.pi * g.random()
            s = math.sqrt(1 - z * z)
            w = math.radians(a.tumble)
            out += [f"env.omega0[{i + 1}]={v * w!r}" for i, v in enumerate((s * math.cos(phi), s * math.sin(phi), z))]
    if a.noise_seed is not None:
        out.append(f"mag.noise_seed={a.noise_seed}")
    print(f"# inclination {inc:.3f} deg, raan {raan:.3f} deg, {n:.8f} rev/day, period {86400 / n:.2f} s",
          file=sys.stderr)
    print("\n".join(out))


if __name__ == "__main__":
    main()
