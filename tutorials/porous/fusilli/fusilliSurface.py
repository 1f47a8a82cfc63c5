#!/usr/bin/env python3
"""Writes the closed surfaces of the fusilli tutorial to constant/triSurface (Python 3 standard library only).

fusilli.obj  a three-bladed cross-section swept along x with a steady twist (a helix), caps fanned from the
             axis. Blade tips reach the radius R at twist angles that are multiples of 3.75 degrees, so the
             bounding box is exactly [X0, X1] x [YAXIS - R, YAXIS + R] x [-R, R]: its particles then sit on
             the same lattice as the water's.
water.obj    the water: the box WATER_MIN..WATER_MAX with the fusilli as a cavity (a second, inward shell),
             so water fills the tank around the dry fusilli without a single particle inside it.

Every corner of both bounding boxes lies on multiples of 0.06 m, so the two lattices coincide for
r = 7.5 mm, 1 cm, 1.5 cm and 3 cm (spacing 2r divides 0.06 m).
Usage: python3 fusilliSurface.py [CASE]   (default: the current directory)
"""

import math
import os
import sys

R = 0.06                       # [m] blade-tip radius of the cross-section
X0, X1 = -0.06, 0.30           # [m] the fusilli's ends along x; x < 0 is held by the fixedBox
YAXIS = 0.36                   # [m] height of its axis (z = 0)
TURNS = 1.5                    # twist over the whole length
WATER_MIN = (-0.12, 0.0, -0.12)  # [m] the water box (inner faces of the tank)
WATER_MAX = (0.42, 0.48, 0.12)
SECTION_POINTS = 72            # points around the section (5 degrees apart)
RINGS = 144                    # sections along x: 3.75 degrees of twist each (less than the 5 degrees
                               # between section points, so the side triangles stay well shaped), and blade
                               # tips point exactly along +-y and +-z somewhere (the exact bounding box above)


def sectionRadius(theta):
    """Three blades: tip radius R, waist 0.2 R (thick enough for a few particles at r = 1.5 cm)."""
    return R * (0.6 + 0.4 * math.cos(3.0 * theta))


def fusilli():
    """Vertices and outward triangles (counter-clockwise seen from outside) of the twisted body."""
    vertices, triangles = [], []
    for k in range(RINGS + 1):
        x = X0 + (X1 - X0) * k / RINGS
        twist = 2.0 * math.pi * TURNS * k / RINGS
        for j in range(SECTION_POINTS):
            theta = 2.0 * math.pi * j / SECTION_POINTS
            rho = sectionRadius(theta)
            vertices.append((x, YAXIS + rho * math.cos(theta + twist), rho * math.sin(theta + twist)))
    ring = lambda k, j: k * SECTION_POINTS + j % SECTION_POINTS
    for k in range(RINGS):
        for j in range(SECTION_POINTS):
            a, b, c, d = ring(k, j), ring(k, j + 1), ring(k + 1, j + 1), ring(k + 1, j)
            triangles += [(a, b, c), (a, c, d)]
    # Caps: a fan from the axis point (the section is star-shaped about it).
    for k, outward in ((0, False), (RINGS, True)):
        centre = len(vertices)
        vertices.append((X0 + (X1 - X0) * k / RINGS, YAXIS, 0.0))
        for j in range(SECTION_POINTS):
            tri = (centre, ring(k, j), ring(k, j + 1))
            triangles.append(tri if outward else tri[::-1])
    return vertices, triangles


def box(lo, hi):
    """The 8 corners and 12 outward triangles of an axis-aligned box."""
    vertices = [(hi[0] if i & 1 else lo[0], hi[1] if i & 2 else lo[1], hi[2] if i & 4 else lo[2]) for i in range(8)]
    quads = [(0, 4, 6, 2), (1, 3, 7, 5), (0, 1, 5, 4), (2, 6, 7, 3), (0, 2, 3, 1), (4, 5, 7, 6)]
    return vertices, [t for q in quads for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]


def signedVolume(vertices, triangles):
    """Divergence theorem: positive when the triangles face outward."""
    volume = 0.0
    for a, b, c in triangles:
        (ax, ay, az), (bx, by, bz), (cx, cy, cz) = vertices[a], vertices[b], vertices[c]
        volume += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)
    return volume / 6.0


def checkClosed(triangles, name):
    """Every edge must be used once in each direction (closed and consistently oriented)."""
    edges = {}
    for tri in triangles:
        for e in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])):
            edges[e] = edges.get(e, 0) + 1
    bad = [e for e, n in edges.items() if n != 1 or edges.get(e[::-1]) != 1]
    if bad:
        sys.exit(f"fusilliSurface.py: {name} is not closed and consistently oriented ({len(bad)} bad edges)")


def sectionMoments():
    """Area A and second moment I (about any axis through the centre: the section has three-fold symmetry)."""
    n = 3600
    pts = [(sectionRadius(2 * math.pi * j / n) * math.cos(2 * math.pi * j / n),
            sectionRadius(2 * math.pi * j / n) * math.sin(2 * math.pi * j / n)) for j in range(n)]
    area = inertia = 0.0
    for (y0, z0), (y1, z1) in zip(pts, pts[1:] + pts[:1]):
        cross = y0 * z1 - y1 * z0
        area += cross / 2.0
        inertia += cross * (y0 * y0 + y0 * y1 + y1 * y1) / 12.0
    return area, inertia


def writeObj(path, vertices, triangles, comment):
    with open(path, "w") as f:
        f.write(f"# {comment}\n")
        f.writelines(f"v {x:.12g} {y:.12g} {z:.12g}\n" for x, y, z in vertices)
        f.writelines(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in triangles)


def main():
    case = sys.argv[1] if len(sys.argv) > 1 else "."
    out = os.path.join(case, "constant", "triSurface")
    os.makedirs(out, exist_ok=True)
    fv, ft = fusilli()
    checkClosed(ft, "fusilli")
    bv, bt = box(WATER_MIN, WATER_MAX)
    # The water: the box plus the fusilli turned inside out (its faces pointing into the cavity).
    wv = bv + fv
    wt = bt + [(c + 8, b + 8, a + 8) for a, b, c in ft]
    checkClosed(wt, "water")
    volume = signedVolume(fv, ft)
    if volume <= 0 or signedVolume(wv, wt) <= 0:
        sys.exit("fusilliSurface.py: a surface faces inward")
    writeObj(os.path.join(out, "fusilli.obj"), fv, ft, "fusilli: written by fusilliSurface.py")
    writeObj(os.path.join(out, "water.obj"), wv, wt, "water around the fusilli: written by fusilliSurface.py")
    area, inertia = sectionMoments()
    print(f"fusilli: volume {volume:.6g} m^3, section area {area:.6g} m^2, second moment {inertia:.6g} m^4")


if __name__ == "__main__":
    main()
