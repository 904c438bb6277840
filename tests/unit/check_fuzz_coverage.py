#!/usr/bin/env python3
"""Every public c_core function is in the fuzz: each function the library
exports (nm: its global text symbols dc_*) and each inline function of the
headers (static inline dc_*) must be called in tests/unit/test_fuzz.c.
Internal helpers, named with a trailing underscore, are exempt, as are the
inline building blocks of the tabulated laws' hot paths listed in INTERNAL
(each checked bit for bit, through the function it serves, by that
function's fuzz and unit test).
Usage: check_fuzz_coverage.py LIBRARY"""
import glob
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
# inline pieces of a fuzzed function's hot path (the function -> its pieces)
INTERNAL = {
    "dc_gwa_table_step_settled": ["dc_gwa_cubic", "dc_gwa_exp"],
    "dc_gwa_table_radius_init_elliptic": ["dc_gwae_eta_node_u", "dc_gwae_L_node", "dc_gwae_x_of_xi", "dc_gwae_xi",
                                          "dc_gwae_z", "dc_gwae_z_scale"],
    "dc_jkr_psi": ["dc_jkr_psi_near", "dc_jkr_psi_series"],
    "dc_hertz_geometry": ["dc_poly14"],
    "dc_cmd_step": ["dc_nf"],
}
lib = sys.argv[1]
nm = subprocess.run(["nm", "-g", "--defined-only", lib], stdout=subprocess.PIPE, text=True, check=True).stdout
exported = {w[2] for w in (l.split() for l in nm.splitlines()) if len(w) == 3 and w[1] == "T" and w[2].startswith("dc_")}
inline = set()
for h in glob.glob(os.path.join(ROOT, "c_core", "include", "dc", "*.h")):
    inline |= set(re.findall(r"^static inline [\w\s\*]*?\b(dc_\w+)\s*\(", open(h).read(), re.M))
fuzz = open(os.path.join(HERE, "test_fuzz.c")).read()
code = re.sub(r'"(?:[^"\\\n]|\\.)*"', '""', fuzz)   # string literals (the report's names) out
called = set(re.findall(r"\b(dc_\w+)\b", code))   # called, or passed to a fuzz helper
exempt = {x for v in INTERNAL.values() for x in v}
public = sorted(f for f in exported | inline if not f.endswith("_"))
missing = [f for f in public if f not in called and f not in exempt]
served = [f for f in INTERNAL if f not in called]
print("fuzz coverage: %d public functions (%d exported, %d inline), %d in the fuzz, %d inline pieces through the "
      "function they serve" % (len(public), len(exported), len(inline), len(public) - len(missing) - len(exempt & set(public)),
                               len(exempt & set(public))))
for f in missing:
    print("FAIL %s: not called in tests/unit/test_fuzz.c" % f)
for f in served:
    print("FAIL %s: serves inline pieces but is itself not in the fuzz" % f)
print("fuzz_coverage: %d passed, %d failed" % (len(public) - len(missing), len(missing) + len(served)))
sys.exit(1 if missing or served else 0)
