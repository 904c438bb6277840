#!/usr/bin/env python3
"""Bad deck input ends the run with an error that names the cause (never a
crash or a silent NaN): unknown model, missing material property, a setting
outside its range, a missing property for an option, a setting the model
does not take, superquadrics without `surface superquadric`, the rolling
model `kalker` without its property, with a setting out of range, under a
normal model that publishes no contact patch or with a tangential model
that does not hand over; and the stock failures the project's patches and
decks turn into messages: a particle that leaves the box (thermo_modify
lost error), coincident spheres, a
sphere centre on a wall, a position that is not a number, youngsModulus <= 0 with
soft_particles, a property value that is not a finite number, write_data
with superquadrics (read back) and with contact history (a warning); a
contact beyond the range of Hertz theory (a warning); attached rough adhesive
summits resumed from a restart with too small a contact distance;
cohesion gw_adhesion without the normal model it adds to (gw_rough
gwElliptic on); cmd_tangential's tangentialRoughness without gw_rough or
with cmdTwisting; an unknown cmdMemory; an unknown adhesionLaw; adhesionLaw maugis without
equilibriumSeparation, with it 0; adhesionLaw tabor on superquadrics; jamari_ep under
LIGGGHTS' sjkr with a cohesive pressure the plastic contact cannot carry.
Usage: check_deck_errors.py WORKDIR"""
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
    ("curvatureTolerance out of range", "in.sphere_base", dict(ok, model="hertz_elliptic tangential history", settings="curvatureTolerance 0.2"), "curvatureTolerance must be in [0, 0.1]"),
    ("curvatureCheck out of range", "in.sphere_base", dict(ok, model="gw_rough tangential history", props=props("props_rough"), settings="curvatureCheck -1"), "curvatureCheck must be in [0, 1]"),
    ("curvatureTolerance with jkr_elliptic", "in.sphere_base", dict(ok, model="jkr_elliptic tangential history", props=props("props_jkr"), settings="curvatureTolerance 1e-4"), "jkr_elliptic: curvatureTolerance is not available"),
    ("viscoelastic without viscoelasticTime", "in.sphere_base", dict(ok, model="hertz_elliptic tangential history", settings="viscoelastic on"), "viscoelasticTime"),
    ("roughnessMu outside [1, 50]", "in.sphere_base", dict(ok, model="gw_rough tangential history", props=props("props_rough_mu60")), "roughnessMu = 60 for types 1 and 1 is outside [1, 50]"),
    ("contact distance too small for the roughness", "in.sphere_base", dict(ok, model="gw_rough tangential history", props=props("props_rough"), x0="0.00099"), "set neigh_modify contact_distance_factor >="),
    # gw_rough's reach (3 sigma) is within contact distance 1.2, the attached summits' (D + 8 sigma) is not
    ("contact distance too small for attached rough adhesive summits", "in.sphere_base", dict(ok, model="gw_rough tangential history cohesion gw_adhesion", props=props("props_rough_adhesive"), settings="gwElliptic on", x0="0.00099", cdf="1.2"), "Cohesion model gw_adhesion: attached summits pull up to 0.000566569 m apart: set neigh_modify contact_distance_factor >= 1.283"),
    ("gw_adhesion without gwElliptic on", "in.sphere_base", dict(ok, model="gw_rough tangential history cohesion gw_adhesion", props=props("props_rough_adhesive"), settings=""), "Cohesion model gw_adhesion needs the normal model gw_rough with 'gwElliptic on'"),
    ("gw_adhesion under hertz_elliptic", "in.sphere_base", dict(ok, model="hertz_elliptic tangential history cohesion gw_adhesion", props=props("props_rough_adhesive"), settings=""), "Cohesion model gw_adhesion needs the normal model gw_rough with 'gwElliptic on'"),
    ("jamari_ep under sjkr with a cohesive pressure above the plastic one", "in.sphere_base", dict(ok, model="jamari_ep tangential history cohesion sjkr", props=props("props_jamari_sjkr"), settings=""), "Normal model jamari_ep: cohesionEnergyDensity = 300000 Pa for types 1 and 1 is not below the largest contact pressure of the plastic contact, plasticityCh x hardness = 10000 Pa: cohesion sjkr would pull"),
    ("tangentialRoughness under hertz_elliptic", "in.sphere_base", dict(ok, model="hertz_elliptic tangential cmd_tangential", settings="tangentialRoughness on"), "Tangential model cmd_tangential: tangentialRoughness on needs the normal model gw_rough"),
    ("tangentialRoughness with cmdTwisting", "in.sphere_base", dict(ok, model="gw_rough tangential cmd_tangential", props=props("props_rough"), settings="tangentialRoughness on cmdTwisting on", cdf="1.2"), "tangentialRoughness on does not take cmdTwisting on"),
    ("unknown cmdMemory", "in.sphere_base", dict(ok, model="hertz_elliptic tangential cmd_tangential", settings="cmdMemory fewPoints"), "(options: profile turningPoints"),
    ("unknown adhesionLaw", "in.sphere_base", dict(ok, model="jkr_elliptic tangential history", props=props("props_jkr"), settings="adhesionLaw bradley"), "(options: dmt jkr maugis tabor"),
    ("adhesionLaw maugis without equilibriumSeparation", "in.sphere_base", dict(ok, model="jkr_elliptic tangential history", props=props("props_jkr"), settings="adhesionLaw maugis"), "equilibriumSeparation"),
    ("equilibriumSeparation 0", "in.sphere_base", dict(ok, model="jkr_elliptic tangential history", props=props("props_md_zero"), settings="adhesionLaw tabor"), "Normal model jkr_elliptic: equilibriumSeparation = 0 for types 1 and 1 is outside (0, inf) m"),
    ("adhesionLaw tabor on superquadrics", "../superquadric_pulloff/in.superquadric_pulloff", {"alaw": "tabor", "w": 0.5, "omega": 0.0}, "Normal model jkr_elliptic: adhesionLaw tabor is for spheres; superquadrics take adhesionLaw jkr, dmt or maugis"),
    ("missing workOfAdhesion", "in.sphere_base", dict(ok, model="jkr_elliptic tangential history", settings="tangential_damping on"), "workOfAdhesion"),
    ("limitForce on an adhesive model", "in.sphere_base", dict(ok, model="jkr_elliptic tangential history", settings="limitForce on"), "Normal model jkr_elliptic: 'limitForce on' is not available"),
    ("superquadrics without surface superquadric", "in.superquadric_no_surface", {"props": props("props_full")}, "needs 'surface superquadric'"),
    ("jamari_ep without hardness", "in.sphere_base", dict(ok, model="jamari_ep tangential history", settings=""), "hardness"),
    ("plasticityCa outside [2, inf)", "in.sphere_base", dict(ok, model="jamari_ep tangential history", props=props("props_hardness"), settings="plasticityCa 1"), "plasticityCa = 1 for types 1 and 1 is outside [2, inf)"),
    ("unknown classicalTangential law", "in.sphere_base", dict(ok, model="hertz_elliptic tangential classical classicalTangential springy", settings=""), "(options: coulomb diRenzo incremental langston"),
    ("coincident spheres", "in.sphere_base", dict(ok, model="hertz tangential history", settings="", x0="0"), "Atoms 1 and 2 are at the same position"),
    ("sphere centre on a wall", "in.sphere_wall", {"props": props("props_full"), "z0": "0"}, "Atom 1 has its centre on the wall"),
    ("a particle leaves the box (thermo_modify lost error)", "in.sphere_wall", {"props": props("props_full"), "fx": "1e308"}, "Lost atoms"),
    ("NaN position", "in.sphere_wall", {"props": props("props_full"), "fx": "v_nan"}, "Atom 1 has a non-finite position"),
    ("youngsModulus 0 with soft_particles", "in.sphere_base", dict(ok, model="hertz_elliptic tangential history", props=props("props_soft_zero")), "youngsModulus for type 1 is 0: it must be > 0"),
    ("youngsModulus 1e999", "in.sphere_base", dict(ok, model="hertz_elliptic tangential history", props=props("props_inf")), "Fix property/global youngsModulus: value 1 is '1e999', not a finite number"),
    ("rolling kalker without coefficientFriction", "in.sphere_base", dict(ok, model="hertz_elliptic tangential classical rolling_friction kalker classicalTangential viscous", props=props("props_no_friction"), settings=""), "coefficientFriction as requested by rolling_model kalker"),
    ("rolling kalker: coefficientFriction < 0", "in.sphere_base", dict(ok, model="hertz_elliptic tangential classical rolling_friction kalker classicalTangential viscous", props=props("props_negative_friction"), settings=""), "Rolling model kalker: coefficientFriction = -0.5 for types 1 and 1 is outside [0, inf)"),
    ("rollingVelocityMin 0", "in.sphere_base", dict(ok, model="hertz_elliptic tangential cmd_tangential rolling_friction kalker", settings="rollingVelocityMin 0"), "Rolling model kalker: rollingVelocityMin = 0 m/s is outside (0, inf)"),
    ("unknown rollingCreepModel", "in.sphere_base", dict(ok, model="hertz_elliptic tangential cmd_tangential rolling_friction kalker", settings="rollingCreepModel linear"), "unknown option or wrong keyword order: 'linear' (options: kalker vermeulenJohnson)"),
    ("rolling kalker under a stock normal model", "in.sphere_base", dict(ok, model="hertz tangential history rolling_friction kalker", settings=""), "Rolling model kalker needs a normal model that publishes the contact patch"),
    ("rolling kalker with a tangential model that does not hand over", "in.sphere_base", dict(ok, model="hertz_elliptic tangential history rolling_friction kalker", settings=""), "Rolling model kalker needs a tangential model that hands the tangential force over while the contact rolls: tangential cmd_tangential or tangential classical"),
    ("tiny youngsModulus with soft_particles (jkr_elliptic)", "in.sphere_base", dict(ok, model="jkr_elliptic tangential history", props=props("props_soft_tiny"), settings="tangential_damping on", x0="0.00099"), "too small a youngsModulus (E* = 5.49451e-301 for types 1 and 1)"),
]
for k, (name, deck, variables, message) in enumerate(cases):
    code, out = run("deck_errors/" + deck, os.path.join(work, "case%d" % k), variables=variables, tag="err", expect_error=True)
    err_lines = [l for l in out.splitlines() if "ERROR" in l]
    c.true(code != 0 and any(message in l for l in err_lines),
           "%s: exit %d, error line: %s" % (name, code, err_lines[0].strip() if err_lines else "(none)"))
# warnings where a data file loses state, and superquadrics read back
code2, out2 = run("deck_errors/in.superquadric_data", os.path.join(work, "sq_data"), variables={"props": props("props_full")}, tag="sq", expect_error=True)
c.true(code2 == 0 and "superquadric orientations are not written" in out2 and "contact history is not written" in out2,
       "write_data with superquadrics: exit %d, warnings on orientation and contact history" % code2)
rows = {}
dump = os.path.join(work, "sq_data", "back.dump")
if os.path.exists(dump):
    lines = open(dump).read().split("\n")
    k = [l.strip() for l in lines].index("ITEM: ATOMS id type shapex shapey shapez blockiness1 blockiness2 density x y z")
    for l in lines[k + 1:]:
        if l.strip():
            v = l.split()
            rows[int(v[0])] = [float(x) for x in v[2:]]
want = {1: [0.001, 0.0015, 0.002, 2, 2, 2500, 0.0, 0.0, 0.0], 2: [0.0012, 0.0012, 0.0025, 4, 3, 2600, 0.005, 0.0, 0.0]}
c.true(rows.keys() == want.keys() and all(abs(rows[i][k] - want[i][k]) <= 1e-12 * max(1.0, abs(want[i][k]))
                                          for i in want for k in range(9)),
       "superquadrics read back from write_data: shape, blockiness, density, position %s" % rows)
# Hertz theory beyond its range: a warning, once, naming the contact
code3, out3 = run("deck_errors/in.sphere_base", os.path.join(work, "hertz_range"),
                  variables=dict(ok, model="hertz_elliptic tangential history", x0="0.0007"), tag="range", expect_error=True)
warn = [l for l in out3.splitlines() if "where Hertz theory no longer holds" in l]
c.true(code3 == 0 and len(warn) >= 1 and "atom 1 with atom 2" in warn[0] and len(set(warn)) == 1,
       "overlap beyond the Hertz range: one warning naming the contact (%s)" % (warn[0].strip() if warn else "none"))
# once per process for the pair style and every wall together: the pair
# and two walls all beyond the range
code3, out3 = run("deck_errors/in.sphere_base", os.path.join(work, "hertz_range_walls"),
                  variables=dict(ok, model="hertz_elliptic tangential history", x0="0.0007", walls=1), tag="range",
                  expect_error=True)
log3 = open(os.path.join(work, "hertz_range_walls", "log.range")).read()
warn = [l for l in log3.splitlines() if "where Hertz theory no longer holds" in l]
c.true(code3 == 0 and len(warn) == 1,
       "pair and two walls beyond the Hertz range: one warning in the log (%d: %s)" % (len(warn), warn))
for model, prop in (("jamari_ep", "props_hardness"), ("jkr_elliptic", "props_jkr"), ("gw_rough", "props_rough_reach")):
    code4, out4 = run("deck_errors/in.sphere_base", os.path.join(work, "hertz_range_" + model),
                      variables=dict(ok, model=model + " tangential history", props=props(prop), settings="", x0="0.0007"),
                      tag="range", expect_error=True)
    warn = [l for l in out4.splitlines() if "where Hertz theory no longer holds" in l]
    c.true(code4 == 0 and len(set(warn)) == 1 and "Normal model " + model in warn[0],
           "%s beyond the Hertz range: one warning (%s)" % (model, warn[0].strip() if warn else "none"))
# attached rough adhesive summits resumed from a restart with a contact
# distance too small for them: the pair (0.4 mm apart, attached, settled in
# its table cell) is checked in the run's first pass, not only when it
# leaves its cell
rough = dict(ok, model="gw_rough tangential history cohesion gw_adhesion", props=props("props_rough_adhesive"),
             settings="gwElliptic on")
d = os.path.join(work, "reach_restart")
code5, out5 = run("deck_errors/in.sphere_base", d, variables=dict(rough, x0="0.0012", cdf="1.3", restart=1), tag="first",
                  expect_error=True)
code6, out6 = run("deck_errors/in.sphere_resume", d, variables=dict(rough, cdf="1.25"), tag="resumed",
                  expect_error=True)
err = [l for l in out6.splitlines() if "ERROR" in l]
c.true(code5 == 0 and code6 != 0 and any("attached summits pull up to 0.000566569 m apart: set neigh_modify "
                                         "contact_distance_factor >= 1.283" in l for l in err),
       "attached rough adhesive summits resumed with contact distance 1.25 (first run exit %d): exit %d, error line: %s"
       % (code5, code6, err[0].strip() if err else "(none)"))
# the same base deck with full input runs
code, out = run("deck_errors/in.sphere_base", os.path.join(work, "good"), variables=dict(ok, model="hertz_elliptic tangential history"), tag="ok", expect_error=True)
c.true(code == 0, "complete deck runs (exit %d)" % code)
c.finish()
