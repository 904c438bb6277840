#!/usr/bin/env python3
"""Structural figures of the 2-rank runs of the settled bench scenes
(tests/bench/in.settled_spheres, in.settled_superquadrics), figures that do
not depend on how busy the machine is: per rank, the owned atoms, ghost
atoms, neighbour-list pairs and contacts (from a dump of the contacts at the
start of the timed run, counted on each side of the cut plane; with newton
off a contact across the cut is computed on both ranks), neighbour-list
builds, the bytes of the one forward communication per step, and the
speed-up these allow; then LIGGGHTS' time breakdown of the same runs on 1
and 2 ranks (this part does depend on the load: `uptime` is printed).
Not a test; prints figures, asserts nothing.

Usage: python3 tests/bench/scaling_figures.py [PREPDIR] [--steps-ss N]
  [--steps-sq N] [--models hertz,hertz_elliptic] [--knobs]
PREPDIR holds (or receives) the prepared restarts ss_<model>.restart and
sq_<model>.restart, the same names as bench_scenes.sh uses with
DC_BENCH_PREP=PREPDIR; missing ones are prepared (untimed, 2 ranks).
--knobs also runs the user's settings against the chosen ones: processor
grid along y or z, neighbour skin, `neigh_modify every`.
--instructions N also counts the instructions of N timed steps under
valgrind's callgrind (collected inside Verlet::run only) on 1 and 2 ranks,
those of the MPI libraries (the waiting ranks' polling among them) apart:
the work's speed-up in instructions, independent of the load; needs
valgrind, takes a few minutes for N = 200.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
LMP = os.path.join(ROOT, "build", "bin", "liggghts")
SCENES = {
    # tag: deck, cut plane x of the 2-rank split (box centre), doubles per ghost per step
    "ss": (os.path.join(ROOT, "tests", "bench", "in.settled_spheres"), 0.07, 9, "3264 spheres"),
    "sq": (os.path.join(ROOT, "tests", "bench", "in.settled_superquadrics"), 0.10, 13, "1056 superquadrics"),
}
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def run(deck, ranks, args, wd, hook=None):
    cmd = ([] if ranks == 1 else ["mpirun", "-np", str(ranks)]) + [LMP, "-in", deck, "-log", "log"] + args
    if hook:
        cmd += ["-var", "hook", hook]
    with open(os.path.join(wd, "screen.txt"), "w") as out:
        rc = subprocess.call(cmd, cwd=wd, stdout=out, stderr=subprocess.STDOUT, env=ENV)
    if rc:
        sys.exit("run failed (%s): see %s/screen.txt" % (" ".join(cmd), wd))
    return parse_log(os.path.join(wd, "log"))


def parse_log(path):
    text = open(path).read()
    text = text[text.rindex("Loop time of"):]
    r = {"loop": float(re.search(r"Loop time of (\S+)", text).group(1))}
    for key in ("Pair", "Neigh", "Comm", "Outpt", "Other"):
        m = re.search(r"^%s\s+time \(%%\) = (\S+) \((\S+)\)" % key, text, re.M)
        r[key] = float(m.group(2)) if m else 0.0
    for key in ("Nlocal", "Nghost", "Neighs"):
        m = re.search(r"^%s:\s+(\S+) ave (\S+) max (\S+) min" % key, text, re.M)
        r[key] = (float(m.group(3)), float(m.group(2)))   # min, max
    r["builds"] = int(re.search(r"Neighbor list builds = (\d+)", text).group(1))
    return r


def contacts(path, cut):
    """Contacts of the first frame of a dump local of `pos id force`: both
    atoms below the cut, both above, across."""
    lines = open(path).read().split("\n")
    n = int(lines[3])
    below = above = across = 0
    for row in lines[9:9 + n]:
        v = [float(t) for t in row.split()]
        if v[9] == 0.0 and v[10] == 0.0 and v[11] == 0.0:
            continue    # in the list, not touching
        a, b = v[0] < cut, v[3] < cut
        if a and b:
            below += 1
        elif not a and not b:
            above += 1
        else:
            across += 1
    return below, above, across


MPI_OBJ = re.compile(r"libmpi|libopen-|mca_|pmix|hwloc|libevent|libfabric|libuc[pst]")


def instructions(deck, base, wd):
    """Instructions inside Verlet::run: [(total, in MPI libraries)] for 1
    rank, then for each of 2 ranks."""
    vg = ["valgrind", "--tool=callgrind", "--toggle-collect=LAMMPS_NS::Verlet::run(int)"]
    args = ["-in", deck, "-log", "log"] + base
    out = []
    for ranks in (1, 2):
        d = os.path.join(wd, "callgrind%d" % ranks)
        os.makedirs(d)
        cmd = ([] if ranks == 1 else ["mpirun", "-np", "2"]) + vg + \
            ["--callgrind-out-file=cg.%q{OMPI_COMM_WORLD_RANK}.out" if ranks == 2 else "--callgrind-out-file=cg.0.out",
             LMP] + args
        with open(os.path.join(d, "screen.txt"), "w") as f:
            if subprocess.call(cmd, cwd=d, stdout=f, stderr=subprocess.STDOUT, env=ENV):
                sys.exit("callgrind run failed: see %s/screen.txt" % d)
        for r in range(ranks):
            ann = subprocess.check_output(["callgrind_annotate", "--inclusive=no", "--threshold=100",
                                           os.path.join(d, "cg.%d.out" % r)]).decode()
            tot = mpi = 0
            for line in ann.split("\n"):
                m = re.match(r"\s*([\d,]+) \(\s*[\d.]+%\)\s+.*\[(.*)\]\s*$", line)
                if m:
                    n = int(m.group(1).replace(",", ""))
                    tot += n
                    mpi += n if MPI_OBJ.search(m.group(2)) else 0
            out.append((tot, mpi))
    return out


HOOK = """compute dcpl all pair/gran/local pos id force
dump dcpl all local 100000000 contacts.local c_dcpl[1] c_dcpl[2] c_dcpl[3] c_dcpl[4] c_dcpl[5] c_dcpl[6] &
     c_dcpl[7] c_dcpl[8] c_dcpl[9] c_dcpl[10] c_dcpl[11] c_dcpl[12]
dump_modify dcpl first yes
"""


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("prepdir", nargs="?")
    ap.add_argument("--steps-ss", type=int, default=5000)
    ap.add_argument("--steps-sq", type=int, default=2000)
    ap.add_argument("--models", default="hertz,hertz_elliptic")
    ap.add_argument("--scenes", default="ss,sq")
    ap.add_argument("--knobs", action="store_true")
    ap.add_argument("--instructions", type=int, default=0, metavar="N")
    a = ap.parse_args()
    work = tempfile.mkdtemp(prefix="scaling_")
    prep = a.prepdir or os.path.join(work, "prep")
    os.makedirs(prep, exist_ok=True)
    hook = os.path.join(work, "hook")
    open(hook, "w").write(HOOK)
    print("uptime:", subprocess.check_output(["uptime"]).decode().strip())
    for tag in a.scenes.split(","):
        deck, cut, per_ghost, what = SCENES[tag]
        steps = a.steps_ss if tag == "ss" else a.steps_sq
        for model in a.models.split(","):
            rf = os.path.join(prep, "%s_%s.restart" % (tag, model))
            if not os.path.exists(rf):
                d = os.path.join(work, "prep_%s_%s" % (tag, model))
                os.makedirs(d)
                print("preparing %s (untimed)" % rf, file=sys.stderr)
                run(deck, 2, ["-var", "model", model, "-var", "prep", "1", "-var", "rfile", rf], d)
            base = ["-var", "model", model, "-var", "steps", str(steps), "-var", "rfile", rf]
            res = {}
            for ranks in (1, 2):
                d = os.path.join(work, "%s_%s_%d" % (tag, model, ranks))
                os.makedirs(d)
                res[ranks] = run(deck, ranks, base, d, hook)
                if ranks == 1:
                    below, above, across = contacts(os.path.join(d, "contacts.local"), cut)
            r1, r2 = res[1], res[2]
            total = below + above + across
            rank_c = (below + across, above + across)
            nl, ng, nn = r2["Nlocal"], r2["Nghost"], r2["Neighs"]
            n1 = r1["Nlocal"][0]
            print("\n%s, %s, %d steps from the settled restart" % (what, model, steps))
            print("  1 rank : atoms %d, neighbour pairs %d, contacts %d, neighbour builds %d"
                  % (n1, r1["Neighs"][0], total, r1["builds"]))
            print("  2 ranks: atoms per rank %d / %d (max/mean %.4f), ghosts %d / %d (%.1f%% of the owned atoms)"
                  % (nl[0], nl[1], 2 * nl[1] / n1, ng[0], ng[1], 100.0 * ng[1] / nl[1]))
            print("           neighbour pairs per rank %d / %d, sum %d = %.4f x 1 rank (duplicated across the cut)"
                  % (nn[0], nn[1], nn[0] + nn[1], (nn[0] + nn[1]) / r1["Neighs"][0]))
            print("           contacts per rank %d / %d, %d across the cut (%.2f%% of %d, computed twice)"
                  % (rank_c[0], rank_c[1], across, 100.0 * across / total, total))
            print("           neighbour builds %d; per step 1 forward communication of %d ghosts x %d doubles"
                  " (%.1f kB each way) and 1 MPI_Allreduce of the rebuild check; no reverse communication"
                  % (r2["builds"], ng[1], per_ghost, ng[1] * per_ghost * 8 / 1000.0))
            s_pair = total / max(rank_c)
            s_nbr = r1["Neighs"][0] / nn[1]
            s_atoms = n1 / nl[1]
            # the 1-rank breakdown weighted by each part's largest rank share
            f_pair, f_other = r1["Pair"] / 100.0, (r1["Other"] + r1["Neigh"] + r1["Outpt"]) / 100.0
            s_mix = 1.0 / (f_pair / s_pair + f_other / s_atoms + r1["Comm"] / 100.0)
            print("           largest rank's share: contacts %.4f, neighbour pairs %.4f, atoms %.4f"
                  % (1 / s_pair, 1 / s_nbr, 1 / s_atoms))
            print("           speed-up allowed by the work split (1-rank Pair %.1f%% at the contacts' share, the"
                  " rest at the atoms' share, no communication cost): %.3f" % (r1["Pair"], s_mix))
            for ranks, r in ((1, r1), (2, r2)):
                print("  breakdown %d rank%s: loop %.3f s; Pair %.1f%%, Neigh %.2f%%, Comm %.1f%%, Outpt %.3f%%,"
                      " Other (Modify: walls, integration, gravity) %.1f%%"
                      % (ranks, "" if ranks == 1 else "s", r["loop"], r["Pair"], r["Neigh"], r["Comm"],
                         r["Outpt"], r["Other"]))
            print("  measured speed-up (one pair of runs, load-dependent): %.3f" % (r1["loop"] / r2["loop"]))
            if a.instructions:
                d = os.path.join(work, "%s_%s_instructions" % (tag, model))
                os.makedirs(d)
                base_n = base[:3] + ["-var", "steps", str(a.instructions)] + base[6:]
                c = instructions(deck, base_n, d)
                w = [t - m for t, m in c]
                print("  instructions of %d steps (callgrind, inside Verlet::run, MPI libraries apart): 1 rank %.4g;"
                      " 2 ranks %.4g / %.4g (+ %.3g / %.3g in MPI, mostly polling), sum %.4f x 1 rank;"
                      " speed-up in instructions %.3f"
                      % (a.instructions, w[0], w[1], w[2], c[1][1], c[2][1], (w[1] + w[2]) / w[0], w[0] / max(w[1:])))
            if a.knobs and model == a.models.split(",")[0]:
                knobs = [("processors 1 * 1 (cut along y)", ["-var", "px", "1", "-var", "py", "*"]),
                         ("processors 1 1 * (cut along z)", ["-var", "px", "1", "-var", "pz", "*"])]
                skin = 0.0003 if tag == "ss" else 0.0005
                for s in (0.5, 2.0):
                    knobs.append(("skin %.2g mm (chosen %.2g mm)" % (s * skin * 1e3, skin * 1e3),
                                  ["-var", "skin", repr(s * skin)]))
                knobs.append(("neigh_modify every 10 check yes", ["-var", "every", "10"]))
                for name, extra in knobs:
                    d = os.path.join(work, "%s_%s_knob%d" % (tag, model, len(os.listdir(work))))
                    os.makedirs(d)
                    r = run(deck, 2, base + extra, d)
                    print("  knob %-34s: atoms %d / %d, ghosts %d / %d, neighbour pairs %d / %d, builds %d,"
                          " loop %.3f s (Comm %.1f%%)"
                          % (name, r["Nlocal"][0], r["Nlocal"][1], r["Nghost"][0], r["Nghost"][1],
                             r["Neighs"][0], r["Neighs"][1], r["builds"], r["loop"], r["Comm"]))
    print("\nuptime:", subprocess.check_output(["uptime"]).decode().strip())
    print("(runs kept in %s)" % work)


if __name__ == "__main__":
    main()
