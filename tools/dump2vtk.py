#!/usr/bin/env python3
"""dump2vtk.py: LIGGGHTS text dumps to VTK XML files that ParaView opens.

Reads
  - `dump custom` files (ITEM: ATOMS ...): particles, spheres or
    superquadrics, with any per-atom columns;
  - `dump local` files of `compute pair/gran/local` or `wall/gran/local`
    (ITEM: ENTRIES c_ID[1] ...): the contact network, with the contact
    patch of the project's normal models where `contactPatch on` stores it;
and writes, per dump snapshot, a VTK XML PolyData file (.vtp: particles as
points with point data; contacts as lines with cell data), plus one .pvd
collection per series for the time series. Standard library only: VTK is
not needed to write the files.

Usage:
  dump2vtk.py [options] FILE [FILE ...]
    FILE: dump files or quoted glob patterns ('post/dump*.sq'); each file
    may hold one or many snapshots; snapshots of the same step from several
    files (per-processor dumps) are joined. The kind of each file is read
    from its header.
  -o DIR            output folder (default: paraview)
  --log FILE        the LIGGGHTS log of the run: gives the keywords of the
                    compute behind a dump local (`compute ID all
                    pair/gran/local pos id force history`), where the
                    contact patch sits in the history values (the line
                    `contact patch in history values A to B (pair)`) and
                    the time step (for the times in the .pvd files)
  --compute "STYLE KEYWORDS"  the compute's style and keywords as in the
                    deck, e.g. "pair/gran/local pos id force history"
                    (instead of reading them from --log)
  --patch A         first history value of the contact patch (0-based, as
                    the log prints it; instead of reading it from --log)
  --dt DT           time step [s]: .pvd times are step * DT (default: from
                    --log, else the step number)
  --surfaces [RES]  also write each particle's surface as polygons
                    (superquadric or sphere; RES latitude divisions, default
                    12): <name>_surface.pvd, exact shapes without glyphs
  --name NAME       series name for the particle files (default: particles;
                    contacts are "contacts", wall contacts "wall_contacts")
  --ascii           write ASCII data instead of compressed binary

Fields written
  particles: points at x y z (or xu yu zu, or xs ys zs scaled by the box);
    vectors from column triples (vx vy vz -> v, fx fy fz -> f, omegax.. ->
    omega, tqx.. -> tq, angmomx.. -> angmom, mux.. -> mu, ix.. -> image),
    shapex shapey shapez -> shape (semi-axes a, b, c [m]), blockiness1
    blockiness2 -> blockiness (n1, n2), quat1..quat4 -> quat (w, i, j, k;
    body-to-world rotation of LIGGGHTS' superquadrics), every other column
    a scalar of its own name (id, type as integers). With shape and quat:
    sq_tensor (9 components: the glyph axes a R e_x, c R e_z, -b R e_y, one
    after the other) for ParaView's Tensor Glyph filter with a Superquadric
    glyph (doc/paraview.md).
  contacts: one line per contact from particle i to particle j (wall
    contacts: from the particle to the contact point), cell data id1 id2
    periodic (pairs) or mesh_id triangle_id atom_id (walls), force (on
    particle i), force_magnitude, force_normal, force_tangential, torque,
    torque_normal, torque_tangential, contactArea, delta, contactPoint,
    ms_id, heatFlux as the compute has them, the history values as one
    array `history`, and the contact patch as patch_a, patch_b [m],
    patch_axis (unit major-axis direction), patch_F (elastic normal force
    [N]), patch_Fbound (normal force that bounds friction [N]),
    patch_formed (1/0). Columns of other computes or fixes: scalars of
    their own name. Without pos, the line ends come from a particle dump
    of the same step given with them (by atom id)."""
import argparse
import base64
import glob
import math
import os
import re
import struct
import sys
import zlib
from xml.sax.saxutils import quoteattr

VECTORS = [(("vx", "vy", "vz"), "v"), (("fx", "fy", "fz"), "f"), (("omegax", "omegay", "omegaz"), "omega"),
           (("tqx", "tqy", "tqz"), "tq"), (("angmomx", "angmomy", "angmomz"), "angmom"),
           (("mux", "muy", "muz"), "mu"), (("ix", "iy", "iz"), "image"),
           (("shapex", "shapey", "shapez"), "shape"), (("blockiness1", "blockiness2"), "blockiness"),
           (("roundness1", "roundness2"), "blockiness"), (("quat1", "quat2", "quat3", "quat4"), "quat")]
INTEGER_COLUMNS = {"id", "type", "mol", "proc", "procp1", "ix", "iy", "iz"}
POSITIONS = [("x", "y", "z"), ("xu", "yu", "zu"), ("xs", "ys", "zs"), ("xsu", "ysu", "zsu")]
# compute pair/gran/local and wall/gran/local: the keywords in output order
# (LIGGGHTS 3.8 compute_pair_gran_local.cpp) with their column counts;
# history is sized from the dump, heatFlux is always the last column
CPGL_ORDER = [("pos", 6), ("vel", 6), ("id", 3), ("force", 3), ("force_normal", 3), ("force_tangential", 3),
              ("torque", 3), ("torque_normal", 3), ("torque_tangential", 3), ("history", None),
              ("contactArea", 1), ("delta", 1), ("contactPoint", 3), ("ms_id", 2), ("heatFlux", 1)]
CPGL_DEFAULT = ["pos", "vel", "id", "force", "torque", "history", "contactArea"]
PATCH = [("patch_a", 1), ("patch_b", 1), ("patch_axis", 3), ("patch_F", 1), ("patch_Fbound", 1),
         ("patch_formed", 1)]
PATCH_N = 8


class DumpError(Exception):
    pass


# ---------------------------------------------------------------- reading

def expand(patterns):
    files = []
    for p in patterns:
        hits = sorted(glob.glob(p)) if any(ch in p for ch in "*?[") else [p]
        if not hits:
            raise DumpError("no file matches %s" % p)
        for h in hits:
            if not os.path.isfile(h):
                raise DumpError("%s is not a file" % h)
            files.append(h)
    return files


def open_text(path):
    if path.endswith(".gz"):
        import gzip
        return gzip.open(path, "rt")
    return open(path)


def snapshots(path):
    """Yields (step, label, box, columns, rows) for each snapshot of a
    LIGGGHTS dump file; label is ATOMS for dump custom, the dump local label
    (ENTRIES) otherwise; rows are lists of strings."""
    with open_text(path) as f:
        lines = iter(f)
        lineno = 0

        def nxt():
            nonlocal lineno
            lineno += 1
            try:
                return next(lines)
            except StopIteration:
                raise DumpError("%s: ends inside a snapshot (line %d)" % (path, lineno))

        step = n = label = None
        box = None
        for line in lines:
            lineno += 1
            line = line.strip()
            if not line:
                continue
            if not line.startswith("ITEM:"):
                raise DumpError("%s:%d: expected an ITEM: line, got %r" % (path, lineno, line[:60]))
            item = line[5:].strip()
            if item == "TIMESTEP":
                step = int(nxt().split()[0])
            elif item == "TIME":
                nxt()
            elif item.startswith("NUMBER OF "):
                label = item[len("NUMBER OF "):].strip()
                n = int(nxt().split()[0])
            elif item.startswith("BOX BOUNDS"):
                box = []
                for _ in range(3):
                    box.append([float(v) for v in nxt().split()[:2]])
            elif label is not None and item.split()[0] == label:
                if step is None or n is None:
                    raise DumpError("%s:%d: a column line before TIMESTEP and NUMBER OF" % (path, lineno))
                columns = item.split()[1:]
                rows = []
                for _ in range(n):
                    r = nxt().split()
                    if len(r) != len(columns):
                        raise DumpError("%s:%d: %d values for %d columns" % (path, lineno, len(r), len(columns)))
                    rows.append(r)
                yield step, label, box, columns, rows
                step = n = label = None
            else:
                raise DumpError("%s:%d: unknown item %r" % (path, lineno, item))


def collect(files):
    """{"atoms": {step: snap}, "local": {step: snap}}; snap = (box, columns,
    rows), rows of per-processor files of one step joined."""
    out = {"atoms": {}, "local": {}}
    for path in files:
        for step, label, box, columns, rows in snapshots(path):
            kind = "atoms" if label == "ATOMS" else "local"
            seen = out[kind].get(step)
            if seen is None:
                out[kind][step] = (box, columns, rows, path)
            elif seen[1] != columns:
                raise DumpError("step %d appears in %s and %s with different columns: convert them separately"
                                % (step, seen[3], path))
            else:
                seen[2].extend(rows)
    return out


def parse_log(path):
    """(computes {ID: (style, keywords)}, patch {kind: first}, dt) from a
    LIGGGHTS log."""
    computes, patch, dt = {}, {}, None
    for line in open(path, errors="replace"):
        w = line.split("#")[0].split()
        if len(w) >= 4 and w[0] == "compute" and w[3] in ("pair/gran/local", "wall/gran/local"):
            computes[w[1]] = (w[3], w[4:])
        elif len(w) >= 2 and w[0] == "timestep":
            try:
                dt = float(w[1])
            except ValueError:
                pass
        m = re.search(r"contact patch in history values (\d+) to (\d+) \((pair|wall)\)", line)
        if m:
            first, last = int(m.group(1)), int(m.group(2))
            if last - first + 1 != PATCH_N:
                raise DumpError("%s: the contact patch spans %d history values, expected %d"
                                % (path, last - first + 1, PATCH_N))
            patch[m.group(3)] = first
    return computes, patch, dt


# ---------------------------------------------------------------- fields

def number(s):
    try:
        return float(s)
    except ValueError:
        raise DumpError("not a number: %r" % s)


def column_values(rows, k, integer=False):
    if integer:
        try:
            return [int(r[k]) for r in rows]
        except ValueError:
            pass
    return [number(r[k]) for r in rows]


def quat_to_matrix(w, i, j, k):
    """LIGGGHTS' MathExtraLiggghtsNonspherical::quat_to_mat: body to world."""
    return ((w * w + i * i - j * j - k * k, 2 * (i * j - k * w), 2 * (j * w + i * k)),
            (2 * (i * j + k * w), w * w - i * i + j * j - k * k, 2 * (j * k - i * w)),
            (2 * (i * k - j * w), 2 * (j * k + i * w), w * w - i * i - j * j + k * k))


def particle_fields(box, columns, rows):
    """(points [(x, y, z)], [(name, ncomp, vtktype, flat values)]) of a
    dump custom snapshot."""
    idx = {c: k for k, c in enumerate(columns)}
    pos = next((p for p in POSITIONS if all(c in idx for c in p)), None)
    if pos is None:
        raise DumpError("no position columns (x y z, xu yu zu or xs ys zs) in %s" % " ".join(columns))
    cols = [column_values(rows, idx[c]) for c in pos]
    if pos[0].startswith("xs"):
        if box is None:
            raise DumpError("scaled positions without box bounds")
        cols = [[lo + v * (hi - lo) for v in col] for col, (lo, hi) in zip(cols, box)]
    points = list(zip(*cols))
    used = set(pos)
    fields = []
    for c in columns:   # in the dump's order; a vector where its first column stands
        if c in used:
            continue
        group = next(((names, vname) for names, vname in VECTORS
                      if c == names[0] and all(x in idx and x not in used for x in names)), None)
        if group:
            names, vname = group
            integer = names[0] in INTEGER_COLUMNS
            vals = [column_values(rows, idx[x], integer) for x in names]
            fields.append((vname, len(names), vtk_type(vals), [v for t in zip(*vals) for v in t]))
            used.update(names)
            continue
        vals = column_values(rows, idx[c], c in INTEGER_COLUMNS)
        fields.append((c, 1, vtk_type([vals]), vals))
        used.add(c)
    by = {f[0]: f for f in fields}
    if "shape" in by:
        sh = by["shape"][3]
        q = by["quat"][3] if "quat" in by else [1.0, 0.0, 0.0, 0.0] * len(rows)
        tensor = []
        for n in range(len(rows)):
            a, b, c = sh[3 * n:3 * n + 3]
            w, i, j, k = q[4 * n:4 * n + 4]
            s = math.sqrt(w * w + i * i + j * j + k * k) or 1.0
            R = quat_to_matrix(w / s, i / s, j / s, k / s)
            # glyph x along body x (a), glyph y (the superquadric source's
            # axis of symmetry) along body z (c), glyph z along -body y (b)
            tensor += [a * R[0][0], a * R[1][0], a * R[2][0],
                       c * R[0][2], c * R[1][2], c * R[2][2],
                       -b * R[0][1], -b * R[1][1], -b * R[2][1]]
        fields.append(("sq_tensor", 9, "Float64", tensor))
    return points, fields


def vtk_type(cols):
    return "Int64" if all(isinstance(v, int) for col in cols for v in col) else "Float64"


def local_layout(style, keywords, ncols):
    """[(keyword, first column (0-based), count)] of a compute
    pair/gran/local or wall/gran/local with ncols columns in all."""
    kws = set(keywords) - {"verbose"} if keywords else set(CPGL_DEFAULT)
    unknown = kws - {k for k, _ in CPGL_ORDER}
    if unknown:
        raise DumpError("unknown %s keyword(s): %s" % (style, " ".join(sorted(unknown))))
    fixed = sum(n for k, n in CPGL_ORDER if k in kws and n is not None)
    layout, col = [], 0
    for k, n in CPGL_ORDER:
        if k not in kws or k == "heatFlux":
            continue
        if n is None:
            n = ncols - fixed
            if n < 1:
                raise DumpError("%s with %s: %d columns leave no history values" % (style, " ".join(keywords), ncols))
        layout.append((k, col, n))
        col += n
    if "heatFlux" in kws:
        layout.append(("heatFlux", ncols - 1, 1))
        col += 1
    if col != ncols:
        raise DumpError("%s %s has %d columns, the dump shows %d: dump every column of the compute"
                        % (style, " ".join(sorted(kws)), col, ncols))
    return layout


def contact_fields(columns, rows, computes, patch, atoms_by_step_ids):
    """(kind, points, [(name, ncomp, vtktype, flat values)] cell data) of a
    dump local snapshot; patch: {"pair"|"wall": first history value of the
    contact patch}."""
    parsed = []
    cid = None
    for c in columns:
        m = re.match(r"^c_([^\[\]]+)(?:\[(\d+)\])?$", c)
        if m and m.group(1) in computes:
            if cid not in (None, m.group(1)):
                raise DumpError("a dump local of two contact computes (%s, %s): dump them separately" % (cid, m.group(1)))
            cid = m.group(1)
            parsed.append((c, int(m.group(2) or 1) - 1))
        else:
            parsed.append((c, None))
    if cid is None:
        raise DumpError("no column of a compute pair/gran/local or wall/gran/local in %s (give --log or --compute)"
                        % " ".join(columns))
    style, keywords = computes[cid]
    kind = "wall" if style.startswith("wall") else "pair"
    patch_first = patch.get(kind)
    present = {k: n for n, (c, k) in enumerate(parsed) if k is not None}
    ncols = max(present) + 1
    layout = local_layout(style, keywords, ncols)
    missing = [k for k in range(ncols) if k not in present]
    if missing:
        raise DumpError("the dump local lacks columns %s of compute %s: dump all of them"
                        % (" ".join("c_%s[%d]" % (cid, k + 1) for k in missing), cid))
    ncont = len(rows)

    def block(first, count, integer=False):
        cols = [column_values(rows, present[first + j], integer) for j in range(count)]
        return cols

    fields, points = [], None
    by = {k: (first, n) for k, first, n in layout}
    if "pos" in by:
        p = block(by["pos"][0], 6)
        points = []
        for r in range(ncont):
            a = (p[0][r], p[1][r], p[2][r])
            b = (p[3][r], p[4][r], p[5][r])
            # walls: pos holds the contact point then the particle
            points += [b, a] if kind == "wall" else [a, b]
    for k, first, n in layout:
        if k == "pos":
            continue
        if k == "id":
            cols = block(first, 3, True)
            names = ("id1", "id2", "periodic") if kind == "pair" else ("mesh_id", "triangle_id", "atom_id")
            for name, col in zip(names, cols):
                fields.append((name, 1, vtk_type([col]), col))
        elif k == "vel":
            cols = block(first, 6)
            fields.append(("vel1", 3, "Float64", [v for t in zip(*cols[:3]) for v in t]))
            fields.append(("vel2", 3, "Float64", [v for t in zip(*cols[3:]) for v in t]))
        elif k == "history":
            cols = block(first, n)
            fields.append(("history", n, "Float64", [v for t in zip(*cols) for v in t]))
            if patch_first is not None:
                if patch_first + PATCH_N > n:
                    raise DumpError("the contact patch (history values %d to %d) lies outside the %d history values"
                                    % (patch_first, patch_first + PATCH_N - 1, n))
                j = patch_first
                for name, m in PATCH:
                    vals = [v for t in zip(*cols[j:j + m]) for v in t]
                    if name == "patch_formed":
                        vals = [int(round(v)) for v in vals]
                    fields.append((name, m, vtk_type([vals]), vals))
                    j += m
        elif k == "ms_id":
            cols = block(first, 2, True)
            fields.append(("ms_id", 2, vtk_type(cols), [v for t in zip(*cols) for v in t]))
        else:
            cols = block(first, n)
            fields.append((k, n, "Float64", [v for t in zip(*cols) for v in t]))
            if k == "force":
                fields.append(("force_magnitude", 1, "Float64",
                               [math.sqrt(cols[0][r] ** 2 + cols[1][r] ** 2 + cols[2][r] ** 2) for r in range(ncont)]))
    for n, (c, k) in enumerate(parsed):
        if k is None:
            vals = column_values(rows, n, True)
            fields.append((c, 1, vtk_type([vals]), vals))
    if points is None:
        ids = {f[0]: f[3] for f in fields}
        if atoms_by_step_ids is None or ("id1" not in ids and "atom_id" not in ids):
            raise DumpError("the compute has no pos: give its `id` and a particle dump of the same steps")
        points = []
        if kind == "pair":
            for i, j in zip(ids["id1"], ids["id2"]):
                points += [atoms_by_step_ids[int(i)], atoms_by_step_ids[int(j)]]
        else:
            raise DumpError("wall contacts need the compute's pos (the contact point)")
    return kind, points, fields


# ---------------------------------------------------------------- writing

FMT = {"Float64": "d", "Float32": "f", "Int64": "q", "Int32": "i", "UInt8": "B"}


class Writer:
    def __init__(self, ascii_data):
        self.ascii = ascii_data

    def array(self, name, ncomp, vtype, values, indent="        "):
        attrs = 'type="%s" Name=%s NumberOfComponents="%d"' % (vtype, quoteattr(name), ncomp)
        if self.ascii:
            if vtype.startswith("Float"):
                text = " ".join(repr(float(v)) for v in values)
            else:
                text = " ".join(str(int(v)) for v in values)
            return '%s<DataArray %s format="ascii">%s</DataArray>\n' % (indent, attrs, text)
        raw = struct.pack("<%d%s" % (len(values), FMT[vtype]), *values)
        # zlib blocks: header [nblocks, block size, last block size,
        # compressed sizes] as UInt64, base64-encoded apart from the data
        bs = 1 << 20
        blocks = [raw[k:k + bs] for k in range(0, len(raw), bs)] or [b""]
        comp = [zlib.compress(b, 6) for b in blocks]
        last = len(blocks[-1]) if len(blocks[-1]) != bs else 0
        head = struct.pack("<%dQ" % (3 + len(comp)), len(blocks), bs, last, *[len(c) for c in comp])
        text = (base64.b64encode(head) + base64.b64encode(b"".join(comp))).decode("ascii")
        return '%s<DataArray %s format="binary">%s</DataArray>\n' % (indent, attrs, text)

    def polydata(self, path, points, verts=None, lines=None, polys=None, point_data=(), cell_data=(),
                 field_data=()):
        header = 'compressor="vtkZLibDataCompressor" ' if not self.ascii else ""
        out = ['<?xml version="1.0"?>\n',
               '<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian" header_type="UInt64" %s>\n' % header,
               '  <PolyData>\n']
        if field_data:
            out.append("    <FieldData>\n")
            for name, vtype, values in field_data:
                a = self.array(name, 1, vtype, values, "      ")
                out.append(a.replace("<DataArray ", '<DataArray NumberOfTuples="%d" ' % len(values), 1))
            out.append("    </FieldData>\n")
        ncells = {k: (len(v[1]) if v else 0) for k, v in (("Verts", verts), ("Lines", lines), ("Polys", polys))}
        out.append('    <Piece NumberOfPoints="%d" NumberOfVerts="%d" NumberOfLines="%d" NumberOfStrips="0" '
                   'NumberOfPolys="%d">\n' % (len(points), ncells["Verts"], ncells["Lines"], ncells["Polys"]))
        out.append("      <Points>\n")
        out.append(self.array("Points", 3, "Float64", [v for p in points for v in p], "        "))
        out.append("      </Points>\n")
        for tag, cells in (("Verts", verts), ("Lines", lines), ("Polys", polys)):
            if cells:
                conn, offsets = cells
                out.append("      <%s>\n" % tag)
                out.append(self.array("connectivity", 1, "Int64", conn))
                out.append(self.array("offsets", 1, "Int64", offsets))
                out.append("      </%s>\n" % tag)
        for tag, data in (("PointData", point_data), ("CellData", cell_data)):
            out.append("      <%s>\n" % tag)
            for name, ncomp, vtype, values in data:
                out.append(self.array(name, ncomp, vtype, values))
            out.append("      </%s>\n" % tag)
        out.append("    </Piece>\n  </PolyData>\n</VTKFile>\n")
        with open(path, "w") as f:
            f.write("".join(out))


def write_pvd(path, entries):
    """entries: [(time, relative file name)]."""
    with open(path, "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">\n'
                '  <Collection>\n')
        for t, name in entries:
            f.write('    <DataSet timestep="%s" group="" part="0" file=%s/>\n' % (repr(float(t)), quoteattr(name)))
        f.write("  </Collection>\n</VTKFile>\n")


def superquadric_surface(center, shape, blockiness, quat, res):
    """Points and polygons (lists of local point indices) of the surface
    (|x/a|^n2 + |y/b|^n2)^(n1/n2) + |z/c|^n1 = 1 in the body frame, turned
    by quat (LIGGGHTS' convention) and moved to center."""
    a, b, c = shape
    n1, n2 = blockiness
    R = quat_to_matrix(*quat)

    def spow(v, e):
        return math.copysign(abs(v) ** e, v)

    nlon = 2 * res
    pts = []
    for k in range(1, res):
        eta = -math.pi / 2 + math.pi * k / res
        ce, se = math.cos(eta), math.sin(eta)
        for m in range(nlon):
            om = -math.pi + 2 * math.pi * m / nlon
            pts.append((a * spow(ce, 2 / n1) * spow(math.cos(om), 2 / n2),
                        b * spow(ce, 2 / n1) * spow(math.sin(om), 2 / n2),
                        c * spow(se, 2 / n1)))
    south, north = len(pts), len(pts) + 1
    pts += [(0.0, 0.0, -c), (0.0, 0.0, c)]
    polys = []
    for k in range(res - 2):
        for m in range(nlon):
            m1 = (m + 1) % nlon
            polys.append((k * nlon + m, k * nlon + m1, (k + 1) * nlon + m1, (k + 1) * nlon + m))
    for m in range(nlon):
        m1 = (m + 1) % nlon
        polys.append((south, m1, m))
        top = (res - 2) * nlon
        polys.append((north, top + m, top + m1))
    world = [tuple(center[r] + R[r][0] * p[0] + R[r][1] * p[1] + R[r][2] * p[2] for r in range(3)) for p in pts]
    return world, polys


# ---------------------------------------------------------------- main

def convert(args):
    files = expand(args.files)
    data = collect(files)
    computes, patch, dt = {}, {}, None
    if args.log:
        computes, patch, dt = parse_log(args.log)
    if args.compute:
        w = args.compute.split()
        if not w or w[0] not in ("pair/gran/local", "wall/gran/local"):
            raise DumpError("--compute takes 'pair/gran/local KEYWORDS' or 'wall/gran/local KEYWORDS'")
        # applies to every compute named in the dumps
        ids = set()
        for step, (box, columns, rows, path) in data["local"].items():
            for c in columns:
                m = re.match(r"^c_([^\[\]]+)", c)
                if m:
                    ids.add(m.group(1))
        for i in ids:
            computes[i] = (w[0], w[1:])
    if args.patch is not None:
        patch = {"pair": args.patch, "wall": args.patch}
    if args.dt is not None:
        dt = args.dt
    os.makedirs(args.output, exist_ok=True)
    wr = Writer(args.ascii)
    written = []

    def tval(step):
        return step * dt if dt is not None else float(step)

    def fdata(step, box):
        fd = [("TimeValue", "Float64", [tval(step)]), ("TimeStep", "Int64", [step])]
        if box:
            fd.append(("box_bounds", "Float64", [v for lohi in box for v in lohi]))
        return fd

    atom_points = {}
    if data["atoms"]:
        name = args.name
        sub = os.path.join(args.output, name)
        os.makedirs(sub, exist_ok=True)
        entries, sentries = [], []
        for step in sorted(data["atoms"]):
            box, columns, rows, _ = data["atoms"][step]
            points, fields = particle_fields(box, columns, rows)
            n = len(points)
            ids = {f[0]: f[3] for f in fields}
            if "id" in ids:
                atom_points[step] = {int(i): p for i, p in zip(ids["id"], points)}
            fn = "%s_%09d.vtp" % (name, step)
            wr.polydata(os.path.join(sub, fn), points, verts=(list(range(n)), list(range(1, n + 1))),
                        point_data=fields, field_data=fdata(step, box))
            entries.append((tval(step), os.path.join(name, fn)))
            if args.surfaces:
                spts, polys, pdata = surfaces(points, fields, args.surfaces)
                conn, offs = [], []
                for p in polys:
                    conn += p
                    offs.append(len(conn))
                sfn = "%s_surface_%09d.vtp" % (name, step)
                wr.polydata(os.path.join(sub, sfn), spts, polys=(conn, offs), point_data=pdata,
                            field_data=fdata(step, box))
                sentries.append((tval(step), os.path.join(name, sfn)))
        write_pvd(os.path.join(args.output, name + ".pvd"), entries)
        written.append((os.path.join(args.output, name + ".pvd"), len(entries), "particles"))
        if sentries:
            write_pvd(os.path.join(args.output, name + "_surface.pvd"), sentries)
            written.append((os.path.join(args.output, name + "_surface.pvd"), len(sentries), "particle surfaces"))
    if data["local"]:
        series = {}
        for step in sorted(data["local"]):
            box, columns, rows, _ = data["local"][step]
            kind, points, fields = contact_fields(columns, rows, computes, patch, atom_points.get(step))
            name = "contacts" if kind == "pair" else "wall_contacts"
            sub = os.path.join(args.output, name)
            os.makedirs(sub, exist_ok=True)
            n = len(rows)
            fn = "%s_%09d.vtp" % (name, step)
            wr.polydata(os.path.join(sub, fn), points, lines=(list(range(2 * n)), list(range(2, 2 * n + 1, 2))),
                        cell_data=fields, field_data=fdata(step, box))
            series.setdefault(name, []).append((tval(step), os.path.join(name, fn)))
        for name, entries in series.items():
            write_pvd(os.path.join(args.output, name + ".pvd"), entries)
            written.append((os.path.join(args.output, name + ".pvd"), len(entries), "contact network"))
    if not written:
        raise DumpError("no snapshot found in %s" % " ".join(files))
    return written


def surfaces(points, fields, res):
    """Polygonal surfaces of every particle: superquadrics from shape,
    blockiness and quat; spheres from radius. Point data: the particle's
    fields (but sq_tensor) on each of its surface points."""
    by = {f[0]: f for f in fields}
    n = len(points)
    if "shape" in by:
        sh, bl = by["shape"][3], by["blockiness"][3] if "blockiness" in by else [2.0, 2.0] * n
        q = by["quat"][3] if "quat" in by else [1.0, 0.0, 0.0, 0.0] * n
        spec = [(tuple(sh[3 * i:3 * i + 3]), tuple(bl[2 * i:2 * i + 2]), tuple(q[4 * i:4 * i + 4])) for i in range(n)]
    elif "radius" in by:
        spec = [((r, r, r), (2.0, 2.0), (1.0, 0.0, 0.0, 0.0)) for r in by["radius"][3]]
    else:
        raise DumpError("--surfaces needs radius (spheres) or shapex shapey shapez (superquadrics) in the dump")
    spts, polys, owner = [], [], []
    for i, (shape, bl, quat) in enumerate(spec):
        s = math.sqrt(sum(v * v for v in quat)) or 1.0
        pts, pl = superquadric_surface(points[i], shape, bl, tuple(v / s for v in quat), res)
        base = len(spts)
        spts += pts
        owner += [i] * len(pts)
        polys += [tuple(base + k for k in p) for p in pl]
    pdata = []
    for name, ncomp, vtype, values in fields:
        if name == "sq_tensor":
            continue
        pdata.append((name, ncomp, vtype, [values[ncomp * i + c] for i in owner for c in range(ncomp)]))
    return spts, polys, pdata


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 epilog="See the module docstring (head -60 %s) and doc/paraview.md." % sys.argv[0])
    ap.add_argument("files", nargs="+", help="dump custom / dump local files or quoted glob patterns")
    ap.add_argument("-o", "--output", default="paraview", help="output folder (default: paraview)")
    ap.add_argument("--log", help="LIGGGHTS log of the run (compute keywords, patch position, time step)")
    ap.add_argument("--compute", help='style and keywords of the contact compute, e.g. "pair/gran/local pos id force history"')
    ap.add_argument("--patch", type=int, help="first history value (0-based) of the contact patch")
    ap.add_argument("--dt", type=float, help="time step [s] for the .pvd times")
    ap.add_argument("--surfaces", type=int, nargs="?", const=12, default=0, metavar="RES",
                    help="also write particle surfaces as polygons (RES latitude divisions, default 12)")
    ap.add_argument("--name", default="particles", help="series name of the particle files (default: particles)")
    ap.add_argument("--ascii", action="store_true", help="ASCII data instead of compressed binary")
    args = ap.parse_args(argv)
    if args.surfaces and args.surfaces < 3:
        ap.error("--surfaces RES must be at least 3")
    try:
        written = convert(args)
    except (DumpError, OSError) as e:
        sys.stderr.write("dump2vtk: %s\n" % e)
        return 2
    for path, n, what in written:
        print("dump2vtk: %s (%s, %d snapshot%s)" % (path, what, n, "" if n == 1 else "s"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
