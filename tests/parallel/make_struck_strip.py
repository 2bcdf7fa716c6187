#!/usr/bin/env python3
"""Writes tests/parallel/struck_strip.k (python3 tests/parallel/make_struck_strip.py > tests/parallel/struck_strip.k).

A free strip struck in its plane, for the distributed runs' run checks: 6 x 8 Belytschko-Tsay
shells (10 mm squares, 1 mm elastic steel with nu = 0, IHQ 1, TSSFAC 0.9), the right half of its
nodes starting at 1 m/s along it.  A velocity jump on a mesh this coarse puts much of the energy
in modes near the step's limit: the printed energy ratio swings outside its band while the
time-centred ratio holds, and the run checks say 5106 (not 5102) - the strip of the run checks'
test (tests/solve/test_run_checks.cpp) eight shells wide, so that it has 6 blocks of 8 shells.
500 us, 5 plot states, the energies (glstat) every 10 us.
"""
nx, ny, h = 6, 8, 0.010


def nid(i, j):
    return 1 + i + (nx + 1) * j


out = []
w = out.append
w("*KEYWORD")
w("$ tests/parallel/struck_strip.k: written by tests/parallel/make_struck_strip.py (do not edit by hand)")
w("*TITLE")
w("free steel strip struck in its plane, SI units (m kg s Pa)")
w("*CONTROL_TERMINATION")
w("    0.0005")
w("*CONTROL_TIMESTEP")
w("       0.0       0.9")
w("*DATABASE_BINARY_D3PLOT")
w("    1.0e-4")
w("*DATABASE_GLSTAT")
w("    1.0e-5")
w("*PART")
w("strip")
w("         1         1         1")
w("*SECTION_SHELL")
w("         1         2       1.0         2")
w("     0.001     0.001     0.001     0.001")
w("*MAT_ELASTIC")
w("         1    7850.0   2.1e+11       0.0")
w("*NODE")
for j in range(ny + 1):
    for i in range(nx + 1):
        w(f"{nid(i, j):8d}{h * i:16.3f}{h * j:16.3f}{0.0:16.1f}")
w("*ELEMENT_SHELL")
e = 0
for j in range(ny):
    for i in range(nx):
        e += 1
        w(f"{e:8d}{1:8d}{nid(i, j):8d}{nid(i + 1, j):8d}{nid(i + 1, j + 1):8d}{nid(i, j + 1):8d}")
w("*INITIAL_VELOCITY_NODE")
for j in range(ny + 1):
    for i in range(nx // 2 + 1, nx + 1):
        w(f"{nid(i, j):8d}       1.0       0.0       0.0")
w("*END")
print("\n".join(out))
