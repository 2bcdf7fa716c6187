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

from shell_benchmark import (add_common_arguments, i, node_id, symmetry_and_diaphragm_flags, write_controls,
                             write_curve, write_damping_and_end, write_elastic_shell_part, write_grid, write_spc)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=16, help="shells per side of the quarter model")
    add_common_arguments(ap, damping=4.0, end=20.0)
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
    w("$ vertical displacement 0.3024 at the middle of the free edge (node %d), linear theory:" % node_id(n, n, 0))
    w("$ the load is %g x the self weight (*LOAD_BODY_Z SF) and w / %g is compared." % (a.load, a.load))
    write_controls(w, "Scordelis-Lo roof, quarter model %dx%d, dynamic relaxation" % (n, n), a.end, node_id(n, n, 0))
    write_elastic_shell_part(w, "roof", 0.25, 360.0, 4.32e8, 0.0, a.ihq, a.qm)

    # x = 25 k / n along the axis, angle 40 j / n from the crown; the middle of the free edge
    # (x = 0, 40 degrees) is node 1 + n (n + 1)
    def position(j, k):
        t = phi * j / n
        return half_len * k / n, R * math.sin(t), R * math.cos(t)

    write_grid(w, n, position)
    # midspan symmetry (x = 0), rigid diaphragm (x = 25), crown symmetry plane y = 0
    write_spc(w, n, lambda j, k: symmetry_and_diaphragm_flags(n, j, k))
    write_curve(w, [(0.0, 1.0), (1e6, 1.0)])
    w("*LOAD_BODY_Z")
    w("$    lcid        sf")
    w(i(1) + "%10g" % a.load)
    write_damping_and_end(w, a.damping)
    print("\n".join(out))


if __name__ == "__main__":
    main()
