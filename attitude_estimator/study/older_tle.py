#!/usr/bin/env python3
"""An element set `--hours` older than a given one, for the on-board computer's own TLE (docs/onboard_references.md).

With a synthetic truth set there is no real older set of the same satellite, so the older one is made from it:
the epoch moved back, and the mean anomaly, node and perigee moved back along SGP4's own secular rates
(its initialization's un-Kozai'd mean motion and J2, J2^2, J4 terms; Vallado et al. 2006, "Revisiting
Spacetrack Report #3"), the mean motion, eccentricity, inclination and B* kept. SGP4 propagating the older
set forward does not land exactly on the newer one: its drag term (B*) acts over the extra hours and its
periodic terms start from another phase. That difference is the age error this study measures. A real older set also carries its fit's error and the atmosphere's departure from B*, which a
synthetic truth cannot show. Standard library only; prints the two lines with their checksums.
"""
import argparse
import math

J2 = 0.001082616  # WGS-72, as SGP4
J4 = -0.00000165597
RE = 6378.135  # km
MU = 398600.8  # km^3/s^2


def checksum(line):
    return sum(int(c) if c.isdigit() else (1 if c == "-" else 0) for c in line[:68]) % 10


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("line1")
    ap.add_argument("line2")
    ap.add_argument("--hours", type=float, required=True)
    a = ap.parse_args()
    l1, l2 = a.line1, a.line2
    days = a.hours / 24.0
    year, doy = int(l1[18:20]), float(l1[20:32])
    inc, raan, argp = float(l2[8:16]), float(l2[17:25]), float(l2[34:42])
    ecc, m0, n0 = float("0." + l2[26:33]), float(l2[43:51]), float(l2[52:63])
    # SGP4's own secular rates (sgp4init's initl and the rates after it, Vallado et al. 2006, WGS-72):
    # the un-Kozai'd mean motion and the J2, J2^2 and J4 terms of the mean anomaly, perigee and node.
    xke = 60.0 / math.sqrt(RE**3 / MU)  # 1/min, Earth radii
    no_kozai = n0 * 2 * math.pi / 1440.0  # rad/min
    cosio = math.cos(math.radians(inc))
    cosio2 = cosio * cosio
    omeosq = 1 - ecc * ecc
    rteosq = math.sqrt(omeosq)
    ak = (xke / no_kozai) ** (2.0 / 3.0)
    d1 = 0.75 * J2 * (3 * cosio2 - 1) / (rteosq * omeosq)
    dl = d1 / (ak * ak)
    adel = ak * (1 - dl * dl - dl * (1.0 / 3.0 + 134 * dl * dl / 81.0))
    dl = d1 / (adel * adel)
    no = no_kozai / (1 + dl)
    ao = (xke / no) ** (2.0 / 3.0)
    pinvsq = 1.0 / (ao * omeosq) ** 2
    temp1 = 1.5 * J2 * pinvsq * no
    temp2 = 0.5 * temp1 * J2 * pinvsq
    temp3 = -0.46875 * J4 * pinvsq * pinvsq * no
    mdot = no + 0.5 * temp1 * rteosq * (3 * cosio2 - 1) + 0.0625 * temp2 * rteosq * (13 - 78 * cosio2 + 137 * cosio2**2)
    argpdot = (-0.5 * temp1 * (1 - 5 * cosio2) + 0.0625 * temp2 * (7 - 114 * cosio2 + 395 * cosio2**2) +
               temp3 * (3 - 36 * cosio2 + 49 * cosio2**2))
    nodedot = -temp1 * cosio + (0.5 * temp2 * (4 - 19 * cosio2) + 2 * temp3 * (3 - 7 * cosio2)) * cosio
    per_day = 1440.0 * 180.0 / math.pi  # rad/min -> deg/day
    m_rate, argp_rate, raan_rate = mdot * per_day, argpdot * per_day, nodedot * per_day
    n_old = n0
    m_old = (m0 - m_rate * days) % 360.0
    raan_old = (raan - raan_rate * days) % 360.0
    argp_old = (argp - argp_rate * days) % 360.0
    doy_old = doy - days
    if doy_old < 1.0:
        raise SystemExit("older_tle: the older epoch falls in the previous year (not handled)")
    n1 = l1[:18] + f"{year:02d}{doy_old:012.8f}" + l1[32:68]
    n2 = l2[:17] + f"{raan_old:8.4f} " + l2[26:34] + f"{argp_old:8.4f} {m_old:8.4f} {n_old:11.8f}" + l2[63:68]
    print(n1 + str(checksum(n1)))
    print(n2 + str(checksum(n2)))


if __name__ == "__main__":
    main()
