#!/usr/bin/env python3
"""Makes meshes/bunny.obj, the low-poly bunny shipped as the mesh test body,
and prints the mass properties that urdf/bunny.urdf carries.

The bunny is an icosphere (two subdivisions: 162 vertices, 320 triangles)
whose radius in each direction is an ellipsoid plus smooth bumps for the
head, two ears and a tail. Mass properties come from the closed triangle
mesh by the divergence theorem (signed tetrahedra), for a uniform density.
Standard library only. Run: python3 scripts/make_bunny_mesh.py
"""
import math
import os

MASS = 0.5  # kg


def normalize(v):
    n = math.sqrt(sum(c * c for c in v))
    return tuple(c / n for c in v)


def icosphere(subdivisions):
    t = (1.0 + math.sqrt(5.0)) / 2.0
    verts = [normalize(v) for v in [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
                                    (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
             (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(subdivisions):
        cache = {}

        def midpoint(a, b):
            key = (min(a, b), max(a, b))
            if key not in cache:
                verts.append(normalize(tuple((verts[a][i] + verts[b][i]) / 2 for i in range(3))))
                cache[key] = len(verts) - 1
            return cache[key]

        new_faces = []
        for a, b, c in faces:
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            new_faces += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = new_faces
    return verts, faces


def radius(d):
    """Distance from the centre to the surface in unit direction d (m)."""
    x, y, z = d
    body = 1.0 / math.sqrt((x / 0.10) ** 2 + (y / 0.065) ** 2 + (z / 0.07) ** 2)
    bumps = [((0.8, 0.0, 0.6), 0.05, 0.35),     # head: forward and up
             ((0.45, 0.35, 0.82), 0.07, 0.12),   # left ear
             ((0.45, -0.35, 0.82), 0.07, 0.12),  # right ear
             ((-1.0, 0.0, 0.15), 0.02, 0.3)]     # tail
    for centre, height, width in bumps:
        c = normalize(centre)
        angle = math.acos(max(-1.0, min(1.0, sum(a * b for a, b in zip(d, c)))))
        body += height * math.exp(-(angle / width) ** 2)
    return body


def mass_properties(verts, faces, mass):
    """Volume, centre of mass and inertia about it of a closed mesh of uniform density."""
    vol = 0.0
    first = [0.0, 0.0, 0.0]
    second = [[0.0] * 3 for _ in range(3)]  # ∫ x_i x_j dV
    for a, b, c in faces:
        p, q, r = verts[a], verts[b], verts[c]
        det = (p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0])
               + p[2] * (q[0] * r[1] - q[1] * r[0]))
        v = det / 6.0
        vol += v
        for i in range(3):
            first[i] += v * (p[i] + q[i] + r[i]) / 4.0
            for j in range(3):
                second[i][j] += v / 20.0 * (2 * (p[i] * p[j] + q[i] * q[j] + r[i] * r[j])
                                            + p[i] * q[j] + q[i] * p[j] + p[i] * r[j] + r[i] * p[j]
                                            + q[i] * r[j] + r[i] * q[j])
    com = [f / vol for f in first]
    rho = mass / vol
    cov = [[rho * (second[i][j] - vol * com[i] * com[j]) for j in range(3)] for i in range(3)]
    trace = cov[0][0] + cov[1][1] + cov[2][2]
    inertia = [[(trace if i == j else 0.0) - cov[i][j] for j in range(3)] for i in range(3)]
    return vol, com, inertia


def main():
    verts, faces = icosphere(2)
    verts = [tuple(radius(d) * c for c in d) for d in verts]
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    path = os.path.join(root, "meshes", "bunny.obj")
    with open(path, "w") as out:
        out.write("# Low-poly bunny made by scripts/make_bunny_mesh.py: %d vertices, %d triangles, metres.\n"
                  % (len(verts), len(faces)))
        for v in verts:
            out.write("v %.6f %.6f %.6f\n" % v)
        for a, b, c in faces:
            out.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))
    vol, com, inertia = mass_properties([tuple(float("%.6f" % c) for c in v) for v in verts], faces, MASS)
    print("wrote %s: %d vertices" % (path, len(verts)))
    print("volume %.6g m^3, mass %g kg" % (vol, MASS))
    print('<origin xyz="%.6f %.6f %.6f" rpy="0 0 0"/>' % tuple(com))
    print('<inertia ixx="%.6g" ixy="%.6g" ixz="%.6g" iyy="%.6g" iyz="%.6g" izz="%.6g"/>'
          % (inertia[0][0], inertia[0][1], inertia[0][2], inertia[1][1], inertia[1][2], inertia[2][2]))


if __name__ == "__main__":
    main()
