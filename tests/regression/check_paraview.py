#!/usr/bin/env python3
"""Regression: ParaView output (tools/dump2vtk.py). Runs inputs/paraview
(18 spheres, 1 rank; 12 superquadrics of two shapes, 2 ranks; both with
hertz_elliptic and contactPatch on, dumps every 100 of 300 steps), converts
the dumps, and reads every written file back with VTK's own XML reader
(Debian python3-vtk9, run with an interpreter that has it: this one or
/usr/bin/python3):
- each .pvd lists one file per dump snapshot, with time = step x dt;
- particles: the point count and field names, and every value (positions,
  id, type, radius, velocities, forces, angular velocities, quaternion,
  shape, blockiness) equal to the dump's, bit for bit (binary and --ascii);
- contacts: one line per dump row from particle i to particle j, id1, id2,
  force and the contact patch (a, b, axis, elastic force, friction load,
  formed flag, at the history values the log names) equal to the dump's;
  force_magnitude = |force|;
- superquadric glyphs as doc/paraview.md draws them (VTK's vtkTensorGlyph
  with sq_tensor, eigenvalues not extracted, scale factor 2, on
  vtkSuperquadricSource with ParaView's defaults, toroidal off, Theta
  Roundness 2/blockiness2, Phi Roundness 2/blockiness1): every glyph point
  lies on its particle's surface (LIGGGHTS' shape function, the rotation
  applied here as q v q*), |f| < 1e-5 (glyph points are single precision);
- --surfaces: every surface point lies on its particle's surface
  (superquadrics |f| < 1e-9, spheres |r - R| < 1e-12 R);
- a dump local without --log or --compute is refused with exit code 2;
- this build's `dump custom/vtk` (plugin/liggghts/io), legacy .vtk and XML .vtp, on
  1 and 2 ranks: the same points and arrays as the converter's particle
  files (without the glyph tensor), bit for bit.
Usage: check_paraview.py WORKDIR"""
import json
import math
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))


def vtk_read(paths, glyph):
    """Runs in an interpreter with VTK: prints the content of each .vtp (or
    legacy .vtk) as JSON; with glyph, also the points of the superquadric
    tensor glyphs."""
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    from vtkmodules.vtkIOLegacy import vtkPolyDataReader
    out = {}
    for p in paths:
        if p.endswith(".vtk"):
            r = vtkPolyDataReader()
            r.ReadAllFieldsOn()
        else:
            r = vtkXMLPolyDataReader()
        r.SetFileName(p)
        r.Update()
        o = r.GetOutput()
        if r.GetErrorCode() or o is None:
            out[p] = None
            continue

        def arrays(data):
            res = {}
            for k in range(data.GetNumberOfArrays()):
                a = data.GetAbstractArray(k)
                n, m = a.GetNumberOfTuples(), a.GetNumberOfComponents()
                res[a.GetName()] = [m, a.GetDataTypeAsString(), [a.GetVariantValue(j).ToDouble() for j in range(n * m)]]
            return res

        pts = o.GetPoints()
        lines = []
        if o.GetNumberOfLines():
            ids = o.GetLines()
            ids.InitTraversal()
            from vtkmodules.vtkCommonCore import vtkIdList
            lst = vtkIdList()
            while ids.GetNextCell(lst):
                lines.append([lst.GetId(j) for j in range(lst.GetNumberOfIds())])
        out[p] = {"npoints": o.GetNumberOfPoints(), "nverts": o.GetNumberOfVerts(), "nlines": o.GetNumberOfLines(),
                  "npolys": o.GetNumberOfPolys(),
                  "points": [list(pts.GetPoint(j)) for j in range(o.GetNumberOfPoints())] if pts else [],
                  "lines": lines, "point": arrays(o.GetPointData()), "cell": arrays(o.GetCellData()),
                  "field": arrays(o.GetFieldData())}
        if glyph and o.GetPointData().GetArray("sq_tensor"):
            from vtkmodules.vtkCommonDataModel import vtkPolyData
            from vtkmodules.vtkCommonCore import vtkPoints, vtkDoubleArray
            from vtkmodules.vtkFiltersCore import vtkTensorGlyph
            from vtkmodules.vtkFiltersSources import vtkSuperquadricSource
            bl = o.GetPointData().GetArray("blockiness")
            T = o.GetPointData().GetArray("sq_tensor")
            glyphs = []
            for j in range(o.GetNumberOfPoints()):
                # one particle at a time: its own roundness (ParaView: one
                # Tensor Glyph per blockiness, after a Threshold)
                n1, n2 = bl.GetTuple2(j)
                pd = vtkPolyData()
                pp = vtkPoints()
                pp.InsertNextPoint(o.GetPoint(j))
                pd.SetPoints(pp)
                t = vtkDoubleArray()
                t.SetNumberOfComponents(9)
                t.SetName("sq_tensor")
                t.InsertNextTuple(T.GetTuple9(j))
                pd.GetPointData().SetTensors(t)
                s = vtkSuperquadricSource()   # ParaView's defaults: Size 0.5, axis of symmetry y
                s.SetToroidal(0)
                s.SetThetaRoundness(2.0 / n2)
                s.SetPhiRoundness(2.0 / n1)
                g = vtkTensorGlyph()
                g.SetInputData(pd)
                g.SetSourceConnection(s.GetOutputPort())
                g.ExtractEigenvaluesOff()
                g.SetScaleFactor(2.0)
                g.ColorGlyphsOff()
                g.Update()
                gp = g.GetOutput().GetPoints()
                glyphs.append([list(gp.GetPoint(k)) for k in range(gp.GetNumberOfPoints())])
            out[p]["glyphs"] = glyphs
    json.dump(out, sys.stdout)


if len(sys.argv) > 1 and sys.argv[1] in ("--vtk-read", "--vtk-read-glyph"):
    vtk_read(sys.argv[2:], sys.argv[1] == "--vtk-read-glyph")
    sys.exit(0)

from regress import ROOT, run, start  # noqa: E402

work, _, c = start()
TOOL = os.path.join(ROOT, "tools", "dump2vtk.py")


def vtk_python():
    """An interpreter with VTK's Python bindings (python3-vtk9 serves the
    system /usr/bin/python3)."""
    for exe in (sys.executable, "/usr/bin/python3"):
        if exe and os.path.exists(exe) and subprocess.run(
                [exe, "-c", "import vtkmodules.vtkIOXML"], stdout=subprocess.DEVNULL,
                stderr=subprocess.DEVNULL).returncode == 0:
            return exe
    return None


VTKPY = vtk_python()
if VTKPY is None:
    c.true(False, "VTK's Python bindings found (Debian python3-vtk9 for /usr/bin/python3; plugin/setup.sh installs it)")
    c.finish()


def read_back(paths, glyph=False):
    p = subprocess.run([VTKPY, os.path.abspath(__file__), "--vtk-read-glyph" if glyph else "--vtk-read"] + paths,
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if p.returncode != 0:
        print(p.stderr[-3000:])
        raise SystemExit("FAIL reading the VTK files back with %s" % VTKPY)
    return json.loads(p.stdout)


def dump_snapshots(path):
    """{step: (columns, rows of floats)} of a LIGGGHTS dump (one or many
    snapshots), parsed here independently of the converter."""
    out = {}
    text = open(path).read()
    for block in text.split("ITEM: TIMESTEP\n")[1:]:
        lines = block.strip("\n").split("\n")
        step = int(lines[0])
        n = int(lines[2])
        columns = lines[7].split()[2:]
        out[step] = (columns, [[float(v) for v in l.split()] for l in lines[8:8 + n]])
    return out


def convert(d, files, extra=()):
    cmd = [sys.executable, TOOL] + files + ["--log", os.path.join(d, "log.run"), "-o", os.path.join(d, "pv")] + list(extra)
    p = subprocess.run(cmd, cwd=d, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(p.stdout.strip())
    if p.returncode != 0:
        raise SystemExit("FAIL %s exited with %d" % (" ".join(cmd), p.returncode))
    return p.stdout


def pvd(path):
    root = ET.parse(path).getroot()
    return [(float(e.get("timestep")), os.path.join(os.path.dirname(path), e.get("file")))
            for e in root.iter("DataSet")]


def rotate(q, v):
    """q v q* for a unit quaternion q = (w, i, j, k)."""
    w, x, y, z = q
    # t = 2 (q_vec x v); v' = v + w t + q_vec x t
    tx, ty, tz = 2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0])
    return (v[0] + w * tx + (y * tz - z * ty), v[1] + w * ty + (z * tx - x * tz), v[2] + w * tz + (x * ty - y * tx))


def shape_f(p, centre, q, shape, n1, n2):
    """LIGGGHTS' superquadric shape function at world point p."""
    d = (p[0] - centre[0], p[1] - centre[1], p[2] - centre[2])
    loc = rotate((q[0], -q[1], -q[2], -q[3]), d)
    a, b, cc = shape
    return (abs(loc[0] / a) ** n2 + abs(loc[1] / b) ** n2) ** (n1 / n2) + abs(loc[2] / cc) ** n1 - 1.0


VECTOR = {"v": ("vx", "vy", "vz"), "f": ("fx", "fy", "fz"), "omega": ("omegax", "omegay", "omegaz"),
          "quat": ("quat1", "quat2", "quat3", "quat4"), "shape": ("shapex", "shapey", "shapez"),
          "blockiness": ("blockiness1", "blockiness2")}


def check_case(name, deck, ranks, sq):
    d = os.path.join(work, name)
    log = run("paraview/" + deck, os.path.join(d, "probe"), variables={"steps": 0}, tag="probe")
    m = re.findall(r"contact patch in history values (\d+) to (\d+) \(pair\)", log)
    c.true(len(m) == 1 and int(m[0][1]) - int(m[0][0]) == 7, "%s: the log names the 8 patch history values %s" % (name, m))
    first, last = int(m[0][0]), int(m[0][1])
    ncols = 12 + last + 1      # pos (6), id (3), force (3), history up to the patch's end
    cols = " ".join("c_cp[%d]" % k for k in range(1, ncols + 1))
    fmt = '"%s"' % " ".join(["%.17g"] * ncols)
    log = run("paraview/" + deck, d, ranks=ranks, variables={"cols": cols, "fmt": fmt}, tag="run")
    dt = float(re.search(r"^timestep\s+(\S+)", log, re.M).group(1))
    ext = "sq" if sq else "sph"
    atoms = {}
    for f in os.listdir(os.path.join(d, "post")):
        if f.endswith("." + ext):
            atoms.update(dump_snapshots(os.path.join(d, "post", f)))
    local = dump_snapshots(os.path.join(d, "post", "contacts.local"))
    out = convert(d, ["post/dump*.%s" % ext, "post/contacts.local"], ["--surfaces", "8"])
    c.true(all(s in out for s in ("particles.pvd", "particles_surface.pvd", "contacts.pvd")),
           "%s: the converter names the three .pvd files it wrote" % name)

    # --- particles
    series = pvd(os.path.join(d, "pv", "particles.pvd"))
    steps = sorted(atoms)
    c.true(len(series) == len(steps) == 4 and all(abs(t - s * dt) <= 1e-12 * max(s * dt, 1e-30)
                                                  for (t, _), s in zip(series, steps)),
           "%s: particles.pvd lists %d snapshots at time = step x dt (dt %g)" % (name, len(series), dt))
    files = [f for _, f in series]
    got = read_back(files, glyph=sq)
    want_names = {"id", "type", "v", "f", "sq_tensor", "quat", "shape", "blockiness"} if sq else \
        {"id", "type", "radius", "v", "f", "omega"}
    ok_count = ok_names = ok_values = True
    worst_glyph, nglyph = 0.0, 0
    for (t, f), s in zip(series, steps):
        columns, rows = atoms[s]
        g = got[f]
        if g is None:
            c.true(False, "%s: VTK reads %s" % (name, f))
            continue
        col = {k: j for j, k in enumerate(columns)}
        ok_count &= g["npoints"] == g["nverts"] == len(rows)
        ok_names &= set(g["point"]) == want_names
        ok_values &= all(g["points"][r] == [rows[r][col["x"]], rows[r][col["y"]], rows[r][col["z"]]] for r in range(len(rows)))
        for field, (m, vtype, vals) in g["point"].items():
            if field == "sq_tensor":
                continue
            src = VECTOR.get(field, (field,))
            ok_values &= m == len(src) and all(vals[m * r + k] == rows[r][col[src[k]]] for r in range(len(rows))
                                               for k in range(m))
            if field in ("id", "type"):
                ok_values &= vtype in ("long long", "long", "int", "idtype")
        ok_values &= g["field"]["TimeStep"][2] == [s] and g["field"]["TimeValue"][2] == [s * dt]
        if sq:
            for r, pts in enumerate(g["glyphs"]):
                row = rows[r]
                centre = [row[col[k]] for k in ("x", "y", "z")]
                q = [row[col[k]] for k in VECTOR["quat"]]
                shape = [row[col[k]] for k in VECTOR["shape"]]
                n1, n2 = row[col["blockiness1"]], row[col["blockiness2"]]
                nglyph += len(pts)
                worst_glyph = max([worst_glyph] + [abs(shape_f(p, centre, q, shape, n1, n2)) for p in pts])
    c.true(ok_count, "%s: every snapshot has as many points (and vertices) as the dump has atoms (%d)"
           % (name, len(atoms[steps[0]][1])))
    c.true(ok_names, "%s: point data %s" % (name, " ".join(sorted(want_names))))
    c.true(ok_values, "%s: positions, id, type and every field equal to the dump's, bit for bit; TimeStep, TimeValue" % name)
    if sq:
        c.true(nglyph > 1000 and worst_glyph < 1e-5,
               "%s: Tensor Glyph recipe: %d glyph points on their particle's surface, worst |f| %.3g "
               "(tol 1e-5: VTK writes glyph points in single precision)"
               % (name, nglyph, worst_glyph))

    # --- surfaces
    sseries = pvd(os.path.join(d, "pv", "particles_surface.pvd"))
    sgot = read_back([sseries[-1][1]])[sseries[-1][1]]
    columns, rows = atoms[steps[-1]]
    col = {k: j for j, k in enumerate(columns)}
    byid = {int(r[col["id"]]): r for r in rows}
    ids = sgot["point"]["id"][2]
    worst = 0.0
    for p, i in zip(sgot["points"], ids):
        row = byid[int(i)]
        centre = [row[col[k]] for k in ("x", "y", "z")]
        if sq:
            err = abs(shape_f(p, centre, [row[col[k]] for k in VECTOR["quat"]], [row[col[k]] for k in VECTOR["shape"]],
                              row[col["blockiness1"]], row[col["blockiness2"]]))
        else:
            err = abs(math.dist(p, centre) / row[col["radius"]] - 1.0)
        worst = max(worst, err)
    tol = 1e-9 if sq else 1e-12
    c.true(len(ids) > 50 * len(rows) and sgot["npolys"] > 50 * len(rows) and worst < tol,
           "%s: --surfaces: %d surface points of %d particles on their surfaces, worst %.3g (tol %g)"
           % (name, len(ids), len(rows), worst, tol))

    # --- contacts
    series = pvd(os.path.join(d, "pv", "contacts.pvd"))
    lsteps = sorted(local)
    got = read_back([f for _, f in series])
    ok_count = ok_lines = ok_values = True
    total = 0
    for (t, f), s in zip(series, lsteps):
        columns, rows = local[s]
        g = got[f]
        total += len(rows)
        ok_count &= g["nlines"] == len(rows) and g["npoints"] == 2 * len(rows)
        for r, row in enumerate(rows):
            ln = g["lines"][r]
            ok_lines &= len(ln) == 2 and g["points"][ln[0]] == row[0:3] and g["points"][ln[1]] == row[3:6]
        cell = g["cell"]
        P = 12 + first
        for r, row in enumerate(rows):
            ok_values &= cell["id1"][2][r] == row[6] and cell["id2"][2][r] == row[7]
            ok_values &= cell["force"][2][3 * r:3 * r + 3] == row[9:12]
            ok_values &= abs(cell["force_magnitude"][2][r] - math.sqrt(sum(v * v for v in row[9:12]))) <= \
                1e-15 * cell["force_magnitude"][2][r]
            ok_values &= cell["history"][2][(last + 1) * r:(last + 1) * (r + 1)] == row[12:12 + last + 1]
            ok_values &= [cell["patch_a"][2][r], cell["patch_b"][2][r]] == row[P:P + 2]
            ok_values &= cell["patch_axis"][2][3 * r:3 * r + 3] == row[P + 2:P + 5]
            ok_values &= [cell["patch_F"][2][r], cell["patch_Fbound"][2][r], cell["patch_formed"][2][r]] == row[P + 5:P + 8]
    c.true(len(series) == len(lsteps) == 4 and ok_count and total > 20,
           "%s: contacts.pvd: %d snapshots, one line per contact (%d contacts in all)" % (name, len(series), total))
    c.true(ok_lines, "%s: each line runs from particle i to particle j (the dump's pos)" % name)
    c.true(ok_values, "%s: id1, id2, force, |force|, history and the contact patch (a, b, axis, F, friction load, "
                      "formed) equal to the dump's" % name)
    # --- this build's dump custom/vtk (the same columns, 1 or 2 ranks): the
    # converter's particles without the glyph tensor, bit for bit, legacy
    # (.vtk) and XML (.vtp)
    for kind, pattern in (("legacy VTK", "legacy%d.vtk"), ("VTK XML", "xml%d.vtp")):
        mine = [os.path.join(d, "post", pattern % st) for st in steps]
        got_mine = read_back(mine)
        got = read_back(files)
        same = True
        for f, m in zip(files, mine):
            want, have = got[f], got_mine[m]
            if have is None:
                same = False
                continue
            arrays = {k: v[2] for k, v in want["point"].items() if k != "sq_tensor"}
            same &= have["points"] == want["points"] and have["npoints"] == have["nverts"] == want["npoints"]
            same &= {k: v[2] for k, v in have["point"].items()} == arrays
        c.true(same, "%s: dump custom/vtk (%s, %d snapshots, %d rank%s) holds the converter's points and arrays %s, "
               "bit for bit" % (name, kind, len(mine), ranks, "s" if ranks > 1 else "",
                                ", ".join(sorted(k for k in want_names if k != "sq_tensor"))))
    if sq:
        axes = [cell["patch_axis"][2][3 * r:3 * r + 3] for r in range(len(rows))]
        c.true(any(abs(a[1]) > 0.1 and abs(a[2]) > 0.1 for a in axes),
               "%s: the ellipsoid contacts have tilted major axes (a nontrivial patch is carried)" % name)
    return d


d = check_case("spheres", "in.paraview", 1, False)
# the same data as ASCII: the same values
convert(d, ["post/dump*.sph", "post/contacts.local"], ["--ascii", "-o", os.path.join(d, "pv_ascii")])
a = read_back([os.path.join(d, "pv", "particles", "particles_000000300.vtp"),
               os.path.join(d, "pv_ascii", "particles", "particles_000000300.vtp"),
               os.path.join(d, "pv", "contacts", "contacts_000000300.vtp"),
               os.path.join(d, "pv_ascii", "contacts", "contacts_000000300.vtp")])
vals = list(a.values())
c.true(vals[0] == vals[1] and vals[2] == vals[3], "spheres: --ascii files hold the same points and values as binary")
p = subprocess.run([sys.executable, TOOL, "post/contacts.local", "-o", "pv_nolog"], cwd=d, stdout=subprocess.PIPE,
                   stderr=subprocess.STDOUT, text=True)
c.true(p.returncode == 2 and "--log or --compute" in p.stdout,
       "a dump local without --log or --compute: exit 2 naming them (%s)" % p.stdout.strip()[:120])
check_case("superquadrics", "in.paraview_superquadric", 2, True)
c.finish()
