#!/usr/bin/env python3
"""Golden values for LinuxCNC's two table-rotary-tilting simulation machines, xyzac-trt and
xyzbc-trt, computed from LinuxCNC's published kinematics equations alone (no kin5 code).

Source: the LinuxCNC manual, chapter "5-Axis Kinematics", sections "Transformations for a
xyzac-trt machine with rotary axis offsets" and "Transformations for a xyzbc-trt machine with
rotary axis offsets" (the forward transformation Q = ^Q A_P . P, and its inverse
P = (^Q A_P)^-1 . Q obtained from the transpose of the rotation, eqs (15)-(16) of the chapter);
the same forward equations are those of the kinematics modules xyzac-trt-kins and
xyzbc-trt-kins. The geometry is that of the simulation configurations
(configs/sim/axis/vismach/5axis/table-rotary-tilting/xyzac-trt.ini and xyzbc-trt.ini):
rotation point (0, 0, 0); xyzac-trt y-offset 20, z-offset 10; xyzbc-trt x-offset -20,
z-offset -15 (mm). The tool offset D_t (the tool length) joins the z-offset, as the modules
take it.

Notation (LinuxCNC's): P = joint positions X, Y, Z (mm) of the machine; Q = the world position
(tool tip in the work frame, plus the tool offset along +Z, which LinuxCNC keeps in world
coordinates); angles in degrees, tables turning right-handed by the commanded angle. With r the
rotation point and D the offset vector of the tilting axis (tool offset added to its z):

    xyzac-trt:  Q = r + Rz(-C) (D + Rx(-A) (P - r - D)),   D = (0, Dy, Dz + Dt)
    xyzbc-trt:  Q = r + Rz(-C) (D + Ry(-B) (P - r - D)),   D = (Dx, 0, Dz + Dt)
    inverse:    P = r + D + R^T (Rz(C) (Q - r) - D), R = Rx(-A) or Ry(-B)

Expanded, the xyzac-trt forward reads (c = cos, s = sin):
    Qx = cC (Px - rx) + sC cA (Py - Dy - ry) + sC sA (Pz - Dz' - rz) + sC Dy + rx
    Qy = -sC (Px - rx) + cC cA (Py - Dy - ry) + cC sA (Pz - Dz' - rz) + cC Dy + ry
    Qz = -sA (Py - Dy - ry) + cA (Pz - Dz' - rz) + Dz' + rz,          Dz' = Dz + Dt
and both the expanded and the rotation forms are evaluated below and must agree.

Tool axis (third column of the rotation): K = Rz(-C) Rx(-A) z or Rz(-C) Ry(-B) z.
Tip in the work frame (G54 zero): Q - (0, 0, Dt).

Every case is checked by the round trip P -> Q -> P (to 1e-12 mm). Known defect, not used
here: LinuxCNC's xyzbcKinematicsInverse has had a sign error in its offset terms since 2023,
so its round trip misses by 2|sin B||offset|; the inverse above is the exact inverse of the
published forward instead.

Run: python3 linuxcnc_trt_golden.py   (prints the C++ rows pasted into linuxcnc_golden.cpp)
"""
import math


def rx(t, v):
    c, s = math.cos(t), math.sin(t)
    return (v[0], c * v[1] - s * v[2], s * v[1] + c * v[2])


def ry(t, v):
    c, s = math.cos(t), math.sin(t)
    return (c * v[0] + s * v[2], v[1], -s * v[0] + c * v[2])


def rz(t, v):
    c, s = math.cos(t), math.sin(t)
    return (c * v[0] - s * v[1], s * v[0] + c * v[1], v[2])


def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


MACHINES = {
    # name: (tilt rotation, rotation point r, offsets (Dx, Dy, Dz))
    "xyzac-trt": (rx, (0.0, 0.0, 0.0), (0.0, 20.0, 10.0)),
    "xyzbc-trt": (ry, (0.0, 0.0, 0.0), (-20.0, 0.0, -15.0)),
}


def forward(name, p, tilt_deg, c_deg, dt):
    rot, r, d = MACHINES[name]
    t, c = math.radians(tilt_deg), math.radians(c_deg)
    dd = (d[0], d[1], d[2] + dt)
    q = add(r, rz(-c, add(dd, rot(-t, sub(sub(p, r), dd)))))
    k = rz(-c, rot(-t, (0.0, 0.0, 1.0)))
    return q, k


def forward_expanded_ac(p, a_deg, c_deg, dt):
    _, r, d = MACHINES["xyzac-trt"]
    a, c = math.radians(a_deg), math.radians(c_deg)
    dy, dz = d[1], d[2] + dt
    ca, sa, cc, sc = math.cos(a), math.sin(a), math.cos(c), math.sin(c)
    return (cc * (p[0] - r[0]) + sc * ca * (p[1] - dy - r[1]) + sc * sa * (p[2] - dz - r[2]) + sc * dy + r[0],
            -sc * (p[0] - r[0]) + cc * ca * (p[1] - dy - r[1]) + cc * sa * (p[2] - dz - r[2]) + cc * dy + r[1],
            -sa * (p[1] - dy - r[1]) + ca * (p[2] - dz - r[2]) + dz + r[2])


def inverse(name, q, tilt_deg, c_deg, dt):
    rot, r, d = MACHINES[name]
    t, c = math.radians(tilt_deg), math.radians(c_deg)
    dd = (d[0], d[1], d[2] + dt)
    return add(add(r, dd), rot(t, sub(rz(c, sub(q, r)), dd)))


# (name, X, Y, Z, tilt A or B, C, tool length): within the simulation's travel, limits included.
CASES = [
    ("xyzac-trt", 12.5, -30.0, 40.0, 30.0, 45.0, 0.0),
    ("xyzac-trt", -150.0, 80.0, -60.0, -100.0, 170.0, 55.0),
    ("xyzac-trt", 0.0, 0.0, 0.0, 50.0, -90.0, 25.0),
    ("xyzac-trt", 199.0, -99.0, 119.0, -45.5, 300.0, 10.0),
    ("xyzac-trt", 35.25, 60.5, -100.0, 0.0, 12.0, 80.0),
    ("xyzbc-trt", 12.5, -30.0, 40.0, 30.0, 45.0, 0.0),
    ("xyzbc-trt", -150.0, 80.0, -60.0, -100.0, 170.0, 55.0),
    ("xyzbc-trt", 0.0, 0.0, 0.0, 50.0, -90.0, 25.0),
    ("xyzbc-trt", 199.0, -99.0, 119.0, -45.5, 300.0, 10.0),
    ("xyzbc-trt", -35.25, 60.5, -100.0, -7.0, -135.0, 80.0),
]


def main():
    for name, x, y, z, tilt, c, dt in CASES:
        p = (x, y, z)
        q, k = forward(name, p, tilt, c, dt)
        if name == "xyzac-trt":
            e = forward_expanded_ac(p, tilt, c, dt)
            assert max(abs(a - b) for a, b in zip(q, e)) < 1e-12, "expanded and rotation forms differ"
        back = inverse(name, q, tilt, c, dt)
        assert max(abs(a - b) for a, b in zip(back, p)) < 1e-12, "round trip"
        tip = (q[0], q[1], q[2] - dt)
        print('    {"%s", {%.17g, %.17g, %.17g}, %.17g, %.17g, %.17g, {%.17g, %.17g, %.17g}, {%.17g, %.17g, %.17g}},'
              % (name, x, y, z, tilt, c, dt, *tip, *k))


if __name__ == "__main__":
    main()
