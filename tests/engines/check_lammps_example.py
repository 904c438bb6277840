"""The LAMMPS example (examples/lammps_adhesive_settling, shortened to
20000 steps) on 2 ranks, and its ParaView output: tools/dump2vtk.py
converts LAMMPS' dump custom files; VTK's own XML reader (through
tests/regression/check_paraview.py --vtk-read) reads every particle file
back: the .pvd lists one file per snapshot at time step x 2e-7 s, 1000
points at the dump's positions and radius, velocity, angular velocity,
force and contact count equal to the dump's, bit for bit; --surfaces puts
every surface point on its sphere (|r - R| < 1e-12 R). The particles
fall freely so far, g t^2 / 2 (the sub-models' physics is checked
elsewhere)."""
import glob
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

import engines

work, _, c = engines.start()
ROOT = engines.ROOT
DECK = os.path.join(ROOT, "examples", "lammps_adhesive_settling", "in.lammps_adhesive_settling")
PARAVIEW = os.path.join(ROOT, "tests", "regression", "check_paraview.py")
d, _ = engines.run("lammps", DECK, work, ranks=2, variables={"steps": 20000}, tag="example")
dumps = sorted(glob.glob(os.path.join(d, "post", "dump*.adh")))
c.true(len(dumps) == 2, "the example wrote its dumps at steps 0 and 20000 (%d files)" % len(dumps))
p = subprocess.run([sys.executable, os.path.join(ROOT, "tools", "dump2vtk.py"), "post/dump*.adh", "-o", "pv",
                    "--surfaces", "6", "--dt", "2e-7"], cwd=d, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                   text=True)
c.true(p.returncode == 0, "dump2vtk converts the LAMMPS dumps (%s)" % p.stdout.strip().replace("\n", "; "))


def pvd(path):
    return [(float(e.get("timestep")), os.path.join(os.path.dirname(path), e.get("file")))
            for e in ET.parse(path).getroot().iter("DataSet")]


def vtk_python():
    for exe in (sys.executable, "/usr/bin/python3"):
        if os.path.exists(exe) and subprocess.run([exe, "-c", "import vtkmodules.vtkIOXML"],
                                                  stderr=subprocess.DEVNULL).returncode == 0:
            return exe
    return None


def snapshot(path):
    """(step, columns, rows) of a one-snapshot LAMMPS dump, read here."""
    lines = open(path).read().split("\n")
    n = int(lines[3])
    return int(lines[1]), lines[8].split()[2:], [[float(v) for v in l.split()] for l in lines[9:9 + n]]


series = pvd(os.path.join(d, "pv", "particles.pvd"))
surfaces = pvd(os.path.join(d, "pv", "particles_surface.pvd"))
c.true([t for t, _ in series] == [0.0, 20000 * 2e-7], "particles.pvd: times 0 and 0.004 s (%s)"
       % [t for t, _ in series])
vtkpy = vtk_python()
c.true(vtkpy is not None, "VTK's Python bindings found (python3-vtk9)")
files = [f for _, f in series] + [f for _, f in surfaces]
out = subprocess.run([vtkpy, PARAVIEW, "--vtk-read"] + files, stdout=subprocess.PIPE, text=True)
got = json.loads(out.stdout)
zmean = []
for (t, f), dump, (_, fs) in zip(series, dumps, surfaces):
    step, cols, rows = snapshot(dump)
    rows.sort(key=lambda r: r[cols.index("id")])
    g = got[f]
    ids = g["point"]["id"][2]
    order = sorted(range(len(ids)), key=lambda k: ids[k])
    same = g["npoints"] == len(rows) == 1000
    for name, comps in (("radius", ["radius"]), ("v", ["vx", "vy", "vz"]), ("omega", ["omegax", "omegay", "omegaz"]),
                        ("f", ["fx", "fy", "fz"]), ("c_nc", ["c_nc"])):
        m, _, vals = g["point"][name]
        for k, r in zip(order, rows):
            same = same and all(vals[m * k + j] == r[cols.index(comp)] for j, comp in enumerate(comps))
    same = same and all(g["points"][k] == [r[cols.index(x)] for x in ("x", "y", "z")] for k, r in zip(order, rows))
    c.true(same, "step %d: 1000 points, positions, radius, v, omega, f, c_nc equal to the dump's" % step)
    # the surfaces: every point on its sphere (the spheres in the dump's order)
    _, _, unsorted = snapshot(dump)
    pts = got[fs]["points"]
    per = len(pts) // len(unsorted)
    worst = 0.0
    for k, q in enumerate(pts):
        r = unsorted[k // per]
        x, y, z, R = (r[cols.index(n)] for n in ("x", "y", "z", "radius"))
        worst = max(worst, abs(((q[0] - x) ** 2 + (q[1] - y) ** 2 + (q[2] - z) ** 2) ** 0.5 - R) / R)
    c.true(len(pts) == per * len(unsorted) and worst < 1e-12,
           "step %d: %d surface points, %d per sphere, each within %.2g R of its sphere (tol 1e-12)"
           % (step, len(pts), per, worst))
    zmean.append(sum(r[cols.index("z")] for r in rows) / len(rows))
fall = 0.5 * 9.81 * (20000 * 2e-7) ** 2
c.rel(zmean[0] - zmean[1], fall, 0.02, "the powder falls freely (no contacts yet): the mean height drops g t^2/2")
c.finish()
