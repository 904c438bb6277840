#!/usr/bin/env python3
"""The model whitelist (plugin/style_contact_model.whitelist) against the
decks: every `pair_style gran` and `fix ... wall/gran` line of inputs/,
examples/ and tests/bench/ must name a compiled combination, with ${model}
taken as each model the deck, its check script or the benchmark script
names (a deck run by a check also fails if LIGGGHTS warns that its
combination is missing: regress.run). And every whitelist line is used by
some deck, so that the list stays small.
Usage: check_whitelist.py WORKDIR"""
import glob
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import Checks, ROOT

c = Checks("whitelist")
KINDS = {"model": "NORMAL", "tangential": "TANGENTIAL", "cohesion": "COHESION", "rolling_friction": "ROLLING",
         "surface": "SURFACE"}
# keyword -> enum name of every model LIGGGHTS and the plugin define
enums = {}
for path in glob.glob(os.path.join(ROOT, ".deps", "liggghts-3.8.0", "src", "*_model_*.h")) + \
        glob.glob(os.path.join(ROOT, "plugin", "models", "*_model_*.h")):
    for kind, enum, name in re.findall(r"^(\w+)_MODEL\((\w+),\s*([\w/]+),", open(path).read(), re.M):
        enums[(kind, name)] = enum
c.true(("NORMAL", "hertz_elliptic") in enums and ("TANGENTIAL", "history") in enums,
       "model keywords read from LIGGGHTS' and the plugin's model headers (%d)" % len(enums))

white = set()
for line in open(os.path.join(ROOT, "plugin", "style_contact_model.whitelist")):
    m = re.match(r"GRAN_MODEL\((.*)\)", line.strip())
    if m:
        white.add(tuple(x.strip() for x in m.group(1).split(",")))


def combination(words):
    """The GRAN_MODEL tuple of a pair_style gran / wall/gran argument list."""
    got = {"NORMAL": "NORMAL_OFF", "TANGENTIAL": "TANGENTIAL_OFF", "COHESION": "COHESION_OFF",
           "ROLLING": "ROLLING_OFF", "SURFACE": "SURFACE_DEFAULT"}
    for k, word in enumerate(words[:-1]):
        if word in KINDS:
            kind = KINDS[word]
            got[kind] = enums.get((kind, words[k + 1]), "unknown %s model '%s'" % (word, words[k + 1]))
    return tuple(got[k] for k in ("NORMAL", "TANGENTIAL", "COHESION", "ROLLING", "SURFACE"))


bench = open(os.path.join(ROOT, "tests", "bench", "bench_scenes.sh")).read()
used, lines = set(), 0
decks = glob.glob(os.path.join(ROOT, "inputs", "*", "in.*")) + glob.glob(os.path.join(ROOT, "examples", "*", "in.*")) + \
    glob.glob(os.path.join(ROOT, "tests", "bench", "in.*"))
for deck in sorted(decks):
    if "deck_errors" in deck:   # decks that must fail; their model words come from the check
        continue
    text = open(deck).read()
    for inc in re.findall(r"^include\s+\$\{dir\}/(\S+)", text, re.M):
        text += open(os.path.join(os.path.dirname(deck), inc)).read()
    case = os.path.basename(os.path.dirname(deck))
    script = os.path.join(ROOT, "tests", "regression", "check_%s.py" % case)
    around = text + (open(script).read() if os.path.exists(script) else "") + (bench if "bench" in deck else "")
    models = {m for (kind, m) in enums if kind == "NORMAL" and re.search(r"\b%s\b" % re.escape(m), around)}
    for line in text.split("\n"):
        line = line.split("#")[0]
        words = line.split()
        if not (line.startswith("pair_style") and "gran" in words[:2] or "wall/gran" in words):
            continue
        for m in sorted(models) if "${model}" in line else [None]:
            combo = combination([m if w == "${model}" else w for w in words])
            lines += 1
            used.add(combo)
            c.true(combo in white, "%s: %s" % (os.path.relpath(deck, ROOT), ", ".join(combo)))
c.true(lines > 20, "%d deck lines checked" % lines)
for combo in sorted(white - used):
    c.true(False, "whitelist line used by no deck: GRAN_MODEL(%s)" % ", ".join(combo))
c.finish()
