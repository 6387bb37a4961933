#!/usr/bin/env python3
"""Writes the trainer's scripted device trajectories (CSV read by GeomagicDriver's
`trajectory`: time, x, y, z, qx, qy, qz, qw, buttons; positions in scene units).

needle.csv: the needle's tip (frame origin; the needle points along its local +x)
follows a circular arc in the plane y = 10 through the skin pad (top face z = 5):
centre (15, 10, 8.75), radius 6.25, entering the top at x = 10, deepest (z = 2.5)
at x = 15, leaving the top at x = 20; the needle stays tangent to the arc. It
holds above the pad for 0.5 s, runs the arc from -80 deg to +100 deg in 7 s (the
back point, 3 behind the tip, leaves the skin near +81 deg), is pulled up by 3
in 1.5 s and holds to 10 s.

scalpel.csv: the scalpel's tip holds above the pad, goes down to z = 4.8 at
(5, 4) between t = 1 and 2 s, cuts along x to 25 in 4 s, and is lifted at 6.5 s.
"""
import math

CX, CZ, R, Y = 15.0, 8.75, 6.25, 10.0


def needle_pose(theta):
    x = CX + R * math.sin(theta)
    z = CZ - R * math.cos(theta)
    # local +x -> tangent (cos t, 0, sin t): a turn of -theta about y.
    return (x, Y, z, 0.0, math.sin(-theta / 2), 0.0, math.cos(-theta / 2))


def row(t, p, buttons=0):
    return "%.4f, %.6f, %.6f, %.6f, %.9f, %.9f, %.9f, %.9f, %d\n" % ((t,) + tuple(p) + (buttons,))


def needle():
    out = ["# time, x, y, z, qx, qy, qz, qw, buttons (trainer needle, make_trajectories.py)\n"]
    a0, a1 = math.radians(-80), math.radians(100)
    t0, t1 = 0.5, 7.5
    out.append(row(0.0, needle_pose(a0)))
    n = 70
    for k in range(n + 1):
        t = t0 + (t1 - t0) * k / n
        out.append(row(t, needle_pose(a0 + (a1 - a0) * k / n)))
    x, y, z, qx, qy, qz, qw = needle_pose(a1)
    out.append(row(9.0, (x, y, z + 3.0, qx, qy, qz, qw)))
    out.append(row(10.0, (x, y, z + 3.0, qx, qy, qz, qw)))
    return "".join(out)


def scalpel():
    q = (0.0, 0.0, 0.0, 1.0)
    pts = [(0.0, (5, 4, 7)), (1.0, (5, 4, 7)), (2.0, (5, 4, 4.8)), (6.0, (25, 4, 4.8)), (6.5, (25, 4, 7)),
           (10.0, (25, 4, 7))]
    out = ["# time, x, y, z, qx, qy, qz, qw, buttons (trainer scalpel, make_trajectories.py)\n"]
    for t, p in pts:
        out.append(row(t, tuple(float(c) for c in p) + q))
    return "".join(out)


if __name__ == "__main__":
    open("needle.csv", "w").write(needle())
    open("scalpel.csv", "w").write(scalpel())
