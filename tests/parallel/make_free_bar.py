#!/usr/bin/env python3
"""Writes tests/parallel/free_bar.k (python3 tests/parallel/make_free_bar.py > tests/parallel/free_bar.k)
and, with the argument 2, free_bar_elform2.k (the same bar of fully integrated solids, ELFORM 2);
with the argument loads, free_bar_loads.k (the bar under loads: nodal forces, pressures on its
bottom face and on one side over its whole height, a body load and global damping); with the
argument motions, free_bar_motions.k (the bar's bottom pulled down at a prescribed velocity until
40 us, top nodes moved by a prescribed displacement, acceleration, velocity along a vector with
its normal plane held, two mid-height nodes turned about the bar's axis, one of them free in
radius, with a nodal force and a body load, falling on a stonewall with friction 0.8 mm below it
after the pull ends); with the argument masses, free_bar_masses.k (mass scaling: DT2MS < 0, the
solids whose step falls below 0.55 us get mass, at the first cycle and as they deform).

A free bar for the distributed runs' tests: 4 x 4 x 20 hexahedra (10 mm x 10 mm x 50 mm), no
wall, no constraint; the lower half copper, the upper half a softer copper (two
materials, so two element groups); every node starts with a spin about the bar's axis (2000 rad/s)
and an axial stretch (+-60 m/s at the ends), so the bar rings, yields in its softer half and keeps
its momentum.  60 us, 10 plot states, time histories of two nodes and two solids.
"""
import sys

variant = sys.argv[1] if len(sys.argv) > 1 else "1"
elform = int(variant) if variant.isdigit() else 1
nx, ny, nz = 4, 4, 20
lx, ly, lz = 0.010, 0.010, 0.050
omega, vend = 2000.0, 60.0


def nid(i, j, k):
    return 1 + i + (nx + 1) * (j + (ny + 1) * k)


out = []
w = out.append
w("*KEYWORD")
name = f"free_bar_{variant}.k" if not variant.isdigit() else "free_bar.k" if elform == 1 else f"free_bar_elform{elform}.k"
w(f"$ tests/parallel/{name}: written by tests/parallel/make_free_bar.py (do not edit by hand)")
w("*TITLE")
w("free bar: spin and stretch, copper and steel halves, SI units (m kg s Pa)")
w("*CONTROL_TERMINATION")
w("    6.0e-5         0       0.0")
w("*CONTROL_TIMESTEP")
if variant == "masses":  # DT2MS < 0: the solids whose step falls below it get mass
    w("       0.0       0.9         0       0.0  -5.50e-7")
else:
    w("       0.0       0.9")
w("*DATABASE_BINARY_D3PLOT")
w("    6.0e-6")
w("*DATABASE_NODOUT")
w("    1.0e-6")
w("*DATABASE_ELOUT")
w("    1.0e-6")
w("*DATABASE_GLSTAT")
w("    1.0e-6")
w("*DATABASE_MATSUM")
w("    1.0e-6")
w("*DATABASE_HISTORY_NODE")
w(f"{nid(0, 0, 0):10d}{nid(nx, ny, nz):10d}")
w("*DATABASE_HISTORY_SOLID")
w(f"{1:10d}{nx * ny * nz:10d}")
w("*SECTION_SOLID")
w(f"         1{elform:10d}")
w("*PART")
w("copper, elastic-plastic")
w("         1         1         1         0         1")
w("*PART")
w("copper, elastic-plastic, softer")
w("         2         1         2         0         1")
w("*MAT_PLASTIC_KINEMATIC")
w("         1    8930.0   1.17e11      0.35     4.0e8     1.0e8       1.0")
w("       0.0       0.0       0.0       0.0")
w("*MAT_PLASTIC_KINEMATIC")
w("         2    8930.0   1.17e11      0.35     2.5e8     1.0e8       1.0")
w("       0.0       0.0       0.0       0.0")
w("*HOURGLASS")
w("         1         4       0.1         0       1.5      0.06")
w("*NODE")
for k in range(nz + 1):
    for j in range(ny + 1):
        for i in range(nx + 1):
            x, y, z = (i / nx - 0.5) * lx, (j / ny - 0.5) * ly, k / nz * lz
            w(f"{nid(i, j, k):8d}{x:16.8e}{y:16.8e}{z:16.8e}       0       0")
w("*ELEMENT_SOLID")
e = 0
for k in range(nz):
    for j in range(ny):
        for i in range(nx):
            e += 1
            n = [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                 nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)]
            w(f"{e:8d}{1 if k < nz // 2 else 2:8d}" + "".join(f"{v:8d}" for v in n))
w("*INITIAL_VELOCITY_NODE")
for k in range(nz + 1):
    for j in range(ny + 1):
        for i in range(nx + 1):
            x, y, z = (i / nx - 0.5) * lx, (j / ny - 0.5) * ly, k / nz * lz
            vx, vy, vz = -omega * y, omega * x, vend * (2 * z / lz - 1)
            w(f"{nid(i, j, k):10d}{vx:10.4f}{vy:10.4f}{vz:10.4f}")


def curve(lcid, title, points):
    w("*DEFINE_CURVE_TITLE")
    w(title)
    w(f"{lcid:10d}")
    for a, o in points:
        w(f"{a:20.6e}{o:20.6e}")


if variant == "loads":
    curve(1, "ramp to 1 in 20 us, then held", [(0.0, 0.0), (2.0e-5, 1.0), (1.0e-3, 1.0)])
    w("*LOAD_NODE_POINT")
    w(f"{nid(nx, ny, nz):10d}         1         1    2000.0")
    w(f"{nid(0, 0, nz // 2):10d}         2         1   -1500.0")
    w("*LOAD_SEGMENT")
    for j in range(ny):  # the bottom face, outward normal -z: pushed up
        for i in range(nx):
            n = [nid(i, j, 0), nid(i, j + 1, 0), nid(i + 1, j + 1, 0), nid(i + 1, j, 0)]
            w("         1     2.0e7       0.0" + "".join(f"{v:10d}" for v in n))
    for k in range(nz):  # the side x = +lx/2, outward normal +x, over the whole height
        for j in range(ny):
            n = [nid(nx, j, k), nid(nx, j + 1, k), nid(nx, j + 1, k + 1), nid(nx, j, k + 1)]
            w("         1     5.0e6    1.0e-5" + "".join(f"{v:10d}" for v in n))
    w("*LOAD_BODY_Z")
    w("         1    9.81e4")
    w("*DAMPING_GLOBAL")
    w("         0    2000.0")
if variant == "motions":
    curve(1, "ramp to 1 in 20 us, then held", [(0.0, 0.0), (2.0e-5, 1.0), (1.0e-3, 1.0)])
    curve(2, "displacement 0.1 mm in 60 us", [(0.0, 0.0), (6.0e-5, 1.0e-4), (1.0e-3, 1.0e-4)])
    curve(3, "constant 1", [(0.0, 1.0), (1.0e-3, 1.0)])
    w("*SET_NODE_LIST")
    w("         1")
    bottom = [nid(i, j, 0) for j in range(ny + 1) for i in range(nx + 1)]
    for a in range(0, len(bottom), 8):
        w("".join(f"{v:10d}" for v in bottom[a:a + 8]))
    w("*DEFINE_VECTOR")
    w("         1       0.0       0.0       0.0       1.0       1.0       0.0")
    w("*BOUNDARY_PRESCRIBED_MOTION_SET")
    w("         1         3         0         1     -20.0         0    4.0e-5")
    w("*BOUNDARY_PRESCRIBED_MOTION_NODE")
    w(f"{nid(nx // 2, ny // 2, nz):10d}         1         2         2       1.0")
    w(f"{nid(0, 0, nz):10d}         2         1         1     2.0e5")
    w(f"{nid(nx, ny, nz):10d}        -4         0         3       2.0         1")
    w(f"{nid(nx, ny // 2, nz // 2):10d}        11         0         3    2000.0")
    w("       0.0       0.0")
    w(f"{nid(0, ny // 2, nz // 2):10d}       -11         0         3    2000.0")
    w("       0.0       0.0")
    w("*LOAD_NODE_POINT")
    w(f"{nid(nx, 0, nz):10d}         1         1     100.0")
    w("*RIGIDWALL_PLANAR")
    w("         0")
    w("       0.0       0.0   -8.0e-4       0.0       0.0       1.0       0.2")
    w("*LOAD_BODY_Z")
    w("         1    9.81e4")
w("*END")
print("\n".join(out))
