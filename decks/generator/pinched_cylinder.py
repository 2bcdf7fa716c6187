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

from shell_benchmark import (add_common_arguments, i, symmetry_and_diaphragm_flags, write_controls, write_curve,
                             write_damping_and_end, write_elastic_shell_part, write_grid, write_spc)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=16, help="shells per side of the octant model")
    add_common_arguments(ap, damping=0.5, end=300.0)
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
    write_controls(w, "Pinched cylinder, octant model %dx%d, dynamic relaxation" % (n, n), a.end, 1)
    write_elastic_shell_part(w, "cylinder", t, 1.0, 3e6, 0.3, a.ihq, a.qm)

    # x = 300 k / n along the axis, angle 90 j / n from the top; the loaded point (x = 0, top)
    # is node 1; the side (j = n) exactly on z = 0
    def position(j, k):
        th = 0.5 * math.pi * j / n
        return half_len * k / n, R if j == n else R * math.sin(th), 0.0 if j == n else R * math.cos(th)

    write_grid(w, n, position)

    # the shared constraints (symmetry plane y = 0 through the loads) and the symmetry plane z = 0
    def flags(j, k):
        f = symmetry_and_diaphragm_flags(n, j, k)
        if j == n:
            f[2] = f[3] = f[4] = 1
        return f

    write_spc(w, n, flags)
    write_curve(w, [(0.0, 0.0), (a.end / 5, 1.0), (1e6, 1.0)])
    w("*LOAD_NODE_POINT")
    w("$     nid       dof      lcid        sf")
    w(i(1) + i(3) + i(1) + "%10g" % -0.25)
    write_damping_and_end(w, a.damping)
    print("\n".join(out))


if __name__ == "__main__":
    main()
