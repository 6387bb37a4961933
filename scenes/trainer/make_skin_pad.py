#!/usr/bin/env python3
"""Writes skin_pad.msh: the trainer's skin pad, a 30 x 20 x 5 box meshed with
tetrahedra (Gmsh 2.2 ASCII, read by MeshGmshLoader).

The box [0,30] x [0,20] x [0,5] is cut into NX x NY x NZ cubes, each split into
six tetrahedra around its main diagonal (Kuhn's subdivision: every cube uses
the same diagonal, so the faces of neighbouring cubes match). All tetrahedra
are positively oriented. Run it again after changing the resolution:
    python3 make_skin_pad.py > skin_pad.msh
"""
import sys

LX, LY, LZ = 30.0, 20.0, 5.0
NX, NY, NZ = 12, 8, 3


def vid(i, j, k):
    return (k * (NY + 1) + j) * (NX + 1) + i


def main(out):
    pts = []
    for k in range(NZ + 1):
        for j in range(NY + 1):
            for i in range(NX + 1):
                pts.append((LX * i / NX, LY * j / NY, LZ * k / NZ))
    # The six tetrahedra of a cube: paths from corner 0 to corner 7 along the
    # three axes in every order (x, y, z offsets of the corners).
    paths = [(0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)]
    tets = []
    for k in range(NZ):
        for j in range(NY):
            for i in range(NX):
                for p in paths:
                    c = [0, 0, 0]
                    corners = [vid(i, j, k)]
                    for axis in p:
                        c[axis] += 1
                        corners.append(vid(i + c[0], j + c[1], k + c[2]))
                    a, b, cc, d = (pts[v] for v in corners)
                    u = [b[m] - a[m] for m in range(3)]
                    v = [cc[m] - a[m] for m in range(3)]
                    w = [d[m] - a[m] for m in range(3)]
                    det = (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                           u[2] * (v[0] * w[1] - v[1] * w[0]))
                    if det < 0:
                        corners[1], corners[2] = corners[2], corners[1]
                    tets.append(corners)
    out.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(pts))
    for n, (x, y, z) in enumerate(pts):
        out.write("%d %.10g %.10g %.10g\n" % (n + 1, x, y, z))
    out.write("$EndNodes\n$Elements\n%d\n" % len(tets))
    for n, t in enumerate(tets):
        out.write("%d 4 2 1 1 %d %d %d %d\n" % (n + 1, t[0] + 1, t[1] + 1, t[2] + 1, t[3] + 1))
    out.write("$EndElements\n")


if __name__ == "__main__":
    main(sys.stdout)
