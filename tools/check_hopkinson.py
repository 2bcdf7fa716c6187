#!/usr/bin/env python3
"""The split-Hopkinson bar of constantinoval/pythonScripts (verification/, task ak4-diam-V1)
against LS-DYNA's pulses shipped beside it.  Not part of CI: the deck and the pulses are that
repository's (no licence), never ours; see docs/validation.md "Split-Hopkinson bar".

  check_hopkinson.py DIR OUT [--soft N] [--end T] [--ncpu N] [--no-run]

DIR: the repository's verification/ folder (verification_tasks.zip, verificationTasks.py,
ak4-rez.zip) or a folder holding the instantiated deck diam1.k and ak4-diam-V1-rez.json.
The task is instantiated as verificationTasks.py does (diam1.k formatted with the striker's
velocity 15.5, the 'ak4' material and *INITIAL_TEMPERATURE_SET 20 inserted before *END), run
by build/impact3d in OUT, and the elout stresses sig-yy of elements 23500 (incident bar) and
46500 (transmitted bar), divided by the bars' E = 185000 MPa, compared with LS-DYNA's elout
strains of the same elements (the JSON's 'pulses': time, 23500, 46500; elastic bars: the
axial strain of the 1D wave is sig-yy / E): the incident plateau (the middle 60 % of the time
the reference is below half its least value, t < 0.25 ms) within 3 %, the reflected pulse (23500, 0.25 <= t <= 0.5 ms,
above half its peak) and the transmitted pulse (46500, t <= 0.5 ms, below half its least value)
within 10 %: the mean over the reference's window, ours over the same times.
--soft N: run a copy with optional card A SOFT = N (SOFT 2 is the deck's); --end T: end time
(ms, default the deck's 0.9); --substitute: the sample's *MAT_MODIFIED_JOHNSON_COOK (FLAG1 = 1,
Zerilli-Armstrong) replaced by a stand-in *MAT_PLASTIC_KINEMATIC (yield 479 MPa, tangent
modulus 1500 MPa: not the AK-4-1 law, only to run the rest of the deck); --no-run: compare the
elout already in OUT.
Exit 0 when every pulse is within its tolerance, 1 when one is not, 2 when the deck did not run.
"""
import json
import os
import re
import subprocess
import sys
import zipfile

E_BAR = 185000.0
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def instantiate(src, out):
    """diam1.k of the task ak4-diam-V1 in out/diam1.k; the reference pulses (dict)."""
    deck = os.path.join(src, "diam1.k")
    ref = os.path.join(src, "ak4-diam-V1-rez.json")
    if os.path.exists(os.path.join(src, "verification_tasks.zip")):
        with zipfile.ZipFile(os.path.join(src, "verification_tasks.zip")) as z:
            text = z.read("diam1.k").decode()
    else:
        text = open(deck).read()
    if os.path.exists(os.path.join(src, "ak4-rez.zip")):
        with zipfile.ZipFile(os.path.join(src, "ak4-rez.zip")) as z:
            pulses = json.loads(z.read("ak4-diam-V1-rez.json").decode())
    else:
        pulses = json.load(open(ref))
    if "{0:" in text:  # not instantiated yet: as verificationTasks.py createTask('ak4', 'diam1', 15.5, 20)
        py = open(os.path.join(src, "verificationTasks.py")).read()
        ns = {}
        exec(py[py.index("materials = {"):py.index("tasks = {")], ns)  # the two tables only
        text = text.format(15.5)
        text = text.replace("*END", ns["materials"]["ak4"] + ns["initial_temperature_card"].format(20.0) + "*END")
    return text, pulses


def set_field(text, keyword, card_after, col, value):
    """text with field col (0-based, 10 columns) of the card_after-th data card after keyword."""
    lines = text.split("\n")
    k = next(i for i, l in enumerate(lines) if l.strip().upper().startswith(keyword))
    n = -1
    for i in range(k + 1, len(lines)):
        if lines[i].startswith("$"):
            continue
        n += 1
        if n == card_after:
            l = lines[i].ljust(80)
            lines[i] = (l[:10 * col] + ("%10s" % value) + l[10 * col + 10:]).rstrip()
            break
    return "\n".join(lines)


SUBSTITUTE = """*MAT_PLASTIC_KINEMATIC_TITLE
stand-in for AK-4-1 (not its law)
        11    0.0028   72000.0      0.33     479.0    1500.0       0.0
       0.0       0.0       0.0       0.0
"""


def substitute_material(text):
    i = text.index("*MAT_MODIFIED_JOHNSON_COOK")
    j = text.index("*PART", i)
    return text[:i] + SUBSTITUTE + text[j:]


def read_elout(path):
    """{element: [(time, sig-yy)]} of an IMPACT-3D elout."""
    out = {}
    t = None
    for line in open(path):
        m = re.search(r"\( at time\s+(\S+)\s*\)", line)
        if m:
            t = float(m.group(1))
            continue
        f = line.split()
        if t is not None and len(f) >= 4 and f[0].isdigit() and f[1].isdigit():
            out.setdefault(int(f[0]), []).append((t, float(f[3])))
    return out


def interp(series, t):
    for (t0, v0), (t1, v1) in zip(series, series[1:]):
        if t0 <= t <= t1:
            return v0 + (v1 - v0) * (t - t0) / (t1 - t0) if t1 > t0 else v0
    return None


def compare(name, ref_t, ref_v, ours, pick, tol):
    window = [(t, v) for t, v in zip(ref_t, ref_v) if pick(t, v)]
    if not window:
        print(f"  {name}: no reference window")
        return False
    ours_v = [interp(ours, t) for t, _ in window]
    if any(v is None for v in ours_v):
        print(f"  {name}: the run does not reach {window[-1][0]:.4g} ms")
        return False
    r = sum(v for _, v in window) / len(window)
    o = sum(v / E_BAR for v in ours_v) / len(window)
    dev = o / r - 1
    ok = abs(dev) <= tol
    print(f"  {name}: {window[0][0]:.3f}-{window[-1][0]:.3f} ms, LS-DYNA {r:.4e}, IMPACT-3D {o:.4e} "
          f"({dev * 100:+.1f} %, tolerance {tol * 100:.0f} %): {'ok' if ok else 'OUT'}")
    return ok


def main():
    args = sys.argv[1:]
    opts = {}
    for key in ("--soft", "--end", "--ncpu"):
        if key in args:
            i = args.index(key)
            opts[key] = args[i + 1]
            del args[i:i + 2]
    no_run = "--no-run" in args
    substitute = "--substitute" in args
    args = [a for a in args if a not in ("--no-run", "--substitute")]
    if len(args) != 2:
        print(__doc__, file=sys.stderr)
        return 3
    src, out = args
    os.makedirs(out, exist_ok=True)
    text, pulses = instantiate(src, out)
    if "--soft" in opts:
        text = set_field(text, "*CONTACT_AUTOMATIC_SINGLE_SURFACE", 3, 0, opts["--soft"])
    if substitute:
        text = substitute_material(text)
    if "--end" in opts:
        text = set_field(text, "*CONTROL_TERMINATION", 0, 0, opts["--end"])
    deck = os.path.join(out, "diam1.k")
    open(deck, "w").write(text)
    if not no_run:
        cmd = [os.path.join(ROOT, "build", "impact3d"), "i=diam1.k", "ncpu=" + opts.get("--ncpu", "2")]
        print("running", " ".join(cmd), "in", out, flush=True)
        rc = subprocess.call(cmd, cwd=out, stdout=open(os.path.join(out, "run.log"), "w"), stderr=subprocess.STDOUT)
        tail = open(os.path.join(out, "run.log")).read().strip().split("\n")[-3:]
        print("  impact3d exit code", rc, "|", " / ".join(l.strip() for l in tail))
        if rc != 0:
            return 2
    if not os.path.exists(os.path.join(out, "elout")):
        print("no elout in", out)
        return 2
    el = read_elout(os.path.join(out, "elout"))
    t, inc, tra = pulses["pulses"]
    least_inc = min(v for tt, v in zip(t, inc) if tt < 0.25)
    peak_ref = max(v for tt, v in zip(t, inc) if 0.25 <= tt <= 0.5)
    least_tra = min(v for tt, v in zip(t, tra) if tt <= 0.5)
    print("split-Hopkinson bar ak4-diam-V1: elout sig-yy / E against LS-DYNA's strains")
    pulse = [tt for tt, v in zip(t, inc) if tt < 0.25 and v <= 0.5 * least_inc]
    a, b = pulse[0] + 0.2 * (pulse[-1] - pulse[0]), pulse[-1] - 0.2 * (pulse[-1] - pulse[0])
    ok = compare("incident plateau (23500)", t, inc, el.get(23500, []), lambda tt, v: a <= tt <= b, 0.03)
    ok &= compare("reflected (23500)", t, inc, el.get(23500, []), lambda tt, v: 0.25 <= tt <= 0.5 and v >= 0.5 * peak_ref, 0.10)
    ok &= compare("transmitted (46500)", t, tra, el.get(46500, []), lambda tt, v: tt <= 0.5 and v <= 0.5 * least_tra, 0.10)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
