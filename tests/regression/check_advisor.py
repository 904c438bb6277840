#!/usr/bin/env python3
"""The advisor (tools/dcadvise.py) checked against runs, not by assertion.

For each scene (the project's examples, three of LIGGGHTS' own tutorials,
and scenes built on both sides of each threshold), the advisor reads the
deck; then, for each effect it predicts a change for, a probe of the
scene's contact with the wall (inputs/advisor, inputs/advisor_shape: the
scene's particle, material and speed) is run with the plain model and with
the richer one, and the measured change must
  - lie on the side of the tolerance the advisor said (a richer law needed
    or not), and
  - be within a factor 2 of the predicted change (where either exceeds a
    quarter of the tolerance; below that both must be below the tolerance).
Effects and probes:
  plasticity  restitution of a head-on impact at the scene's largest speed,
              elastic against elastic-plastic (in.probe_impact);
  adhesion    pull-off force from the wall, none against JKR
              (in.probe_pulloff), as a fraction of the weight for the side;
  sticking    a JKR impact at the scene's speed (in.probe_impact): sticks
              where the advisor's sticking speed exceeds it, else rebounds
              at (v^2 - v_stick^2)^1/2;
  roughness   the wall force at the overlap at rest, smooth against rough
              (in.probe_static);
  pair plasticity, pair sticking  the same for two particles of the
              class meeting head-on (in.probe_pair_impact): the pair's
              restitution change, and whether they stick;
  tangential memory  the contact point's tangential restitution of a
              45-degree impact, tangential history against cmd_tangential,
              and cmd_tangential's bounded memory (cmdMemory turningPoints)
              against its exact profile (in.probe_oblique);
  time step   the elastic impact at the deck's dt against dt/50: duration
              and restitution (the error part of the advisor's rule);
  shape       the wall force of 24 superquadrics in random orientations at
              equal overlap, one radius against the curvatures
              (in.probe_shape): max and rms of F_1/F - 1.
Writes advisor_runs.csv (scene, effect, predicted, measured) into the work
folder; the table in doc/advisor.md is this file."""
import csv
import importlib.util
import io
import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import regress  # noqa: E402

ROOT = regress.ROOT
spec = importlib.util.spec_from_file_location("dcadvise", os.path.join(ROOT, "tools", "dcadvise.py"))
dcadvise = importlib.util.module_from_spec(spec)
spec.loader.exec_module(dcadvise)
TUT = os.path.join(ROOT, ".deps", "liggghts-3.8.0", "examples", "LIGGGHTS", "Tutorials_public")
SCENE = os.path.join(ROOT, "inputs", "advisor", "in.scene_drop")
TOL = 0.05

# (name, deck, -var pairs, advisor options, effects run)
SCENES = [
    ("example superquadric_settling", os.path.join(ROOT, "examples", "superquadric_settling", "in.superquadric_settling"),
     [], {}, ["shape", "time step", "tangential memory"]),
    ("example rough_packing, sigma_r 0.001", os.path.join(ROOT, "examples", "rough_packing", "in.rough_packing"),
     [("sigma_r", "0.001")], {}, ["roughness"]),
    ("example adhesive_settling", os.path.join(ROOT, "examples", "adhesive_settling", "in.adhesive_settling"), [], {},
     ["adhesion", "sticking"]),
    ("example rough_cohesive_powder", os.path.join(ROOT, "examples", "rough_cohesive_powder", "in.rough_cohesive_powder"),
     [], {}, ["roughness", "adhesion"]),
    ("tutorial packing, hardness 2e4 Pa", os.path.join(TUT, "packing", "in.packing"), [], {"H": 2e4}, ["plasticity"]),
    ("tutorial cohesion, w 0.01 J/m^2", os.path.join(TUT, "cohesion", "in.cohesion"), [], {"w": 0.01}, ["adhesion"]),
    ("tutorial conveyor, sigma 50 um", os.path.join(TUT, "conveyor", "in.conveyor"), [], {"sigma": 5e-5}, ["roughness"]),
    ("drop: hard, below yield", SCENE, [("H", "1e9")], {}, ["plasticity", "tangential memory"]),
    ("drop: near yield", SCENE, [("H", "3e7")], {}, ["plasticity", "pair plasticity"]),
    ("drop: soft, beyond yield", SCENE, [("H", "1e7")], {}, ["plasticity", "pair plasticity"]),
    ("drop: weak adhesion", SCENE, [("w", "1e-5")], {}, ["adhesion", "sticking"]),
    ("drop: strong adhesion", SCENE, [("w", "0.05")], {}, ["adhesion", "sticking", "pair sticking"]),
    ("drop: fine sticky powder", SCENE, [("w", "0.5"), ("r", "2e-5"), ("E", "5e6")], {},
     ["adhesion", "sticking", "pair sticking"]),
    ("drop: smooth", SCENE, [("sigma", "1e-9")], {}, ["roughness", "time step"]),
    ("drop: coarse time step", SCENE, [("dt", "2e-5")], {}, ["time step"]),
    ("drop: slippery (mu 0.05)", SCENE, [("mu", "0.05")], {}, ["tangential memory"]),
    ("drop: rough", SCENE, [("sigma", "2e-6")], {}, ["roughness"]),
]


def advise(deck, variables, options):
    o = dcadvise.parse_args([deck] + sum([["-var", k, v] for k, v in variables], []) +
                            sum([["--%s" % k, repr(v)] for k, v in options.items()], []))
    o.dclaw = regress.DCLAW
    d = dcadvise.Deck(deck, o.vars)
    rows, measures, parts, v = dcadvise.advise(d, o, io.StringIO())
    return d, o, rows, measures, parts, v


def probe(deck, work, tag, variables):
    regress.run(deck, work, variables=dict(variables, dir=os.path.dirname(deck)), tag=tag)
    return regress.table(os.path.join(work, "probe.txt"))


def material(m, part):
    """The probe's variables: one type for the particle and the wall, with the
    pair's E* (nu of the particle), combined roughness, w, hardness and mu as
    the advisor took them for the wall contact."""
    nu = m["in_nu"]
    return {"R": part["radius"], "rho": part["density"], "E": 2.0 * (1.0 - nu * nu) * m["Estar"], "nu": nu,
            "H": m["in_H"] if m["in_H"] > 0 else 1e30, "w": m["in_w"], "sigma": m["in_sigma"] / math.sqrt(2.0),
            "mu_r": m["in_mu_rough"]}


def run_plasticity(work, mat, m, v):
    dt = m["t_c"] / 4000.0
    steps = int(3 * m["t_c"] / dt)
    e = {}
    for model in ("hertz_elliptic", "jamari_ep"):
        rows = probe(os.path.join(ROOT, "inputs", "advisor", "in.probe_impact"), work, model,
                     dict(mat, model=model, v=repr(v), dt=repr(dt), steps=steps))
        e[model] = rows[-1][2] / v
    return 1.0 - m["e_plastic"], e["hertz_elliptic"] - e["jamari_ep"]


def run_adhesion(work, mat, m):
    # pressed to the overlap of the contact at rest (at least half JKR's
    # separation overlap) in 2000 steps, then pulled back as slowly until
    # 1.5 separation overlaps apart
    dt = m["t_c"] / 2000.0
    delta = max(m["delta_rest"], 0.5 * m["jkr_separation"])
    u = delta / (2000 * dt)
    steps = int((delta + 1.5 * m["jkr_separation"]) / (u * dt)) + 100
    F = {}
    for model in ("hertz_elliptic", "jkr_elliptic"):
        rows = probe(os.path.join(ROOT, "inputs", "advisor", "in.probe_pulloff"), work, model,
                     dict(mat, model=model, delta=repr(delta), u=repr(u), dt=repr(dt), steps=steps))
        F[model] = max(max(-r[3] for r in rows), 0.0)
    meas = (F["jkr_elliptic"] - F["hertz_elliptic"]) / m["weight"]
    return m["pulloff_over_weight"], meas


def run_sticking(work, mat, m, v):
    """JKR impact at the scene's speed (no damping): the rebound speed, (v^2 - v_stick^2)^1/2 by energy, or 0 (sticks)"""
    dt = m["t_c"] / 4000.0
    rows = probe(os.path.join(ROOT, "inputs", "advisor", "in.probe_impact"), work, "jkr_impact",
                 dict(mat, model="jkr_elliptic", v=repr(v), dt=repr(dt), steps=int(6 * m["t_c"] / dt)))
    pred = math.sqrt(max(v * v - m["v_stick"] ** 2, 0.0))
    apart = rows[-1][1] > mat["R"] + m["jkr_separation"]   # beyond the neck's reach at the end
    return pred, rows[-1][2] if apart else 0.0


def run_time_step(work, mat, m, v, dt):
    """The elastic impact at the deck's dt against dt/50: the larger of the
    contact duration's and the restitution's relative change"""
    got = {}
    for tag, h in (("deck", dt), ("fine", dt / 50.0)):
        rows = probe(os.path.join(ROOT, "inputs", "advisor", "in.probe_impact"), work, "dt_" + tag,
                     dict(mat, model="hertz_elliptic", v=repr(v), dt=repr(h), steps=int(3 * m["t_c"] / h) + 10))
        n = sum(1 for r in rows if r[1] < mat["R"])
        got[tag] = (n * h, rows[-1][2] / v)
    meas = max(abs(got["deck"][0] / got["fine"][0] - 1.0), abs(got["deck"][1] - got["fine"][1]))
    return max(m["duration_error"], m["restitution_error"]), meas


def run_tangential(work, mat, m, v):
    """the contact point's tangential restitution of a 45-degree impact: stock
    history against cmd_tangential, and its bounded memory against it
    (predicted and measured each)"""
    dt = m["t_c"] / 4000.0
    beta = {}
    for tm in ("history", "cmd_tangential", "cmd_tangential cmdMemory turningPoints"):
        variables = {"dir": os.path.join(ROOT, "inputs", "advisor_oblique"), "tmodel": tm.split(" ", 1)[0],
                     "R": mat["R"], "rho": mat["rho"], "E": mat["E"], "nu": mat["nu"], "mu": m["in_mu"], "v": repr(v),
                     "vt": repr(v), "dt": repr(dt), "steps": int(2 * m["t_c"] / dt)}
        if " " in tm:
            variables["tset"] = tm.split(" ", 1)[1]   # the model's settings, after the wall's primitive
        regress.run(os.path.join(ROOT, "inputs", "advisor_oblique", "in.probe_oblique"), work,
                    tag="oblique_" + tm.replace(" ", "_"), variables=variables)
        last = regress.table(os.path.join(work, "probe.txt"))[-1]
        beta[tm] = (last[2] - mat["R"] * last[4]) / v
    tp = "cmd_tangential cmdMemory turningPoints"
    return (abs(m["beta_cmd"] - m["beta_history"]), abs(beta["cmd_tangential"] - beta["history"]),
            abs(m["beta_cmd"] - m["beta_turning_points"]), abs(beta["cmd_tangential"] - beta[tp]))


def run_pair(work, mat, mp, v, model):
    """two spheres of the class head-on at relative speed v: the relative rebound speed over v (0: they stick)"""
    dt = mp["t_c"] / 4000.0
    regress.run(os.path.join(ROOT, "inputs", "advisor", "in.probe_pair_impact"), work, tag="pair_" + model,
                variables={"dir": os.path.join(ROOT, "inputs", "advisor"), "model": model, "R1": mat["R"], "R2": mat["R"],
                           "rho1": mat["rho"], "rho2": mat["rho"], "E": mat["E"], "nu": mat["nu"], "H": mat["H"],
                           "w": mat["w"], "v": repr(v), "dt": repr(dt), "steps": int(6 * mp["t_c"] / dt)})
    last = regress.table(os.path.join(work, "probe.txt"))[-1]
    apart = last[2] - last[1] > 2 * mat["R"] + mp["jkr_separation"]
    return (last[4] - last[3]) / v if apart else 0.0


def run_roughness(work, mat, m):
    F = {}
    for model in ("hertz_elliptic", "gw_rough"):
        rows = probe(os.path.join(ROOT, "inputs", "advisor", "in.probe_static"), work, model,
                     dict(mat, model=model, delta=repr(m["delta_rest"]), dt="1e-9"))
        F[model] = rows[-1][3]
    return abs(m["rough_force_rest"]), abs(F["gw_rough"] / F["hertz_elliptic"] - 1.0)


def support(shape, bl, Rm):
    """Lowest world z of the superquadric turned by the rotation matrix Rm (equal blockiness: exact)."""
    n = bl[0]
    q = n / (n - 1.0)
    d = [-Rm[2][k] for k in range(3)]   # body frame of world -z
    return (sum(abs(shape[k] * d[k]) ** q for k in range(3))) ** (1.0 / q)


def run_shape(work, m, part, rng):
    """max and rms over random orientations of |F_hertz / F_hertz_elliptic - 1| at equal overlap"""
    sh, bl = part["shape"], part.get("blockiness", (2.0, 2.0))
    if bl[0] != bl[1]:
        raise SystemExit("FAIL the shape probe takes equal blockiness (got %s)" % (bl,))
    L = max(sh)
    lines, N = [], 24
    for i in range(N):
        ax = [rng.gauss(0, 1) for _ in range(3)]
        al = math.sqrt(sum(x * x for x in ax))
        ax = [x / al for x in ax]
        th = rng.uniform(0, math.pi)
        c, s = math.cos(th), math.sin(th)
        x, y, z = ax
        Rm = [[c + x * x * (1 - c), x * y * (1 - c) - z * s, x * z * (1 - c) + y * s],
              [y * x * (1 - c) + z * s, c + y * y * (1 - c), y * z * (1 - c) - x * s],
              [z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c)]]
        h = support(sh, bl, Rm)
        lines.append("create_atoms 1 single %r 0 %r units box" % (3 * L * i, h - 1e-3 * L))
        lines.append("set atom %d shape %r %r %r blockiness %r %r density %r" % (i + 1, sh[0], sh[1], sh[2], bl[0], bl[1],
                                                                                  part["density"]))
        lines.append("set atom %d quat %r %r %r %r" % (i + 1, x, y, z, math.degrees(th)))
    os.makedirs(work, exist_ok=True)
    atoms = os.path.join(work, "atoms.inc")
    open(atoms, "w").write("\n".join(lines) + "\n")
    nu = m["in_nu"]
    F = {}
    for model in ("hertz", "hertz_elliptic"):
        regress.run(os.path.join(ROOT, "inputs", "advisor_shape", "in.probe_shape"), work, tag=model,
                    variables={"dir": os.path.join(ROOT, "inputs", "advisor_shape"), "model": model, "atoms": atoms,
                               "E": 2.0 * (1.0 - nu * nu) * m["Estar"], "nu": nu,
                               "xlo": -2 * L, "xhi": 3 * L * N, "ylo": -2 * L, "yhi": 2 * L, "zlo": -L, "zhi": 3 * L,
                               "skin": 0.2 * L})
        rows = [l.split() for l in open(os.path.join(work, "probe.txt")).read().split("ITEM: ATOMS")[1].splitlines()[1:]]
        F[model] = {int(r[0]): float(r[1]) for r in rows if r}
    err = [abs(F["hertz"][i] / F["hertz_elliptic"][i] - 1.0) for i in F["hertz"] if F["hertz_elliptic"].get(i, 0) > 0]
    if len(err) != N:
        raise SystemExit("FAIL shape probe: %d of %d superquadrics touched the wall in both runs" % (len(err), N))
    return max(err), math.sqrt(sum(e * e for e in err) / N)


def main():
    work, update, c = regress.start()
    rng = random.Random(20261205)
    out = []
    for name, deck, variables, options, effects in SCENES:
        d, o, rows, measures, parts, v = advise(deck, variables, options)
        # the wall contact of the first particle class (the probes' contact)
        part = parts[0]
        m = next(mm for mm in measures if mm["kind"] == "%s on a wall" % part["label"])
        needs = {r[1]: r[3] for r in rows if r[0] == m["kind"]}
        mat = material(m, part)
        wd = os.path.join(work, name.split(",")[0].replace(" ", "_").replace(":", ""))
        for eff in effects:
            if eff == "plasticity":
                pred, meas = run_plasticity(wd, mat, m, v)
                richer = needs[eff] == "jamari_ep"
            elif eff == "adhesion":
                pred, meas = run_adhesion(wd, mat, m)
                richer = needs[eff].startswith("jkr_elliptic")
            elif eff == "sticking":
                pred, meas = run_sticking(wd, mat, m, v)
                out.append((name, eff, pred, meas))
                c.true((meas == 0.0) == (pred == 0.0), "%s: JKR impact at %.3g m/s %s, as the advisor said (sticking "
                       "speed %.3g m/s)" % (name, v, "sticks" if meas == 0.0 else "rebounds at %.3g m/s" % meas, m["v_stick"]))
                if pred > 0.0:
                    c.true(meas > 0 and 0.5 <= pred / meas <= 2.0, "%s: rebound speed predicted %.3g, measured %.3g (factor 2)"
                           % (name, pred, meas))
                continue
            elif eff == "pair plasticity":
                mp = next(mm for mm in measures if mm["kind"] == "%s with %s" % (part["label"], part["label"]))
                pred = 1.0 - mp["e_plastic"]
                meas = run_pair(wd, mat, mp, v, "hertz_elliptic") - run_pair(wd, mat, mp, v, "jamari_ep")
                richer = next(r[3] for r in rows if r[0] == mp["kind"] and r[1] == "plasticity") == "jamari_ep"
            elif eff == "pair sticking":
                mp = next(mm for mm in measures if mm["kind"] == "%s with %s" % (part["label"], part["label"]))
                pred = math.sqrt(max(1.0 - (mp["v_stick"] / v) ** 2, 0.0))
                meas = run_pair(wd, mat, mp, v, "jkr_elliptic")
                out.append((name, eff, pred, meas))
                c.true((meas == 0.0) == (pred == 0.0), "%s: two spheres at %.3g m/s %s, as the advisor said (sticking "
                       "speed %.3g m/s)" % (name, v, "stick" if meas == 0.0 else "part at %.3g of it" % meas, mp["v_stick"]))
                if pred > 0.0:
                    c.true(meas > 0 and 0.5 <= pred / meas <= 2.0, "%s: relative rebound predicted %.3g, measured %.3g "
                           "(factor 2)" % (name, pred, meas))
                continue
            elif eff == "tangential memory":
                pred, meas, pred_tp, meas_tp = run_tangential(wd, mat, m, v)
                richer = needs[eff] != "tangential history"
                out.append((name, "tangential memory: turningPoints", pred_tp, meas_tp))
                if richer:
                    # a Cattaneo-Mindlin law: the bounded memory where its change is within the tolerance
                    c.true((meas_tp > TOL) == (needs[eff] == "cmd_tangential"),
                           "%s: turningPoints against the exact profile: measured change %.3g %s the tolerance %g, "
                           "as the advisor said (%s)" % (name, meas_tp, ">" if meas_tp > TOL else "<=", TOL, needs[eff]))
                c.true(abs(pred_tp - meas_tp) <= max(0.5 * meas_tp, TOL / 4),
                       "%s: turningPoints' change predicted %.3g, measured %.3g" % (name, pred_tp, meas_tp))
            elif eff == "time step":
                pred, meas = run_time_step(wd, mat, m, v, d.dt[0])
                richer = pred > TOL   # the error part of the advisor's rule (the Rayleigh part is no run's)
            elif eff == "roughness":
                pred, meas = run_roughness(wd, mat, m)
                richer = needs[eff] == "gw_rough"
            elif eff == "shape":
                pred, pred_rms = m["shape_error_max"], m["shape_error_rms"]
                meas, meas_rms = run_shape(wd, m, part, rng)
                richer = needs[eff] == "hertz_elliptic"
                out.append((name, "shape rms", pred_rms, meas_rms))
                c.true(0.5 <= pred_rms / meas_rms <= 2.0, "%s: shape rms: predicted %.3g, measured %.3g (factor 2)"
                       % (name, pred_rms, meas_rms))
            out.append((name, eff, pred, meas))
            c.true((meas > TOL) == richer, "%s: %s: measured change %.3g %s the tolerance %g, as the advisor said (%s)"
                   % (name, eff, meas, ">" if meas > TOL else "<=", TOL, needs.get(eff, "jamari_ep" if richer else "elastic law")))
            if max(pred, meas) >= TOL / 4:
                c.true(meas > 0 and 0.5 <= pred / meas <= 2.0, "%s: %s: predicted %.3g, measured %.3g (factor 2)"
                       % (name, eff, pred, meas))
            else:
                c.true(pred < TOL and meas < TOL, "%s: %s: predicted %.3g and measured %.3g both small" % (name, eff, pred, meas))
    with open(os.path.join(work, "advisor_runs.csv"), "w", newline="") as f:
        wr = csv.writer(f)
        wr.writerow(["scene", "effect", "predicted", "measured"])
        for r in out:
            wr.writerow([r[0], r[1], "%.4g" % r[2], "%.4g" % r[3]])
    c.finish()


if __name__ == "__main__":
    main()
