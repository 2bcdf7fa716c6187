#!/usr/bin/env python3
"""Runs real DYNA3D decks and compares IMPACT-3D's answers with DYNA3D's.

The folder is laid out as LLNL GRIZ's regression tests are (repository mdg-graphics/griz,
Src/test): DIR/image/NAME/NAME.dyn (the deck) and DIR/derived/NAME_th.answ (GRIZ's text dump of
DYNA3D's time histories: node positions and displacements, element stresses and plastic
strains, one row per state).  For each deck with an answer file: impact3d runs it (in
OUT/NAME), POST-IMPACT writes our curves (history ... CSV), and every answer curve is compared
with ours at DYNA3D's times (ours interpolated linearly between our states); where DYNA3D's own
plot database lies beside the deck (image/NAME/NAME.pltA, LLNL Mili), POST-IMPACT's compare gives
the largest node-position difference over all nodes and states.  Printed per curve:
the largest deviation over the answer times, the value at the end time (DYNA3D, IMPACT-3D), and
PASS/FAIL against the deck's tolerance (tolerance table below; curves without one are shown as
"info").  Exit status: 0 all compared curves pass, 1 some fail, 2 a deck did not run.

Usage: tools/check-dyna3d-decks.sh DIR [OUT]   (this script: python3 check_dyna3d_decks.py ...)
"""
import csv
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

# The tolerances of the real-DYNA3D-decks issue, per deck: (kind, scale, fraction).
#  kind "position": node positions/displacements, within fraction x scale (a length);
#  kind "eps_end": effective plastic strain at the end time, within fraction x DYNA3D's value.
# scale "length0": the model's first extent along its longest axis; "peak": the largest |value|
# of the curve family (DYNA3D's); "maxdisp": DYNA3D's largest displacement over the curves.
TOLERANCES = {
    "bar71": [("position", "length0", 0.01), ("eps_end", None, 0.05)],
    "plate71": [("zdisp", "peak", 0.03)],
    "d3samp6": [("position", "maxdisp", 0.02)],
    "bending-71": [("position", "maxdisp", 0.02)],
}

# GRIZ's names -> POST-IMPACT history quantities (node or element)
QUANTITY = {
    "Node Position[X Position]": ("node", "x"),
    "Node Position[Y Position]": ("node", "y"),
    "Node Position[Z Position]": ("node", "z"),
    "X Displacement": ("node", "dx"),
    "Y Displacement": ("node", "dy"),
    "Z Displacement": ("node", "dz"),
    "Displacement Magnitude": ("node", "disp"),
    "Equiv. Plastic Strain": ("element", "eps"),
    "X Stress": ("element", "sxx"),
    "Y Stress": ("element", "syy"),
    "Z Stress": ("element", "szz"),
    "XY Stress": ("element", "sxy"),
    "YZ Stress": ("element", "syz"),
    "ZX Stress": ("element", "szx"),
}
FAMILY = {"Node": "node", "Bricks": "solid", "Brick": "solid", "Shell": "shell", "Shells": "shell",
          "Beam": "beam", "Beams": "beam"}


def parse_answers(path):
    """Curves of a GRIZ .answ file: dicts with family, id, quantity, ref_state, t, v."""
    curves, cur, ref = [], None, None
    with open(path, errors="replace") as f:
        for line in f:
            s = line.strip()
            m = re.match(r"#\s*(\w+)\s*-\s*(\d+):\s*(.+)$", s)
            if m and m.group(1) in FAMILY:
                cur = {"family": FAMILY[m.group(1)], "id": int(m.group(2)), "quantity": m.group(3).strip(),
                       "ref_state": ref, "t": [], "v": []}
                curves.append(cur)
                ref = None
                continue
            m = re.match(r"#.*\breference state:\s*(\d+)", s)
            if m and "Displacement" in s:
                ref = int(m.group(1))
                continue
            if s.startswith("#") or not s:
                if s.startswith("# Curve"):
                    cur = None
                continue
            if cur is not None:
                parts = s.split()
                try:
                    cur["t"].append(float(parts[0]))
                    cur["v"].append(float(parts[1]))
                except (ValueError, IndexError):
                    pass
    # the same curve may be dumped twice (GRIZ appends): keep the first of each
    seen, unique = set(), []
    for c in curves:
        key = (c["family"], c["id"], c["quantity"])
        if key in seen or not c["t"]:
            continue
        seen.add(key)
        unique.append(c)
    return unique


def interp(ts, vs, t):
    if t <= ts[0]:
        return vs[0]
    for k in range(1, len(ts)):
        if t <= ts[k]:
            a = (t - ts[k - 1]) / (ts[k] - ts[k - 1]) if ts[k] > ts[k - 1] else 1.0
            return vs[k - 1] + a * (vs[k] - vs[k - 1])
    return vs[-1]


def run(cmd, cwd):
    return subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def our_curves(postimpact, db, outdir, curves):
    """Our values of every comparable curve, one POST-IMPACT history call per family."""
    groups = []
    for c in curves:
        q = QUANTITY.get(c["quantity"])
        if not q:
            continue
        name = c["family"] if q[0] == "element" else "node"
        groups.append((c, "%s %d %s" % (name, c["id"], q[1])))
    if not groups:
        return {}
    result = {}
    for k in range(0, len(groups), 20):  # a few curves a call (the PNG stays readable)
        chunk = groups[k:k + 20]
        png = os.path.join(outdir, "check_%d.png" % (k // 20))
        r = run([postimpact, db, "-d", outdir, "-e", "history %s %s" % (os.path.basename(png), " ".join(g for _, g in chunk))], outdir)
        csv_path = png[:-4] + ".csv"
        if r.returncode != 0 or not os.path.exists(csv_path):
            print("    postimpact failed: " + r.stdout.strip().splitlines()[-1] if r.stdout.strip() else "    postimpact failed")
            continue
        with open(csv_path) as f:
            rows = list(csv.reader(f))
        head, data = rows[0], rows[1:]
        times = [float(r[1]) for r in data]
        for j, (c, _) in enumerate(chunk):
            col = 2 + j
            result[id(c)] = (times, [float(r[col]) for r in data])
    return result


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    base = os.path.abspath(sys.argv[1])
    out = os.path.abspath(sys.argv[2]) if len(sys.argv) > 2 else os.path.join(os.getcwd(), "dyna3d-check")
    impact3d = os.path.abspath(os.environ.get("IMPACT3D", os.path.join(ROOT, "build", "impact3d")))
    postimpact = os.path.abspath(os.environ.get("POSTIMPACT", os.path.join(ROOT, "build", "postimpact", "postimpact")))
    image = os.path.join(base, "image") if os.path.isdir(os.path.join(base, "image")) else base
    derived = os.path.join(base, "derived")
    status = 0
    for name in sorted(os.listdir(image)):
        deck = os.path.join(image, name, name + ".dyn")
        answ = os.path.join(derived, name + "_th.answ")
        if not os.path.exists(deck):
            continue
        wd = os.path.join(out, name)
        os.makedirs(wd, exist_ok=True)
        print("== %s" % name)
        r = run([impact3d, "i=" + deck, "o=d3hsp", "g=d3plot"], wd)
        last = [l for l in r.stdout.splitlines() if l.strip()]
        if r.returncode != 0:
            errs = [l for l in r.stdout.splitlines() if " error " in l]
            print("   not run (exit %d): %s" % (r.returncode, last[-1].strip() if last else ""))
            for l in errs[:5]:
                print("     " + l.strip())
            status = max(status, 2)
            continue
        ratio = [l for l in r.stdout.splitlines() if "energy ratio" in l]
        print("   ran: %s; %s" % (last[-1].strip(), ratio[-1].strip() if ratio else ""))
        if not os.path.exists(answ):
            print("   no answer file %s" % answ)
            continue
        curves = parse_answers(answ)
        ours = our_curves(postimpact, os.path.join(wd, "d3plot"), wd, curves)
        tol = TOLERANCES.get(name, [])
        # scales
        pos_curves = [c for c in curves if QUANTITY.get(c["quantity"], ("", ""))[0] == "node"]
        peak = max([abs(v) for c in pos_curves if "Displacement" in c["quantity"] for v in c["v"]] or [0.0])
        maxdisp = 0.0
        for c in pos_curves:
            maxdisp = max(maxdisp, max(c["v"]) - min(c["v"]))
        length0 = 0.0
        summ = run([postimpact, "summary", os.path.join(wd, "d3plot")], wd).stdout
        m = re.search(r"^length0 (\S+)", summ, re.M)
        if m:
            length0 = float(m.group(1))
        print("   %-8s %-6s %-28s %12s %13s %13s  %s" % ("family", "id", "quantity", "max |dev|", "DYNA3D end", "IMPACT-3D end", "verdict"))
        for c in curves:
            key = id(c)
            if key not in ours:
                continue
            ts, vs = ours[key]
            ref_t = c["t"][c["ref_state"] - 1] if c["ref_state"] and c["ref_state"] <= len(c["t"]) else None
            ref_v = interp(ts, vs, ref_t) if ref_t is not None else 0.0
            dev = 0.0
            for t, v in zip(c["t"], c["v"]):
                dev = max(dev, abs(interp(ts, vs, t) - ref_v - v))
            end_ours = interp(ts, vs, c["t"][-1]) - ref_v
            kind = QUANTITY[c["quantity"]][0]
            verdict = "info"
            if c["family"] == "beam" and "Stress" in c["quantity"]:
                # DYNA3D's beam point stresses are global-axis components at one point; ours the
                # beam's axial and shear stresses (mean of the points): not the same quantity
                verdict = "info (DYNA3D: global axes, one point)"
            for (k, scale, frac) in tol:
                if (k == "position" and kind == "node") or (k == "zdisp" and c["quantity"] == "Z Displacement"):
                    s = {"length0": length0, "peak": peak, "maxdisp": maxdisp}[scale]
                    limit = frac * s
                    verdict = "PASS" if dev <= limit else "FAIL"
                    verdict += " (<= %.3g)" % limit
                if k == "eps_end" and c["quantity"] == "Equiv. Plastic Strain":
                    limit = frac * abs(c["v"][-1])
                    d_end = abs(end_ours - c["v"][-1])
                    verdict = ("PASS" if d_end <= limit else "FAIL") + " (end %.3g <= %.3g)" % (d_end, limit)
            if verdict.startswith("FAIL"):
                status = max(status, 1)
            print("   %-8s %-6d %-28s %12.4e %13.5e %13.5e  %s" % (c["family"], c["id"], c["quantity"][:28], dev, c["v"][-1], end_ours, verdict))
        full_field(postimpact, os.path.join(wd, "d3plot"), os.path.join(image, name, name + ".pltA"), wd)
        beam_field(postimpact, os.path.join(wd, "d3plot"), os.path.join(image, name, name + ".pltA"), wd)
    return status


def full_field(postimpact, ours, mili, wd):
    """The largest node-position difference over all nodes and states against DYNA3D's own
    database (LLNL Mili, NAME.pltA beside the deck), by POST-IMPACT's compare (states by time)."""
    if not os.path.exists(mili):
        return
    r = run([postimpact, "compare", ours, mili, "--report", "1"], wd)
    coords = [l for l in r.stdout.splitlines() if l.startswith("coords")]
    states = [l for l in r.stdout.splitlines() if l.startswith("states:")]
    if coords:
        f = coords[0].split()
        print("   full field vs %s: largest node-position difference %s at %s; %s" %
              (os.path.basename(mili), f[3], " ".join(f[6:]), states[0] if states else ""))
    else:
        last = [l for l in r.stdout.splitlines() if l.strip()]
        print("   full field vs %s: not compared (%s)" % (os.path.basename(mili), last[-1] if last else "no output"))


def history_table(postimpact, db, wd, words, tag):
    """Times and columns of one POST-IMPACT history call (None if it failed)."""
    png = os.path.join(wd, "beams_%s.png" % tag)
    r = run([postimpact, db, "-d", wd, "-e", "history %s %s" % (os.path.basename(png), " ".join(words))], wd)
    csv_path = png[:-4] + ".csv"
    if r.returncode != 0 or not os.path.exists(csv_path):
        return None
    with open(csv_path) as f:
        rows = list(csv.reader(f))[1:]
    return [float(x[1]) for x in rows], [[float(x[2 + j]) for x in rows] for j in range(len(words) // 2)]


def beam_field(postimpact, ours, mili, wd):
    """Per beam, against DYNA3D's own database: the plastic strain (mean of the section's points)
    and the axial force, largest deviation over DYNA3D's states and the end values (information:
    where the beams' plastic response differs).  The Mili reader turns DYNA3D's point stresses
    (global axes) into the beam's axes, as ours."""
    if not os.path.exists(mili):
        return
    m = re.search(r"^beams (\d+)", run([postimpact, "summary", mili], wd).stdout, re.M)
    nb = int(m.group(1)) if m else 0
    if nb == 0:
        return
    words = []
    for b in range(1, nb + 1):
        words += ["beam", str(b), "eps", "axial_force"]
    print("   beams vs %s (mean plastic strain of the section points, axial force; information):" % os.path.basename(mili))
    print("   %-6s %12s %10s %10s %12s" % ("beam", "eps max|dev|", "DYNA3D end", "ours end", "N max|dev|"))
    for k in range(0, len(words), 40):  # 10 beams a call
        chunk = words[k:k + 40]
        d = history_table(postimpact, mili, wd, chunk, "d%d" % k)
        o = history_table(postimpact, ours, wd, chunk, "o%d" % k)
        if d is None or o is None:
            print("   (postimpact failed)")
            return
        (td, dv), (to, ov) = d, o
        for j in range(0, len(chunk) // 4):
            eps_d, eps_o, n_d, n_o = dv[2 * j], ov[2 * j], dv[2 * j + 1], ov[2 * j + 1]
            de = max(abs(interp(to, eps_o, t) - v) for t, v in zip(td, eps_d))
            dn = max(abs(interp(to, n_o, t) - v) for t, v in zip(td, n_d))
            print("   %-6s %12.4f %10.4f %10.4f %12.4g" % (chunk[4 * j + 1], de, eps_d[-1], interp(to, eps_o, td[-1]), dn))


if __name__ == "__main__":
    sys.exit(main())
