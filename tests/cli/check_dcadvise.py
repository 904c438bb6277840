#!/usr/bin/env python3
"""Checks tools/dcadvise.py (dclaw's path in argv[1]); needs no LIGGGHTS run.

Every example deck reads and gets a row per effect; the scene values the
advisor takes from a deck (radius through an equal-style variable, impact
speed from the fall height, -var on its command line) are the deck's; its
measures are dclaw scene's for those values; bad decks exit 2 with a
message naming the line or the property, never a traceback; what the
advisor assumed is listed."""
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cli_checks import check, finish  # noqa: E402

DCLAW = sys.argv[1]
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TOOL = os.path.join(ROOT, "tools", "dcadvise.py")
EFFECTS = ["time step", "Hertz range", "shape", "plasticity", "adhesion", "roughness", "tangential memory", "rolling"]


def advise(args):
    p = subprocess.run([sys.executable, TOOL] + args, capture_output=True, text=True, timeout=300,
                       env=dict(os.environ, DCLAW=DCLAW))
    return p.returncode, p.stdout, p.stderr


for ex in sorted(os.listdir(os.path.join(ROOT, "examples"))):
    d = os.path.join(ROOT, "examples", ex)
    decks = [f for f in os.listdir(d) if f.startswith("in.")] if os.path.isdir(d) else []
    for deck in decks:
        rc, out, err = advise([os.path.join(d, deck)])
        if "pair_style granular" in open(os.path.join(d, deck)).read():
            # a LAMMPS deck: refused with a message that says so
            check(rc != 0 and "a LAMMPS deck (pair_style granular)" in err and "Traceback" not in err,
                  "examples/%s/%s: a LAMMPS deck, refused (exit %d: %s)" % (ex, deck, rc, err.strip()[-200:]))
            continue
        check(rc == 0 and all("\n  %s " % e in out for e in EFFECTS) and "Traceback" not in err,
              "examples/%s/%s: exit %d, every effect (%s)" % (ex, deck, rc, err.strip()[-200:]))

# the deck's own models against the contacts' needs
rc, out, err = advise([os.path.join(ROOT, "examples", "superquadric_settling", "in.superquadric_settling")])
check(rc == 0 and "tangential memory: the contacts need cmd_tangential; the deck has history" in out,
      "superquadric_settling: the deck's tangential history named against the need")
rc, out, err = advise([os.path.join(ROOT, "inputs", "advisor", "in.scene_drop"), "-var", "H", "1e9"])
check(rc == 0 and "jamari_ep" not in out.split("the deck's models")[1],
      "scene_drop below yield: no plasticity verdict")

# the threshold scene: values from the deck, -var, and dclaw scene's numbers
drop = os.path.join(ROOT, "inputs", "advisor", "in.scene_drop")
tmp = tempfile.mkdtemp()
rc, out, err = advise([drop, "-var", "H", "1e7", "--csv", os.path.join(tmp, "m.csv")])
rows = list(csv.DictReader(open(os.path.join(tmp, "m.csv")))) if rc == 0 else []
wall = next((r for r in rows if r["kind"] == "type 1 on a wall"), {})
v = math.sqrt(2 * 9.81 * 0.02)   # fall from the top of region fill (0.02 m) to the box bottom (0)
check(rc == 0 and abs(float(wall.get("in_v", 0)) / v - 1) < 1e-12 and "jamari_ep" in out,
      "scene_drop -var H 1e7: impact speed %s (want %r), jamari_ep advised (%s)" % (wall.get("in_v"), v, err.strip()))
p = subprocess.run([DCLAW, "scene", "--R1", "0.001", "--R2", "0", "--E1", "5e8", "--E2", "5e8", "--nu1", "0.25", "--nu2",
                    "0.25", "--rho1", "2500", "--rho2", "2500", "--v", repr(v), "--g", "9.81", "--dt", "1e-6", "--mu", "0.4",
                    "--H", "1e7"], capture_output=True, text=True)
direct = dict(zip(*[l.split(",") for l in p.stdout.strip().splitlines()]))
for k in ("delta_max", "e_plastic", "T_rayleigh", "delta_rest", "beta_cmd", "beta_history"):
    check(k in direct and abs(float(wall.get(k, "nan")) / float(direct[k]) - 1) < 1e-9,
          "scene_drop: %s %s as dclaw scene gives %s" % (k, wall.get(k), direct.get(k)))
rc, out, err = advise([drop])
check(rc == 0 and "not assessed" in out and "jamari_ep" not in out, "scene_drop without -var: plasticity not assessed")
# rough and oblique: the tangential deck line takes the summits' stiffness; smooth: it does not
rc, out, err = advise([drop, "-var", "sigma", "2e-5"])
check(rc == 0 and re.search(r"tangential cmd_tangential (cmdMemory turningPoints )?tangentialRoughness on", out),
      "rough scene needing memory: the deck line adds tangentialRoughness on")
rc, out, err = advise([drop])
check(rc == 0 and "tangentialRoughness" not in out, "smooth scene: no tangentialRoughness")
# adhesion across the Tabor range: z0 0.4 nm (Tabor 65): JKR; 10 nm (Tabor 2.6): Maugis-Dugdale with its property
rc, out, err = advise([drop, "-var", "w", "0.05"])
check(rc == 0 and "Tabor 65" in out and "adhesionLaw" not in out, "Tabor 65: jkr_elliptic, JKR")
rc, out, err = advise([drop, "-var", "w", "0.05", "--z0", "1e-8"])
check(rc == 0 and "Tabor 2.6" in out and "model jkr_elliptic adhesionLaw maugis" in out and
      "equilibriumSeparation peratomtypepair ... (z0 1e-08 m)" in out, "Tabor 2.6: adhesionLaw maugis and z0")


def deck(text):
    path = os.path.join(tmp, "in.test")
    open(path, "w").write(text)
    return path


BASE = """atom_style sphere
units si
region box block 0 0.01 0 0.01 0 0.02 units box
create_box 1 box
variable d equal 0.002
variable r equal 0.5*v_d
fix m1 all property/global youngsModulus peratomtype 5e6
fix m2 all property/global poissonsRatio peratomtype 0.3
fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
pair_style gran model hertz tangential history
fix pts all particletemplate/sphere 1 atom_type 1 density constant 2500 radius constant ${r}
region fill block 0 0.01 0 0.01 0.01 0.02 units box
fix ins all insert/pack seed 3 distributiontemplate pdd insert_every once region fill vel constant 0 0 -0.5
fix grav all gravity 9.81 vector 0 0 -1
timestep 1e-5
"""
rc, out, err = advise([deck(BASE)])
check(rc == 0 and "radius 0.001 m" in out, "radius from an equal-style variable: %s" % (out.splitlines()[4:6] if rc == 0 else err))
v = math.sqrt(0.25 + 2 * 9.81 * 0.02)
check(rc == 0 and ("largest impact speed %.3g m/s" % v) in out, "impact speed from insertion speed and fall: %.3g" % v)
BAD = [
    (BASE.replace("peratomtype 5e6", "peratomtype ${Emod}"), ["in.test:7", "Emod"]),
    (BASE.replace("fix m1 all property/global youngsModulus peratomtype 5e6\n", ""), ["youngsModulus"]),
    (BASE.replace("fix pts all particletemplate/sphere", "#"), ["no particles"]),
    (BASE.replace("variable r equal 0.5*v_d", "variable r equal 0.5*v_dd"), ["in.test:6", "dd"]),
    (BASE.replace("timestep 1e-5", ""), ["timestep"]),
    (BASE.replace("radius constant ${r}", "radius weibull 1 2"), ["in.test:11", "radius"]),
    (BASE.replace("timestep 1e-5", "timestep 1e-5x"), ["in.test:15", "timestep"]),
    (BASE.replace("density constant 2500", "density constant"), ["in.test:11"]),
]
for text, words in BAD:
    rc, out, err = advise([deck(text)])
    check(rc == 2 and all(w in err for w in words) and "Traceback" not in err,
          "bad deck names %s: exit %d, %s" % (words, rc, err.strip()))
for args, words in [([os.path.join(tmp, "none")], ["cannot read"]), ([drop, "--tol", "x"], ["--tol"]),
                    ([drop, "--bogus"], ["--bogus"]), ([drop, "-var", "H"], ["-var"])]:
    rc, out, err = advise(args)
    check(rc == 2 and all(w in err for w in words) and "Traceback" not in err, "%s: exit %d, %s" % (args[1:], rc, err.strip()))
rc, out, err = advise([deck(BASE.replace("radius constant ${r}", "radius gaussian number 0.001 0.0001"))])
check(rc == 0 and "assumed:" in out and "gaussian" in out, "a gaussian radius is listed under assumed")
finish()
