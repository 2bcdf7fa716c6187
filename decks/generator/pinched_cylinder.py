#!/usr/bin/env python3
"""Writes the pinched cylinder keyword deck (decks/keyword/pinched_cylinder.k).

    python3 decks/generator/pinched_cylinder.py [--n N] [--ihq 4] [--qm 0.1] > cylinder.k

The benchmark (MacNeal and Harder 1985): a cylinder, radius R = 300, length L = 600, thickness
3, E = 3e6, nu = 0.3, supported at its ends by rigid diaphragms (the displacements in the
diaphragm's plane zero, the axial one free), pinched at mid-length by two opposite radial loads
P = 1.  Reference: radial displacement 1.8248e-5 under a load.

Octant model: x (the axis) from the midspan (x = 0, symmetry: ux = 0, ry = rz = 0) to the
diaphragm (x = 300: uy = uz = 0), the arc from the loaded generator at the top (angle 0: y = 0,
z = R; symmetry: uy = 0, rx = rz = 0) to the side (90 degrees: z = 0; symmetry: uz = 0,
rx = ry = 0); N x N Belytschko-Tsay shells; P / 4 on node 1 (x = 0, top) toward -z, ramped over
the first fifth of the run and held.  Consistent units (the benchmark's); rho = 1 (only the
dynamics of the relaxation depend on it).  The static answer is reached by dynamic relaxation:
*DAMPING_GLOBAL, mass-weighted damping D near twice the lowest circular frequency.
"""
import argparse
import math


def e16(v):
    s = "%.9e" % v
    return "%16s" % s


def i(v, w=10):
    return "%*d" % (w, v)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=16, help="shells per side of the octant model")
    ap.add_argument("--ihq", type=int, default=4, help="hourglass type (4: stiffness)")
    ap.add_argument("--qm", type=float, default=0.1, help="hourglass coefficient")
    ap.add_argument("--damping", type=float, default=0.5, help="*DAMPING_GLOBAL VALDMP (1/time)")
    ap.add_argument("--end", type=float, default=300.0, help="termination time")
    a = ap.parse_args()
    n = a.n
    R, half_len, t = 300.0, 300.0, 3.0
    out = []
    w = out.append
    w("*KEYWORD")
    w("$ pinched_cylinder.k: written by decks/generator/pinched_cylinder.py --n %d --ihq %d --qm %g --damping %g --end %g"
      % (n, a.ihq, a.qm, a.damping, a.end))
    w("$ Pinched cylinder (MacNeal-Harder 1985): R 300, L 600, t 3, E 3e6, nu 0.3, rigid diaphragms,")
    w("$ two opposite loads P = 1 at mid-length; octant model %d x %d Belytschko-Tsay shells, P/4 on" % (n, n))
    w("$ node 1; reference radial displacement 1.8248e-5 under the load.")
    w("$ Static answer by dynamic relaxation (*DAMPING_GLOBAL). README \"Shells\".")
    w("*TITLE")
    w("Pinched cylinder, octant model %dx%d, dynamic relaxation" % (n, n))
    w("*CONTROL_TERMINATION")
    w("%10g" % a.end)
    w("*DATABASE_BINARY_D3PLOT")
    w("%10g" % (a.end / 4))
    w("*DATABASE_NODOUT")
    w("%10g" % (a.end / 200))
    w("*DATABASE_HISTORY_NODE")
    w(i(1))
    w("*PART")
    w("cylinder")
    w("$     pid     secid       mid     eosid      hgid")
    w(i(1) + i(1) + i(1) + i(0) + i(1))
    w("*SECTION_SHELL")
    w("$   secid    elform      shrf       nip")
    w(i(1) + i(2) + "%10.7f" % (5.0 / 6.0) + i(2))
    w("%10g" % t)
    w("*MAT_ELASTIC")
    w("$     mid        ro         e        pr")
    w(i(1) + "%10g" % 1.0 + "%10g" % 3e6 + "%10g" % 0.3)
    w("*HOURGLASS")
    w("$    hgid       ihq        qm")
    w(i(1) + i(a.ihq) + "%10g" % a.qm)
    w("*NODE")
    # node (k along x, j along the arc): id = 1 + j (n + 1) + k, x = 300 k / n, angle 90 j / n
    # from the top; the loaded point (x = 0, top) is node 1
    for j in range(n + 1):
        th = 0.5 * math.pi * j / n
        for k in range(n + 1):
            x = half_len * k / n
            y = R if j == n else R * math.sin(th)
            z = 0.0 if j == n else R * math.cos(th)
            w("%8d" % (1 + j * (n + 1) + k) + e16(x) + e16(y) + e16(z))
    w("*ELEMENT_SHELL")
    e = 0
    for j in range(n):
        for k in range(n):
            e += 1
            n1 = 1 + j * (n + 1) + k
            # outward normal: x cross (the arc's direction) points out of the cylinder
            w("%8d%8d%8d%8d%8d%8d" % (e, 1, n1, n1 + 1, n1 + 1 + n + 1, n1 + n + 1))
    w("*BOUNDARY_SPC_NODE")
    w("$     nid       cid      dofx      dofy      dofz     dofrx     dofry     dofrz")
    for j in range(n + 1):
        for k in range(n + 1):
            f = [0] * 6
            if k == 0:       # midspan symmetry plane x = 0
                f[0] = f[4] = f[5] = 1
            if k == n:       # rigid diaphragm
                f[1] = f[2] = 1
            if j == 0:       # symmetry plane y = 0 (through the loads)
                f[1] = f[3] = f[5] = 1
            if j == n:       # symmetry plane z = 0
                f[2] = f[3] = f[4] = 1
            if any(f):
                w(i(1 + j * (n + 1) + k) + i(0) + "".join(i(v) for v in f))
    w("*DEFINE_CURVE")
    w(i(1))
    w("%20g%20g" % (0.0, 0.0))
    w("%20g%20g" % (a.end / 5, 1.0))
    w("%20g%20g" % (1e6, 1.0))
    w("*LOAD_NODE_POINT")
    w("$     nid       dof      lcid        sf")
    w(i(1) + i(3) + i(1) + "%10g" % -0.25)
    w("*DAMPING_GLOBAL")
    w("$    lcid    valdmp")
    w(i(0) + "%10g" % a.damping)
    w("*END")
    print("\n".join(out))


if __name__ == "__main__":
    main()
