#!/usr/bin/env python3
"""Writes tests/parallel/shell_tube.k (python3 tests/parallel/make_shell_tube.py > tests/parallel/shell_tube.k)
and, with the argument beams, shell_tube_beams.k: the same tube with three beam groups on its
nodes (a ring of Hughes-Liu beams, elastic-plastic, around its upper end; a ring of resultant
beams, ELFORM 2, around its middle; 12 trusses across its upper quarter, each between opposite
nodes); with the argument loads, shell_tube_loads.k: the tube under loads and prescribed motions
(an internal pressure on its middle rows of shells arriving at 10 us, a sideways body load, the
lower ring of tube nodes pulled down at a prescribed velocity, one upper-end node's spin about
the axis prescribed, DOF 6, as a rotational velocity).

A free shell tube for the distributed runs' tests: radius 10 mm, length 40 mm, 24 x 16 shells
0.5 mm thick in three parts (three materials, so three shell groups): the lower rows
Belytschko-Tsay elastic steel (3 points through the thickness), the middle rows Belytschko-Tsay
elastic-plastic copper (5 points, the block kernel's plastic path), the upper rows fully integrated
shells (ELFORM 16, the scalar kernel); a collar of 24 hexahedra around the lower end shares the
tube's first two rings of nodes (solids and shells at the same nodes).  Every node starts with a
spin about the tube's axis (2000 rad/s, and the same rotational velocity on the shell nodes), an
axial stretch (+-60 m/s at the ends) and a sideways swing (30 m/s at the top), so the tube
rings, bends and yields in its middle; one node of the upper end has its rotations held
(*BOUNDARY_SPC_NODE).  100 us, 10 plot states, time histories of two nodes, two shells and a solid.
"""
import math
import sys

beams = len(sys.argv) > 1 and sys.argv[1] == "beams"
loads = len(sys.argv) > 1 and sys.argv[1] == "loads"
masses = len(sys.argv) > 1 and sys.argv[1] == "masses"

nt, nz = 24, 16
radius, length, thick, collar = 0.010, 0.040, 0.0005, 0.002
omega, vend, swing = 2000.0, 60.0, 30.0
DT2MS = 5.0e-7  # (masses) the target element step, s


def nid(i, k):  # tube node: i around, k along
    return 1 + i % nt + nt * k


def cid(i, k):  # collar's outer nodes: i around, k = 0, 1
    return 1 + nt * (nz + 1) + i % nt + nt * k


def part(k):
    return 1 if k < 6 else 2 if k < 12 else 3


out = []
w = out.append
w("*KEYWORD")
name = "shell_tube_beams.k" if beams else "shell_tube_loads.k" if loads else "shell_tube_masses.k" if masses else "shell_tube.k"
w(f"$ tests/parallel/{name}: written by tests/parallel/make_shell_tube.py (do not edit by hand)")
w("*TITLE")
w("free shell tube with a solid collar: spin, stretch and swing, SI units (m kg s Pa)")
w("*CONTROL_TERMINATION")
w("    1.0e-4         0       0.0")
w("*CONTROL_TIMESTEP")
if masses:  # DT2MS < 0: the shells and solids whose step falls below it get mass
    w(f"       0.0       0.9         0       0.0{-DT2MS:10.2e}")
else:
    w("       0.0       0.9")
w("*DATABASE_BINARY_D3PLOT")
w("    1.0e-5")
w("*DATABASE_NODOUT")
w("    2.0e-6")
w("*DATABASE_ELOUT")
w("    2.0e-6")
w("*DATABASE_GLSTAT")
w("    2.0e-6")
w("*DATABASE_MATSUM")
w("    2.0e-6")
w("*DATABASE_HISTORY_NODE")
w(f"{nid(0, 0):10d}{nid(nt // 2, nz):10d}")
w("*DATABASE_HISTORY_SHELL")
w(f"{1:10d}{nt * nz // 2 + 5:10d}")
if beams:
    w("*DATABASE_HISTORY_BEAM")
    w(f"{nt * nz + nt + 1:10d}{nt * nz + 2 * nt + 1:10d}{nt * nz + 3 * nt + 1:10d}")
w("*DATABASE_HISTORY_SOLID")
w(f"{nt * nz + 1:10d}")
for p, (sec, mid, title) in enumerate([(1, 1, "steel, elastic, Belytschko-Tsay"),
                                      (2, 2, "copper, elastic-plastic, Belytschko-Tsay"),
                                      (3, 3, "aluminium, elastic, fully integrated")], start=1):
    w("*PART")
    w(title)
    w(f"{p:10d}{sec:10d}{mid:10d}         0         1")
w("*PART")
w("collar, steel solids")
w("         4         4         4         0         1")
w("*SECTION_SHELL")
w("         1         2 0.8333333         3")
w(f"{thick:10.4g}{thick:10.4g}{thick:10.4g}{thick:10.4g}")
w("*SECTION_SHELL")
w("         2         2 0.8333333         5")
w(f"{thick:10.4g}{thick:10.4g}{thick:10.4g}{thick:10.4g}")
w("*SECTION_SHELL")
w("         3        16 0.8333333         2")
w(f"{thick:10.4g}{thick:10.4g}{thick:10.4g}{thick:10.4g}")
w("*SECTION_SOLID")
w("         4         1")
w("*MAT_ELASTIC")
w("         1    7850.0   2.10e11      0.30")
w("*MAT_PLASTIC_KINEMATIC")
w("         2    8930.0   1.17e11      0.35     1.0e8     1.0e8       1.0")
w("       0.0       0.0       0.0       0.0")
w("*MAT_ELASTIC")
w("         3    2700.0   0.70e11      0.33")
w("*MAT_ELASTIC")
w("         4    7850.0   2.10e11      0.30")
if beams:
    w("*PART")
    w("ring of Hughes-Liu beams, steel, elastic-plastic")
    w("         5         5         5")
    w("*PART")
    w("ring of resultant beams, steel")
    w("         6         6         6")
    w("*PART")
    w("trusses across, steel")
    w("         7         7         6")
    w("*SECTION_BEAM")
    w("         5         1  0.833333         2         0")
    w("     0.001     0.001    0.0015    0.0015")
    w("*SECTION_BEAM")
    w("         6         2")
    w("    1.0e-6   8.3e-14   8.3e-14   1.4e-13")
    w("*SECTION_BEAM")
    w("         7         3")
    w("    1.0e-6")
    w("*MAT_PLASTIC_KINEMATIC")
    w("         5    7850.0   2.10e11      0.30     2.0e8     1.0e9       1.0")
    w("       0.0       0.0       0.0       0.0")
    w("*MAT_ELASTIC")
    w("         6    7850.0   2.10e11      0.30")
w("*HOURGLASS")
w("         1         4       0.1")
w("*NODE")
coords = {}
for k in range(nz + 1):
    for i in range(nt):
        a = 2 * math.pi * i / nt
        coords[nid(i, k)] = (radius * math.cos(a), radius * math.sin(a), length * k / nz)
for k in range(2):
    for i in range(nt):
        a = 2 * math.pi * i / nt
        coords[cid(i, k)] = ((radius + collar) * math.cos(a), (radius + collar) * math.sin(a), length * k / nz)
for n in sorted(coords):
    x, y, z = coords[n]
    w(f"{n:8d}{x:16.8e}{y:16.8e}{z:16.8e}       0       0")
w("*ELEMENT_SHELL")
e = 0
for k in range(nz):
    for i in range(nt):
        e += 1
        w(f"{e:8d}{part(k):8d}{nid(i, k):8d}{nid(i + 1, k):8d}{nid(i + 1, k + 1):8d}{nid(i, k + 1):8d}")
w("*ELEMENT_SOLID")
for i in range(nt):
    e += 1
    n = [nid(i, 0), cid(i, 0), cid(i + 1, 0), nid(i + 1, 0), nid(i, 1), cid(i, 1), cid(i + 1, 1), nid(i + 1, 1)]
    w(f"{e:8d}{4:8d}" + "".join(f"{v:8d}" for v in n))
if beams:
    w("*ELEMENT_BEAM")
    for i in range(nt):  # around the upper end, oriented by the node below
        e += 1
        w(f"{e:8d}{5:8d}{nid(i, nz):8d}{nid(i + 1, nz):8d}{nid(i, nz - 1):8d}")
    for i in range(nt):  # around the middle
        e += 1
        w(f"{e:8d}{6:8d}{nid(i, nz // 2):8d}{nid(i + 1, nz // 2):8d}{nid(i, nz // 2 - 1):8d}")
    for i in range(nt // 2):  # across
        e += 1
        w(f"{e:8d}{7:8d}{nid(i, nz - 4):8d}{nid(i + nt // 2, nz - 4):8d}")
w("*BOUNDARY_SPC_NODE")
w(f"{nid(nt // 4, nz):10d}         0         0         0         0         1         1         1")
w("*INITIAL_VELOCITY_NODE")
for n in sorted(coords):
    x, y, z = coords[n]
    vx, vy, vz = -omega * y + swing * z / length, omega * x, vend * (2 * z / length - 1)
    w(f"{n:10d}{vx:10.4f}{vy:10.4f}{vz:10.4f}{0.0:10.4f}{0.0:10.4f}{omega:10.4f}")
if loads:
    w("*DEFINE_CURVE_TITLE")
    w("ramp to 1 in 20 us, then held")
    w("         1")
    for a, o in [(0.0, 0.0), (2.0e-5, 1.0), (1.0e-3, 1.0)]:
        w(f"{a:20.6e}{o:20.6e}")
    w("*DEFINE_CURVE_TITLE")
    w("constant 1")
    w("         2")
    for a, o in [(0.0, 1.0), (1.0e-3, 1.0)]:
        w(f"{a:20.6e}{o:20.6e}")
    w("*LOAD_SEGMENT")  # the shells' normal points outward: a negative pressure pushes out
    for k in range(4, 12):
        for i in range(nt):
            w(f"         1    -2.0e6    1.0e-5{nid(i, k):10d}{nid(i + 1, k):10d}{nid(i + 1, k + 1):10d}{nid(i, k + 1):10d}")
    w("*LOAD_BODY_Y")
    w("         1    1.0e5")
    w("*BOUNDARY_PRESCRIBED_MOTION_NODE")
    for i in range(nt):
        w(f"{nid(i, 0):10d}         3         0         2     -60.0")
    w(f"{nid(nt // 2, nz):10d}         6         0         2  {omega:8.1f}")
w("*END")
print("\n".join(out))
