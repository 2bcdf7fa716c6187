#!/usr/bin/env python3
"""By-hand check of POST-IMPACT's Mili reader against GRIZ (README.md, "POST-IMPACT on Mili
databases"): every curve of GRIZ's text dump of a DYNA3D run (Src/test/derived/NAME_th.answ of
the public repository mdg-graphics/griz) is read again from the run's Mili database
(Src/test/image/NAME/NAME.pltA and NAME.plt00) with `postimpact -e 'history ...'` and the two
compared value by value.  The griz files are not shipped with IMPACT-3D (all rights reserved):
extract them first, e.g.

    git clone https://github.com/mdg-graphics/griz && cd griz
    mkdir -p /tmp/griz/derived /tmp/griz/image/d3samp6
    cp Src/test/derived/*_th.answ /tmp/griz/derived/
    cp Src/test/image/d3samp6/d3samp6.plt* /tmp/griz/image/d3samp6/    # and plate71 ...

usage: tools/check-griz-mili.py [--griz /tmp/griz] [--postimpact build/postimpact/postimpact]
                                NAME...    (d3samp6 plate71 bending-71 bar71)

A value agrees to the printed precision when |ours - GRIZ| <= 1e-8 max(|GRIZ|, 1e-7 S), S the
largest magnitude of the curve (GRIZ prints 9 significant digits of single-precision values).
Quantities GRIZ derives (von Mises, pressure, magnitudes, displacements) are computed here in
double precision from the stored values, so they may differ from GRIZ's single-precision
arithmetic in the last digits; their largest relative difference is printed.  Exit status 0
when every raw value agrees to the printed precision, 1 otherwise.
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

RAW = {
    "Node Position[X Position]": "ux", "Node Position[Y Position]": "uy", "Node Position[Z Position]": "uz",
    "Node Velocity[X Velocity]": "vx", "Node Velocity[Y Velocity]": "vy", "Node Velocity[Z Velocity]": "vz",
    "Node Acceleration[X Acceleration]": "ax", "Node Acceleration[Y Acceleration]": "ay",
    "Node Acceleration[Z Acceleration]": "az",
    "Rot. Displ.[X Angle]": "rux", "Rot. Displ.[Y Angle]": "ruy", "Rot. Displ.[Z Angle]": "ruz",
    "Axial Force": "axf", "Shear Resultant - s": "sfs", "Shear Resultant - t": "sft",
    "Bending Moment - s": "ms", "Bending Moment - t": "mt", "Torsional Resultant": "tor",
    "Element Status": "sand",
    "S Vector[S Vector - x]": "svec_x", "S Vector[S Vector - y]": "svec_y", "S Vector[S Vector - z]": "svec_z",
    "Bending Resultant[Mxx]": "mxx", "Bending Resultant[Myy]": "myy", "Bending Resultant[Mxy]": "mxy",
    "Shear Resultant[Qxx]": "qxx", "Shear Resultant[Qyy]": "qyy",
    "Normal Resultant[Nxx]": "nxx", "Normal Resultant[Nyy]": "nyy", "Normal Resultant[Nxy]": "nxy",
    "Equiv. Plastic Strain": "eps", "Current Temperature": "t_cur", "Plastic Strain Rate": "eps_rate",
    "Yield Strength": "yield",
    "X Stress": "sx", "Y Stress": "sy", "Z Stress": "sz", "XY Stress": "sxy", "YZ Stress": "syz", "ZX Stress": "szx",
}
STRESS = ["sx", "sy", "sz", "sxy", "syz", "szx"]
CLASS = {"Node": "node", "Beams": "beam", "Shells": "shell", "Bricks": "brick"}
SURFACE = {"middle": "mid", "inner": "in", "outer": "out"}


def parse_answ(path):
    """Curves: dict(kind, id, title, mods, rows[(t, v)])."""
    curves, cur = [], None
    for line in open(path, encoding="latin-1"):
        m = re.match(r"# Curve \d+ - (\w+) (\d+)", line)
        if m:
            cur = {"kind": m.group(1), "id": int(m.group(2)), "title": None, "mods": [], "rows": []}
            curves.append(cur)
            continue
        if cur is None:
            continue
        m = re.match(r"# (\w+) - (\d+): (.*)$", line.rstrip("\n"))
        if m:
            cur["title"] = m.group(3).strip()
            continue
        if line.startswith("#"):
            cur["mods"].append(line[1:].strip())
            continue
        w = line.split()
        if len(w) == 2:
            cur["rows"].append((float(w[0]), float(w[1])))
    return [c for c in curves if c["title"] and c["rows"]]


def mod(c, key):
    for m in c["mods"]:
        if m.startswith(c["title"] + " " + key + ":") or (key == "Integration point" and "Integration point:" in m):
            return m.split(":")[-1].strip()
    return None


def element_set(c):
    """'Material M Integration point: K' -> (es_M + 'a' container guess, K)."""
    for m in c["mods"]:
        r = re.match(r"Material (\d+) Integration point: (\d+)", m)
        if r:
            return r.group(1), int(r.group(2))
    return None


def plan(c, containers):
    """What to read for a curve: (list of (class, id, var)), combine(values, ref) -> value, kind)."""
    cls = CLASS.get(c["kind"])
    if cls is None:
        return None
    title = c["title"]
    es = element_set(c)
    surface = SURFACE.get(mod(c, "reference surface") or "middle", "mid")

    def stress_var(leaf):
        if es:  # an element-set array: es_<M><letter> holding the stresses
            cont = containers.get((cls, es[0]))
            return f"{leaf}:{cont}@{es[1]}" if cont else None
        if cls == "shell" and (cls, "stress_" + surface) in containers:
            return f"{leaf}:stress_{surface}"
        return leaf

    if title in RAW:
        leaf = RAW[title]
        var = stress_var(leaf) if leaf in STRESS else leaf
        return ([(cls, c["id"], var)], lambda v, r: v[0], "raw") if var else None
    if title in ("Effective Stress", "Pressure"):
        vs = [stress_var(s) for s in STRESS]
        if None in vs:
            return None
        if title == "Pressure":
            return [(cls, c["id"], v) for v in vs[:3]], lambda v, r: -(v[0] + v[1] + v[2]) / 3, "derived"
        def vm(v, r):
            sx, sy, sz, sxy, syz, szx = v
            return math.sqrt(0.5 * ((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2) + 3 * (sxy ** 2 + syz ** 2 + szx ** 2))
        return [(cls, c["id"], v) for v in vs], vm, "derived"
    if title == "Acceleration Magnitude":
        return ([(cls, c["id"], a) for a in ("ax", "ay", "az")],
                lambda v, r: math.sqrt(sum(x * x for x in v)), "derived")
    m = re.match(r"([XYZ]) Displacement$", title)
    if m or title == "Displacement Magnitude":
        ref = int(mod(c, "reference state") or 0)
        comps = ["ux", "uy", "uz"] if not m else ["u" + m.group(1).lower()]
        def disp(v, r, comps=comps):
            d = [v[k] - r[k] for k in range(len(comps))]
            return math.sqrt(sum(x * x for x in d)) if len(d) == 3 else d[0]
        return [(cls, c["id"], x) for x in comps], disp, ("derived", ref)
    return None


def containers_of(pltA):
    """(class, material) -> the element-set container ('es_3a'), and (class, 'stress_mid') ...,
    from the variable names in the A file (the strings section is plain text)."""
    data = open(pltA, "rb").read()
    names = set(re.findall(rb"es_(\d+)([a-z])\x00", data))
    out = {}
    for mat, letter in sorted(names):
        for cls in ("beam", "shell", "brick"):
            out.setdefault((cls, mat.decode()), "es_" + mat.decode() + letter.decode())
    for s in (b"stress_mid", b"stress_in", b"stress_out"):
        if s + b"\x00" in data:
            out[("shell", s.decode())] = s.decode()
    return out


def run(postimpact, pltA, requests, tmp):
    """Values of every (class, id, var) at every state: {request: [values]}, times."""
    uniq = sorted(set(requests))
    values, times = {}, None
    for k in range(0, len(uniq), 40):
        chunk = uniq[k:k + 40]
        words = []
        for cls, ident, var in chunk:
            words += ["mili", cls, str(ident), var]
        png = os.path.join(tmp, f"h{k}.png")
        cmd = [postimpact, pltA, "--plotsize", "400x300", "-e", "history " + png + " " + " ".join(words)]
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit(f"check-griz-mili: {' '.join(cmd[:3])} ...: {r.stderr.strip()}")
        with open(png[:-4] + ".csv") as f:
            rows = list(csv.reader(f))
        times = [float(row[1]) for row in rows[1:]]
        for j, req in enumerate(chunk):
            values[req] = [float(row[2 + j]) for row in rows[1:]]
    return values, times


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--griz", default="/tmp/griz")
    ap.add_argument("--postimpact", default="build/postimpact/postimpact")
    ap.add_argument("names", nargs="+")
    a = ap.parse_args()
    bad = 0
    with tempfile.TemporaryDirectory(prefix="griz-mili-") as tmp:
        for name in a.names:
            answ = os.path.join(a.griz, "derived", name + "_th.answ")
            pltA = os.path.join(a.griz, "image", name, name + ".pltA")
            if not os.path.exists(answ) or not os.path.exists(pltA) or not os.path.exists(pltA[:-1] + "00"):
                print(f"{name}: skipped (needs {answ}, {pltA} and its state file)")
                continue
            curves = parse_answ(answ)
            conts = containers_of(pltA)
            plans, skipped = [], {}
            for c in curves:
                p = plan(c, conts)
                if p is None:
                    skipped[c["title"]] = skipped.get(c["title"], 0) + 1
                else:
                    plans.append((c, p))
            values, times = run(a.postimpact, pltA, [r for _, p in plans for r in p[0]], tmp)
            stats = {}
            for c, (reqs, combine, kind) in plans:
                ref = kind[1] if isinstance(kind, tuple) else None
                kind = kind[0] if isinstance(kind, tuple) else kind
                if ref is not None and ref == 0:
                    # displacement from the initial geometry: the positions of the first state
                    # (t = 0, DYNA3D writes the initial coordinates there)
                    r0 = [values[q][0] for q in reqs]
                elif ref is not None:
                    r0 = [values[q][ref - 1] for q in reqs]
                else:
                    r0 = None
                scale = max(abs(v) for _, v in c["rows"]) or 1.0
                key = (c["title"] + (" (" + mod(c, "reference surface") + ")" if mod(c, "reference surface") not in (None, "middle") else ""), kind)
                st = stats.setdefault(key, {"curves": 0, "values": 0, "within": 0, "max": 0.0})
                st["curves"] += 1
                for t, g in c["rows"]:
                    i = min(range(len(times)), key=lambda j: abs(times[j] - t))
                    ours = combine([values[q][i] for q in reqs], r0)
                    d = abs(ours - g) / max(abs(g), 1e-7 * scale)
                    st["values"] += 1
                    st["max"] = max(st["max"], d)
                    st["within"] += d <= 1e-8
            print(f"{name}: {len(curves)} curves in {os.path.basename(answ)}, {len(plans)} checked")
            for (title, kind), st in sorted(stats.items()):
                flag = "" if kind != "raw" or st["within"] == st["values"] else "   <-- outside the printed precision"
                if flag:
                    bad += 1
                print(f"  {title:42s} {kind:7s} {st['curves']:4d} curves {st['values']:6d} values  "
                      f"max rel diff {st['max']:.2e}  within 1e-8: {st['within']}/{st['values']}{flag}")
            for title, n in sorted(skipped.items()):
                print(f"  {title:42s} not checked ({n} curves: a quantity this check does not derive)")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
