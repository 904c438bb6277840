#!/usr/bin/env python3
"""Bad deck input ends the run with an error that names the cause (never a
crash or a silent NaN): unknown model, missing material property, a setting
outside its range, a missing property for an option, a setting the model
does not take, superquadrics without `surface superquadric`. Usage: check_deck_errors.py WORKDIR"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import ROOT, run, start

work, _, c = start()
props = lambda name: os.path.join(ROOT, "inputs", "deck_errors", name)
ok = {"props": props("props_full"), "settings": "limitForce off"}
cases = [
    ("unknown model", "in.sphere_base", dict(ok, model="hertz_eliptic tangential history"), "model hertz_eliptic tangential history"),
    ("missing youngsModulus", "in.sphere_base", dict(ok, model="hertz_elliptic tangential history", props=props("props_no_youngs")), "youngsModulus"),
    ("maxRadiusFactor out of range", "in.sphere_base", dict(ok, model="hertz_elliptic tangential history", settings="maxRadiusFactor 0.5"), "maxRadiusFactor must be in (1, 1e12]"),
    ("viscoelastic without viscoelasticTime", "in.sphere_base", dict(ok, model="hertz_elliptic tangential history", settings="viscoelastic on"), "viscoelasticTime"),
    ("roughnessMu outside [1, 50]", "in.sphere_base", dict(ok, model="gw_rough tangential history", props=props("props_rough_mu60")), "roughnessMu = 60 for types 1 and 1 is outside [1, 50]"),
    ("contact distance too small for the roughness", "in.sphere_base", dict(ok, model="gw_rough tangential history", props=props("props_rough"), x0="0.00099"), "set neigh_modify contact_distance_factor >="),
    ("missing workOfAdhesion", "in.sphere_base", dict(ok, model="jkr_elliptic tangential history", settings="tangential_damping on"), "workOfAdhesion"),
    ("limitForce on an adhesive model", "in.sphere_base", dict(ok, model="jkr_elliptic tangential history", settings="limitForce on"), "Normal model jkr_elliptic: 'limitForce on' is not available"),
    ("superquadrics without surface superquadric", "in.superquadric_no_surface", {"props": props("props_full")}, "needs 'surface superquadric'"),
]
for k, (name, deck, variables, message) in enumerate(cases):
    code, out = run("deck_errors/" + deck, os.path.join(work, "case%d" % k), variables=variables, tag="err", expect_error=True)
    err_lines = [l for l in out.splitlines() if "ERROR" in l]
    c.true(code != 0 and any(message in l for l in err_lines),
           "%s: exit %d, error line: %s" % (name, code, err_lines[0].strip() if err_lines else "(none)"))
# the same base deck with full input runs
code, out = run("deck_errors/in.sphere_base", os.path.join(work, "good"), variables=dict(ok, model="hertz_elliptic tangential history"), tag="ok", expect_error=True)
c.true(code == 0, "complete deck runs (exit %d)" % code)
c.finish()
