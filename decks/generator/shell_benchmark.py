"""Card writers shared by the shell benchmark deck generators (scordelis_lo_roof.py,
pinched_cylinder.py): both are a cylindrical patch of N x N Belytschko-Tsay shells on an
(n + 1) x (n + 1) node grid, elastic, one hourglass card, symmetry and diaphragm constraints by
*BOUNDARY_SPC_NODE, and dynamic relaxation by *DAMPING_GLOBAL.  Node (k along the axis x, j
along the arc) has id 1 + j (n + 1) + k; shell (j, k) joins its four corner nodes."""


def e16(v):
    s = "%.9e" % v
    return "%16s" % s


def i(v, w=10):
    return "%*d" % (w, v)


def node_id(n, j, k):
    return 1 + j * (n + 1) + k


def add_common_arguments(ap, damping, end):
    ap.add_argument("--ihq", type=int, default=4, help="hourglass type (4: stiffness)")
    ap.add_argument("--qm", type=float, default=0.1, help="hourglass coefficient")
    ap.add_argument("--damping", type=float, default=damping, help="*DAMPING_GLOBAL VALDMP (1/time)")
    ap.add_argument("--end", type=float, default=end, help="termination time")


def write_controls(w, title, end, history_node):
    """*TITLE, termination, the plot and nodout intervals, the one history node."""
    w("$ Static answer by dynamic relaxation (*DAMPING_GLOBAL). README \"Shells\".")
    w("*TITLE")
    w(title)
    w("*CONTROL_TERMINATION")
    w("%10g" % end)
    w("*DATABASE_BINARY_D3PLOT")
    w("%10g" % (end / 4))
    w("*DATABASE_NODOUT")
    w("%10g" % (end / 200))
    w("*DATABASE_HISTORY_NODE")
    w(i(history_node))


def write_elastic_shell_part(w, name, thickness, rho, e, nu, ihq, qm):
    """Part 1: *SECTION_SHELL ELFORM 2, SHRF 5/6, NIP 2; *MAT_ELASTIC; *HOURGLASS."""
    w("*PART")
    w(name)
    w("$     pid     secid       mid     eosid      hgid")
    w(i(1) + i(1) + i(1) + i(0) + i(1))
    w("*SECTION_SHELL")
    w("$   secid    elform      shrf       nip")
    w(i(1) + i(2) + "%10.7f" % (5.0 / 6.0) + i(2))
    w("%10g" % thickness)
    w("*MAT_ELASTIC")
    w("$     mid        ro         e        pr")
    w(i(1) + "%10g" % rho + "%10g" % e + "%10g" % nu)
    w("*HOURGLASS")
    w("$    hgid       ihq        qm")
    w(i(1) + i(ihq) + "%10g" % qm)


def write_grid(w, n, position):
    """*NODE from position(j, k) -> (x, y, z) and the n x n *ELEMENT_SHELL grid."""
    w("*NODE")
    for j in range(n + 1):
        for k in range(n + 1):
            x, y, z = position(j, k)
            w("%8d" % node_id(n, j, k) + e16(x) + e16(y) + e16(z))
    w("*ELEMENT_SHELL")
    e = 0
    for j in range(n):
        for k in range(n):
            e += 1
            n1 = node_id(n, j, k)
            # x cross the arc's direction: the outward normal of the cylinder
            w("%8d%8d%8d%8d%8d%8d" % (e, 1, n1, n1 + 1, n1 + 1 + n + 1, n1 + n + 1))


def write_spc(w, n, flags):
    """*BOUNDARY_SPC_NODE for every node where flags(j, k) -> [dofx .. dofrz] fixes something."""
    w("*BOUNDARY_SPC_NODE")
    w("$     nid       cid      dofx      dofy      dofz     dofrx     dofry     dofrz")
    for j in range(n + 1):
        for k in range(n + 1):
            f = flags(j, k)
            if any(f):
                w(i(node_id(n, j, k)) + i(0) + "".join(i(v) for v in f))


def write_curve(w, points):
    w("*DEFINE_CURVE")
    w(i(1))
    for t, f in points:
        w("%20g%20g" % (t, f))


def write_damping_and_end(w, damping):
    w("*DAMPING_GLOBAL")
    w("$    lcid    valdmp")
    w(i(0) + "%10g" % damping)
    w("*END")


def symmetry_and_diaphragm_flags(n, j, k):
    """Constraints both benchmarks share: midspan symmetry plane x = 0 (k = 0), the rigid
    diaphragm at the end (k = n: uy = uz = 0), the symmetry plane y = 0 (j = 0)."""
    f = [0] * 6
    if k == 0:
        f[0] = f[4] = f[5] = 1
    if k == n:
        f[1] = f[2] = 1
    if j == 0:
        f[1] = f[3] = f[5] = 1
    return f


