#!/usr/bin/env python3
"""Seed corpora of the fuzz targets (docs/fuzzing.md, "Fuzzing and sanitizers"), from the shipped
decks, the malformed-deck corpus, the regression references and fuzz/seeds/.

usage: make_corpus.py SOURCE_DIR OUT_DIR IMPACT3D_BINARY

OUT_DIR/<target>/ gets one file per seed.  Restart dumps are made by running IMPACT3D_BINARY
on small decks with a dump interval (no dump format is stored, so the seeds follow it)."""
import glob
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile

SRC, OUT, IMPACT3D = sys.argv[1], sys.argv[2], sys.argv[3]
SEP = b"$$FUZZ-FILE$$\n"
MAX_DECK = 100_000  # bytes: bigger decks only slow the fuzzer down
MAX_MEMBER = 24_000  # bytes of a plot member kept (a partial last state is ignored)


def out(target, name, data):
    d = os.path.join(OUT, target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data)


def read(path):
    with open(path, "rb") as f:
        return f.read()


def src(*parts):
    return os.path.join(SRC, *parts)


shutil.rmtree(OUT, ignore_errors=True)
for target in ("fixed_deck", "keyword_deck", "plot_database", "postimpact_database",
               "restart_dump", "command_file", "tolerances", "mili_database"):
    os.makedirs(os.path.join(OUT, target), exist_ok=True)
    for seed in glob.glob(src("fuzz", "seeds", target, "*")):
        out(target, "seed_" + os.path.basename(seed), read(seed))

# ---- fixed-format decks
fixed = sorted(glob.glob(src("decks", "*.dyn")) + glob.glob(src("tests", "regression", "decks", "*.dyn")) +
               glob.glob(src("tests", "input", "malformed", "*.dyn")) + glob.glob(src("tests", "cli", "*.dyn")))
for p in fixed:
    data = read(p)
    if len(data) <= MAX_DECK:
        out("fixed_deck", os.path.relpath(p, SRC).replace("/", "_"), data)

# ---- keyword decks: the shipped twins that are small enough, and small decks converted by
# impact3d --write-keyword, whole and cut into a main deck and include files.
tmp = tempfile.mkdtemp(prefix="impact3d-corpus-")
keyword = [p for p in glob.glob(src("decks", "keyword", "*.k")) if os.path.getsize(p) <= MAX_DECK]
for p in glob.glob(src("tests", "regression", "decks", "*.dyn")) + [src("decks", "one_hex.dyn")]:
    k = os.path.join(tmp, os.path.basename(p)[:-4] + ".k")
    r = subprocess.run([IMPACT3D, "i=" + p, "--write-keyword=" + k], capture_output=True, cwd=tmp)
    if r.returncode == 0 and os.path.exists(k):
        keyword.append(k)
for p in sorted(set(keyword)):
    data = read(p)
    name = os.path.basename(p)
    out("keyword_deck", name, data)
    # the *NODE and *ELEMENT_SOLID blocks into inc1.k (which includes inc2.k for the solids)
    blocks = re.split(rb"(?m)^(?=\*)", data)
    main, inc1, inc2 = [], [], []
    for b in blocks:
        if b.upper().startswith(b"*NODE"):
            inc1.append(b)
        elif b.upper().startswith(b"*ELEMENT"):
            inc2.append(b)
        else:
            main.append(b)
    if inc1 and inc2:
        main_text = b"".join(main)
        at = main_text.upper().find(b"*END")
        at = len(main_text) if at < 0 else at
        main_text = main_text[:at] + b"*INCLUDE\ninc1.k\n" + main_text[at:]
        inc1_text = b"*KEYWORD\n" + b"".join(inc1) + b"*INCLUDE\ninc2.k\n*END\n"
        inc2_text = b"*KEYWORD\n" + b"".join(inc2) + b"*END\n"
        out("keyword_deck", "include_" + name, main_text + SEP + inc1_text + SEP + inc2_text)
# include errors: missing file, self include, a name over two lines
out("keyword_deck", "include_missing.k", b"*KEYWORD\n*INCLUDE\ninc3.k\nnot_there.k\n*END\n")
out("keyword_deck", "include_loop.k", b"*KEYWORD\n*INCLUDE\ninc1.k\n*END\n" + SEP +
    b"*KEYWORD\n*INCLUDE\ninc1.k\nmain.k\n*END\n")
out("keyword_deck", "include_long_name.k", b"*KEYWORD\n*INCLUDE\ninc +\n1.k\n*END\n" + SEP +
    b"*KEYWORD\n*TITLE\nincluded\n*END\n")

# ---- plot databases: 4-byte root length, root, first bytes of d3plot01
for d in sorted(glob.glob(src("tests", "regression", "reference", "*"))):
    root = read(os.path.join(d, "d3plot"))
    member = read(os.path.join(d, "d3plot01"))[:MAX_MEMBER]
    seed = struct.pack("<I", len(root)) + root + member
    name = os.path.basename(d)
    out("plot_database", name, seed)
    out("postimpact_database", name, seed)
    if name == "one_hex":
        out("plot_database", name + "_root_only", struct.pack("<I", len(root)) + root)

# ---- restart dumps: impact3d runs of small decks with a dump every 20 cycles
for deck in (src("decks", "one_hex.dyn"), src("tests", "regression", "decks", "column_uniaxial_strain.dyn")):
    lines = read(deck).decode("latin-1").split("\n")
    for i, line in enumerate(lines):
        if "CONTROL CARD #6" in line:
            card = lines[i + 1].ljust(40)
            lines[i + 1] = card[:30] + "%5d" % 20 + card[35:]
            break
    run = os.path.join(tmp, "dump_" + os.path.basename(deck)[:-4])
    os.makedirs(run)
    d = os.path.join(run, "deck.dyn")
    with open(d, "w", encoding="latin-1") as f:
        f.write("\n".join(lines))
    subprocess.run([IMPACT3D, "i=deck.dyn", "o=d3hsp", "g=d3plot", "d=d3dump", "ncpu=1"],
                   cwd=run, capture_output=True)
    dump = os.path.join(run, "d3dump01")
    if os.path.exists(dump):
        out("restart_dump", os.path.basename(run), read(dump))
    else:
        sys.exit("make_corpus.py: no dump written by " + IMPACT3D + " in " + run)

# ---- POST-IMPACT command files: the README pictures' files
for p in glob.glob(src("tools", "pictures", "*.cmd")):
    out("command_file", os.path.basename(p), read(p))

# ---- tolerance files, with two summaries to compare
tol = read(src("tests", "regression", "tolerances.txt"))
out("tolerances", "tolerances.txt", tol)
summaries = sorted(glob.glob(src("tests", "regression", "summaries", "*.txt")))
for p in summaries:
    s = read(p)
    out("tolerances", "summary_" + os.path.basename(p), tol + SEP + s + SEP + s)
if len(summaries) >= 2:
    out("tolerances", "summaries_differ", tol + SEP + read(summaries[0]) + SEP + read(summaries[1]))

shutil.rmtree(tmp, ignore_errors=True)
for target in sorted(os.listdir(OUT)):
    files = os.listdir(os.path.join(OUT, target))
    size = sum(os.path.getsize(os.path.join(OUT, target, f)) for f in files)
    print("corpus %-20s %3d seeds, %7d bytes" % (target, len(files), size))
