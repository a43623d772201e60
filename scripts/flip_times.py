#!/usr/bin/env python3
"""Prints when a spinning body flips (the intermediate-axis, or Dzhanibekov,
effect) in an rbsim CSV, beside the closed form of the torque-free motion.

  flip_times.py TRAJECTORY.csv BODY.urdf

The body's angular velocity about its middle principal axis (y for the
shipped box, whose inertia is diagonal in its link frame) changes sign at
each flip. For principal moments I1 < I2 < I3, energy E and momentum L, the
free motion is Jacobi's elliptic functions (Landau and Lifshitz, Mechanics,
section 37): w2 ~ sn(nu t), which crosses zero every 2K(k)/nu; starting at
its extreme, the first crossing is at K(k)/nu.
"""
import csv
import math
import sys
import xml.etree.ElementTree as ET


def rotate_back(q, v):
    """v (world axes) in the axes of the frame with orientation q = (x, y, z, w)."""
    x, y, z, w = q
    # Rotate by the conjugate: v' = v + 2 u x (u x v - w v) with u = -(x, y, z).
    ux, uy, uz = -x, -y, -z
    tx = uy * v[2] - uz * v[1] + w * v[0]
    ty = uz * v[0] - ux * v[2] + w * v[1]
    tz = ux * v[1] - uy * v[0] + w * v[2]
    return (v[0] + 2 * (uy * tz - uz * ty), v[1] + 2 * (uz * tx - ux * tz), v[2] + 2 * (ux * ty - uy * tx))


def complete_elliptic_k(k):
    """K(k) = pi / (2 AGM(1, sqrt(1 - k^2)))."""
    a, b = 1.0, math.sqrt(1.0 - k * k)
    while abs(a - b) > 1e-15 * a:
        a, b = 0.5 * (a + b), math.sqrt(a * b)
    return math.pi / (2.0 * a)


def diagonal_inertia(urdf):
    inertia = ET.parse(urdf).getroot().find("link/inertial/inertia")
    if inertia is None or any(abs(float(inertia.get(k, "0"))) > 0 for k in ("ixy", "ixz", "iyz")):
        sys.exit("flip_times: needs one link with a diagonal <inertia> (as urdf/box.urdf)")
    return [float(inertia.get(k)) for k in ("ixx", "iyy", "izz")]


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    rows = list(csv.DictReader(open(sys.argv[1])))
    I = diagonal_inertia(sys.argv[2])
    if not (I[0] < I[1] < I[2]):
        sys.exit("flip_times: the middle principal axis must be y (Ixx < Iyy < Izz)")
    t, wy = [], []
    for r in rows:
        q = tuple(float(r[k]) for k in ("qx", "qy", "qz", "qw"))
        w = rotate_back(q, tuple(float(r[k]) for k in ("wx", "wy", "wz")))
        t.append(float(r["t"]))
        wy.append(w[1])
    flips = [t[i] + (t[i + 1] - t[i]) * wy[i] / (wy[i] - wy[i + 1])
             for i in range(len(t) - 1) if (wy[i] > 0) != (wy[i + 1] > 0)]

    # The closed form from the first row's angular velocity (body axes).
    q0 = tuple(float(rows[0][k]) for k in ("qx", "qy", "qz", "qw"))
    w0 = rotate_back(q0, tuple(float(rows[0][k]) for k in ("wx", "wy", "wz")))
    I1, I2, I3 = I
    L2 = sum((Ii * wi) ** 2 for Ii, wi in zip(I, w0))
    E2 = sum(Ii * wi * wi for Ii, wi in zip(I, w0))  # 2E
    if L2 > E2 * I2:
        nu = math.sqrt((I3 - I2) * (L2 - E2 * I1) / (I1 * I2 * I3))
        k2 = (I2 - I1) * (E2 * I3 - L2) / ((I3 - I2) * (L2 - E2 * I1))
    else:  # axes 1 and 3 exchanged
        nu = math.sqrt((I2 - I1) * (E2 * I3 - L2) / (I1 * I2 * I3))
        k2 = (I3 - I2) * (L2 - E2 * I1) / ((I2 - I1) * (E2 * I3 - L2))
    if not (0.0 <= k2 < 1.0):
        print("flip_times: this start is on the separatrix (no period)")
        return
    K = complete_elliptic_k(math.sqrt(k2))
    expected = [K / nu + 2.0 * K / nu * n for n in range(100) if K / nu + 2.0 * K / nu * n <= t[-1]]
    print("flips of the spin axis in %.3g s (closed form: first at K/nu = %.4f s, then every 2K/nu = %.4f s):"
          % (t[-1], K / nu, 2.0 * K / nu))
    for n in range(max(len(flips), len(expected))):
        got = "t = %8.4f s" % flips[n] if n < len(flips) else "none"
        want = "%8.4f s" % expected[n] if n < len(expected) else "none"
        print("  flip %d: %s   closed form %s" % (n + 1, got, want))
    if not flips:
        print("  no flip: without the gyroscopic term (gyroscopic: false) the spin never flips")


if __name__ == "__main__":
    main()
