#!/usr/bin/env python3
"""Writes the Scordelis-Lo roof keyword deck (decks/keyword/scordelis_lo_roof.k).

    python3 decks/generator/scordelis_lo_roof.py [--n N] [--ihq 4] [--qm 0.05] [--load 0.01] > roof.k

The benchmark (MacNeal and Harder 1985): a cylindrical roof, radius R = 25, length L = 50,
half-angle 40 degrees, thickness 0.25, E = 4.32e8, nu = 0, self weight 90 per unit area
(vertical), supported at the curved ends by rigid diaphragms (uy = uz = 0), the straight edges
free.  Reference (linear theory): vertical displacement 0.3024 at the middle of the free edge.
The reference is a linear answer and the full load deflects the free edge by 1.2 thicknesses,
enough for the geometric stiffening of the explicit (large-displacement) solution to show
(16 x 16: 0.2536 at the full load, 0.3002 per unit load at 1 %): the deck applies --load (default
0.01) of the self weight, and the displacement divided by it is compared with 0.3024.

Quarter model: x (the cylinder's axis) from the midspan (x = 0, symmetry: ux = 0, ry = rz = 0)
to the diaphragm (x = 25: uy = uz = 0), the arc from the crown (y = 0, symmetry: uy = 0,
rx = rz = 0) to the free edge (40 degrees); N x N Belytschko-Tsay shells.  Consistent units
(the benchmark's: length, force); rho = 360 so that rho t = 90 per unit area under
*LOAD_BODY_Z with g = 1 (a positive value pulls toward -z).  The static answer is reached by
dynamic relaxation: *DAMPING_GLOBAL, mass-weighted damping D near twice the lowest circular
frequency (about 2 rad/s in these units), over 20 time units.
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
    ap.add_argument("--n", type=int, default=16, help="shells per side of the quarter model")
    ap.add_argument("--ihq", type=int, default=4, help="hourglass type (4: stiffness)")
    ap.add_argument("--qm", type=float, default=0.1, help="hourglass coefficient")
    ap.add_argument("--damping", type=float, default=4.0, help="*DAMPING_GLOBAL VALDMP (1/time)")
    ap.add_argument("--end", type=float, default=20.0, help="termination time")
    ap.add_argument("--load", type=float, default=0.01, help="fraction of the self weight applied")
    a = ap.parse_args()
    n = a.n
    R, half_len, phi = 25.0, 25.0, math.radians(40.0)
    out = []
    w = out.append
    w("*KEYWORD")
    w("$ scordelis_lo_roof.k: written by decks/generator/scordelis_lo_roof.py --n %d --ihq %d --qm %g --damping %g --end %g --load %g"
      % (n, a.ihq, a.qm, a.damping, a.end, a.load))
    w("$ Scordelis-Lo roof (MacNeal-Harder 1985): R 25, L 50, 40 degrees, t 0.25, E 4.32e8, nu 0,")
    w("$ self weight 90 per unit area; quarter model %d x %d Belytschko-Tsay shells; reference" % (n, n))
    w("$ vertical displacement 0.3024 at the middle of the free edge (node %d), linear theory:" % (1 + n * (n + 1)))
    w("$ the load is %g x the self weight (*LOAD_BODY_Z SF) and w / %g is compared." % (a.load, a.load))
    w("$ Static answer by dynamic relaxation (*DAMPING_GLOBAL). README \"Shells\".")
    w("*TITLE")
    w("Scordelis-Lo roof, quarter model %dx%d, dynamic relaxation" % (n, n))
    w("*CONTROL_TERMINATION")
    w("%10g" % a.end)
    w("*DATABASE_BINARY_D3PLOT")
    w("%10g" % (a.end / 4))
    w("*DATABASE_NODOUT")
    w("%10g" % (a.end / 200))
    w("*DATABASE_HISTORY_NODE")
    w(i(1 + n * (n + 1)))
    w("*PART")
    w("roof")
    w("$     pid     secid       mid     eosid      hgid")
    w(i(1) + i(1) + i(1) + i(0) + i(1))
    w("*SECTION_SHELL")
    w("$   secid    elform      shrf       nip")
    w(i(1) + i(2) + "%10.7f" % (5.0 / 6.0) + i(2))
    w("%10g" % 0.25)
    w("*MAT_ELASTIC")
    w("$     mid        ro         e        pr")
    w(i(1) + "%10g" % 360.0 + "%10g" % 4.32e8 + "%10g" % 0.0)
    w("*HOURGLASS")
    w("$    hgid       ihq        qm")
    w(i(1) + i(a.ihq) + "%10g" % a.qm)
    w("*NODE")
    # node (k along x, j along the arc): id = 1 + j (n + 1) + k, x = 25 k / n, angle 40 j / n;
    # the middle of the free edge (x = 0, 40 degrees) is node 1 + n (n + 1)
    for j in range(n + 1):
        t = phi * j / n
        for k in range(n + 1):
            x = half_len * k / n
            w("%8d" % (1 + j * (n + 1) + k) + e16(x) + e16(R * math.sin(t)) + e16(R * math.cos(t)))
    w("*ELEMENT_SHELL")
    e = 0
    for j in range(n):
        for k in range(n):
            e += 1
            n1 = 1 + j * (n + 1) + k
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
            if j == 0:       # crown symmetry plane y = 0
                f[1] = f[3] = f[5] = 1
            if any(f):
                w(i(1 + j * (n + 1) + k) + i(0) + "".join(i(v) for v in f))
    w("*DEFINE_CURVE")
    w(i(1))
    w("%20g%20g" % (0.0, 1.0))
    w("%20g%20g" % (1e6, 1.0))
    w("*LOAD_BODY_Z")
    w("$    lcid        sf")
    w(i(1) + "%10g" % a.load)
    w("*DAMPING_GLOBAL")
    w("$    lcid    valdmp")
    w(i(0) + "%10g" % a.damping)
    w("*END")
    print("\n".join(out))


if __name__ == "__main__":
    main()
