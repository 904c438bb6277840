#!/usr/bin/env python3
"""Writes the model whitelist (the contact-model combinations compiled for
speed) from the decks: every `pair_style gran` and `fix ... wall/gran` line
of inputs/, examples/ and tests/bench/, with a ${variable} after a model
keyword (model, tangential, ...) taken as each model of that kind the deck,
its check script (tests/regression/check_<case>.py) or the benchmark script
names, and after cohesion or rolling_friction also off (decks switch those
sub-models on and off by a variable); and, as LIGGGHTS' own build does,
the lines of LIGGGHTS' example decks (examples/LIGGGHTS beside its src/,
skipping lines with a model from a variable or from a package this build
lacks) and of the user's decks (DECK arguments, from DC_DECKS at set-up).
Run by plugin/liggghts/CMakeLists.txt at configure time.
A project or user deck line naming an unknown model is an error (exit 2).
Usage: gen_whitelist.py PROJECT_ROOT LIGGGHTS_SRC OUTPUT [DECK ...]"""
import glob
import os
import re
import sys

ROOT, LIGG_SRC, OUTPUT = sys.argv[1:4]
USER_DECKS = sys.argv[4:]
KINDS = {"model": "NORMAL", "tangential": "TANGENTIAL", "cohesion": "COHESION", "rolling_friction": "ROLLING",
         "surface": "SURFACE"}
# keyword -> enum name of every model LIGGGHTS and the plugin define
enums = {}
for path in glob.glob(os.path.join(LIGG_SRC, "*_model_*.h")) + \
        glob.glob(os.path.join(ROOT, "plugin", "liggghts", "models", "*_model_*.h")):
    for kind, enum, name in re.findall(r"^(\w+)_MODEL\((\w+),\s*([\w/]+),", open(path).read(), re.M):
        enums[(kind, name)] = enum
if ("NORMAL", "hertz_elliptic") not in enums or ("TANGENTIAL", "history") not in enums:
    sys.exit("gen_whitelist: no model headers found in %s and plugin/liggghts/models" % LIGG_SRC)


def combination(words, where, strict=True):
    """The GRAN_MODEL arguments of a pair_style gran / wall/gran argument
    list; None for an unknown model where not strict."""
    got = {"NORMAL": "NORMAL_OFF", "TANGENTIAL": "TANGENTIAL_OFF", "COHESION": "COHESION_OFF",
           "ROLLING": "ROLLING_OFF", "SURFACE": "SURFACE_DEFAULT"}
    for k, word in enumerate(words[:-1]):
        if word in KINDS:
            kind = KINDS[word]
            if words[k + 1] == "off" and kind != "SURFACE":
                got[kind] = kind + "_OFF"
                continue
            if (kind, words[k + 1]) not in enums:
                if not strict:
                    return None
                sys.stderr.write("gen_whitelist: %s: unknown %s model '%s'\n" % (where, word, words[k + 1]))
                sys.exit(2)
            got[kind] = enums[(kind, words[k + 1])]
    return tuple(got[k] for k in ("NORMAL", "TANGENTIAL", "COHESION", "ROLLING", "SURFACE"))


bench = open(os.path.join(ROOT, "tests", "bench", "bench_scenes.sh")).read()
used = []
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
    named = lambda kind: sorted(m for (k, m) in enums if k == kind and re.search(r"\b%s\b" % re.escape(m), around))
    for line in text.split("\n"):
        line = line.split("#")[0]
        words = line.split()
        if not (line.startswith("pair_style") and "gran" in words[:2] or "wall/gran" in words):
            continue
        # a ${variable} after a model keyword: every model of that kind the deck or its scripts name
        variants = [[]]
        for k, w in enumerate(words):
            choices = [w]
            if w.startswith("${") and k > 0 and words[k - 1] in KINDS:
                choices = named(KINDS[words[k - 1]])
                if words[k - 1] in ("cohesion", "rolling_friction"):
                    choices.append("off")
            variants = [v + [c] for v in variants for c in choices]
        for v in variants:
            combo = combination(v, os.path.relpath(deck, ROOT))
            if combo not in used:
                used.append(combo)


def model_lines(text):
    """The argument lists of a deck's pair_style gran and wall/gran lines."""
    for line in text.replace("&\n", " ").split("\n"):
        words = line.split("#")[0].replace('"', " ").split()
        if words and (words[0] == "pair_style" and "gran" in words[:2] or "wall/gran" in words) and "model" in words:
            yield words


# LIGGGHTS' examples and the user's decks: the models they write out
others = [(p, False) for p in sorted(glob.glob(os.path.join(LIGG_SRC, "..", "examples", "LIGGGHTS", "**", "in.*"),
                                           recursive=True))]
others += [(p, True) for p in USER_DECKS]
for deck, user in others:
    for words in model_lines(open(deck, errors="replace").read()):
        if any(w.startswith("$") for w in words):
            if user:
                sys.stderr.write("gen_whitelist: %s: a model from a variable is not compiled (%s): write the "
                                 "models out on the line\n" % (deck, " ".join(words)))
            continue
        combo = combination(words, deck, strict=user)
        if combo and combo not in used:
            used.append(combo)
text = "".join("GRAN_MODEL(%s)\n" % ", ".join(c) for c in sorted(used))
if not os.path.exists(OUTPUT) or open(OUTPUT).read() != text:
    with open(OUTPUT, "w") as f:
        f.write(text)
