#!/usr/bin/env python3
"""Recompute the golden values of docs/golden.md without kin5.

Each value comes from Rodrigues rotations in 30-digit arithmetic (mpmath): a forward value is
the rotation chain itself, an inverse value is found by solving the chain for its angles
(latitude first, then the azimuth difference), never by the closed forms of the papers or by
kin5's solver. Run: python3 docs/golden-values.py (needs python3-mpmath).
"""
from mpmath import mp, mpf, sin, cos, sqrt, atan2, asin, acos, pi, degrees, radians

mp.dps = 30
X, Y, Z = [1, 0, 0], [0, 1, 0], [0, 0, 1]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def rot(n, angle, v):
    """Right-handed rotation of v by angle (radians) about the unit vector n."""
    c, s, d, x = cos(angle), sin(angle), dot(n, v), cross(n, v)
    return [v[i] * c + x[i] * s + n[i] * d * (1 - c) for i in range(3)]


def unit(v):
    length = sqrt(dot(v, v))
    return [mpf(x) / length for x in v]


def azimuth_turn(n, w, u):
    """Signed angle about n that carries w's projection onto u's projection (radians)."""
    wp = [w[i] - dot(n, w) * n[i] for i in range(3)]
    up = [u[i] - dot(n, u) * n[i] for i in range(3)]
    return atan2(dot(n, cross(wp, up)), dot(wp, up))


def show(*values):
    return " ".join(mp.nstr(v, 10) for v in values)


DMU80_HEAD = unit([0, 1, 1])      # DMU 80P head axis
DMU50_TABLE = unit([0, 1, -1])    # DMU 50V B axis, as Liu 2010's inverse uses it
TILTED_TABLE = unit([1, 0, -1])   # Li et al. 2013 head-table machine


def sajo(a_deg, b_deg):
    return rot(Y, radians(b_deg), rot(X, radians(a_deg), Z))


def sajo_to_dmu(u):
    return [-u[0], u[2], u[1]]


def dmu80(b_deg, c_deg):
    return rot(Z, radians(c_deg), rot(DMU80_HEAD, radians(b_deg), Z))


def dmu80_inverse(u, branch=1):
    b = branch * 2 * atan2(sqrt(1 - u[2]), sqrt(u[2]))       # latitude: u_z = (1 + cos b)/2
    c = azimuth_turn(Z, rot(DMU80_HEAD, b, Z), u)
    return degrees(b), degrees(c)


def main():
    for a, b in [(-45, 30), (-10, 200), (-89, 123), (-100, 20), (-135, 0)]:
        u_s = sajo(a, b)
        u_d = sajo_to_dmu(u_s)
        b_d, c_d = dmu80_inverse(u_d)
        print(f"SAJO ({a}, {b}): u_s = {show(*u_s)}  u_d = {show(*u_d)}  B_d C_d = {show(b_d, c_d % 360)}")
    for b, c in [(90, 0), (180, 0), (60, 45)]:
        print(f"DMU 80P ({b}, {c}): u = {show(*dmu80(b, c))}")
    b_d, c_d = dmu80_inverse(dmu80(60, 45), branch=-1)
    print(f"DMU 80P (60, 45), other branch: B C = {show(b_d, c_d)}")

    u = rot(Z, radians(-121), rot(X, radians(-37), Z))  # physical table angles: psi = -phi
    print(f"Ji (37, 121): u = {show(*u)}")
    for sign in (1, -1):
        a = sign * acos(u[2])
        c = -azimuth_turn(Z, rot(X, -a, Z), u)
        print(f"  inverse: a c = {show(degrees(a), degrees(c) % 360)}")

    for v in ([-1, 1, 1], ["0.3", "-0.4", "0.8"]):
        u = unit([mpf(x) for x in v])
        b = 2 * atan2(sqrt(1 - u[2]), sqrt(u[2]))
        c = azimuth_turn(Z, rot(DMU50_TABLE, b, Z), u)
        print(f"Liu 2010 {v}: B C = {show(degrees(b), degrees(c))}")

    u = unit([mpf("0.2"), mpf("0.3"), mpf("0.9")])
    kappa = dot(TILTED_TABLE, u)                 # p . R(Y, theta) z = sin(theta - 45 deg)
    for theta in (pi / 4 + asin(kappa), 5 * pi / 4 - asin(kappa)):
        psi = azimuth_turn(TILTED_TABLE, rot(Y, theta, Z), u)
        print(f"Li et al. 2013 head-table: psi_table theta_B = {show(degrees(psi), degrees(theta))}")

    for a, b in [("-77.954", "3.536"), ("-77.913", "4.027"), ("-77.918", "4.588"), ("-77.963", "5.158")]:
        b_d, c_d = dmu80_inverse(sajo_to_dmu(sajo(mpf(a), mpf(b))))
        print(f"Table 1 ({a}, {b}): B_d C_d = {show(b_d, c_d % 360)}")


if __name__ == "__main__":
    main()
