#!/usr/bin/env python3
"""Checks dclaw plot (path of dclaw in argv[1]); needs python3-matplotlib for
the system python3, not LIGGGHTS.

Every law side by side, and one quantity at a time: the PNG must be a valid
PNG (signature, chunk checksums, image data of the size the header gives) of
plausible size with the curves of the laws drawn in their colours; the
plotted series (--csv) must be exactly the force, area and stiffness columns
dclaw <law> prints, against its delta column, labelled with the law and its
keys. Bad input must exit 2 with a clear message and write no PNG."""
import csv
import os
import shlex
import struct
import sys
import tempfile
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cli_checks  # noqa: E402
from cli_checks import check, finish  # noqa: E402

EXE = sys.argv[1]


def run(args, env=None):
    """Runs dclaw with args (and extra environment); returns (exit code, stdout, stderr)."""
    return cli_checks.run(EXE, args, env)


def table(args):
    """dclaw <args>'s CSV: {column: [floats]} and the column order."""
    rc, out, err = run(args)
    assert rc == 0, "dclaw %s: %s" % (" ".join(args), err)
    lines = out.strip().splitlines()
    head = lines[0].split(",")
    rows = [[float(x) for x in l.split(",")] for l in lines[1:]]
    return {c: [r[j] for r in rows] for j, c in enumerate(head)}, head


def png_pixels(path):
    """(width, height, rows of RGB(A) tuples) of an 8-bit RGB or RGBA PNG,
    decoded here (chunk CRCs checked, scanline filters undone); raises
    ValueError on anything that is not such a PNG."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("no PNG signature")
    pos, chunks = 8, []
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body, crc = data[pos + 8:pos + 8 + n], data[pos + 8 + n:pos + 12 + n]
        if len(crc) != 4 or struct.unpack(">I", crc)[0] != zlib.crc32(kind + body):
            raise ValueError("bad checksum of chunk %r" % kind)
        chunks.append((kind, body))
        pos += 12 + n
    if chunks[0][0] != b"IHDR" or chunks[-1][0] != b"IEND":
        raise ValueError("chunks %s" % [k for k, _ in chunks])
    w, h, depth, colour = struct.unpack(">IIBB", chunks[0][1][:10])
    if depth != 8 or colour not in (2, 6):
        raise ValueError("bit depth %d, colour type %d" % (depth, colour))
    bpp = 3 if colour == 2 else 4
    raw = zlib.decompress(b"".join(b for k, b in chunks if k == b"IDAT"))
    stride = w * bpp
    if len(raw) != h * (stride + 1):
        raise ValueError("%d bytes of image data for %d x %d" % (len(raw), w, h))
    rows, prev = [], bytearray(stride)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
            elif f != 0:
                raise ValueError("filter %d" % f)
        rows.append([tuple(line[i:i + 3]) for i in range(0, stride, bpp)])
        prev = line
    return w, h, rows


def image(path, what):
    """png_pixels(path), counting a check; (0, 0, []) if path is no such PNG."""
    try:
        got = png_pixels(path)
    except (OSError, ValueError, zlib.error) as e:
        got = (0, 0, [])
        check(False, "%s: %s is not a valid PNG: %s" % (what, path, e))
    else:
        check(True, what)
    return got


def near(rows, rgb, tol=30):
    """Number of pixels within tol (each channel) of colour rgb."""
    return sum(all(abs(p[k] - rgb[k]) <= tol for k in range(3)) for row in rows for p in row)


def coloured(rows):
    """Number of pixels that are not grey (axes, text and grid are)."""
    return sum(max(p) - min(p) > 60 for row in rows for p in row)


# matplotlib's first colours: the first curve of the first and second law
BLUE, ORANGE = (31, 119, 180), (255, 127, 14)

# Every law; the columns dclaw plot must draw of each for force, area, stiffness.
LAWS = [
    ("hertz_elliptic --R1 0.002 --R2 0.0005 --Estar 1e9 --delta_min 0 --delta_max 2e-7 --n 21",
     {"force": ["force"], "area": ["area"], "stiffness": ["stiffness"]}),
    ("jkr_elliptic --R1 0.002 --R2 0.0005 --Estar 1e9 --w 0.05 --delta_min -2e-8 --delta_max 2e-7 --n 23",
     {"force": ["force"], "area": ["area"], "stiffness": ["stiffness"]}),
    ("gw_rough --w 0.05 --n 9",
     {"force": ["force_gw_elliptic", "force_feng_table", "force_feng_fitted", "force_gw_table",
                "force_adhesive_loading", "force_adhesive_unloading"],
      "area": ["area_gw_elliptic", "area_adhesive_loading", "area_adhesive_unloading"],
      "stiffness": ["kn_gw_elliptic", "kn_feng_table", "kn_feng_fitted", "kn_gw_table"]}),
    ("jamari_ep --n 7", {"force": ["force"], "area": ["area"], "stiffness": ["stiffness"]}),
    ("hertz_elliptic --R1 0.001 --R2 0.001 --delta 1e-6", {"force": ["force"], "area": ["area"], "stiffness": ["stiffness"]}),
]


def plot_args(png, laws, *options):
    """dclaw plot's arguments for png and the laws (strings of law and keys)."""
    args = ["plot", "--png", png] + list(options)
    for law in laws:
        args += ["--"] + law.split()
    return args


def check_series(csv_path, laws, quantities, what):
    """The plotted series equal each law's printed columns of quantities, in row order."""
    if not os.path.exists(csv_path):
        return check(False, "%s: no %s" % (what, csv_path))
    with open(csv_path) as f:
        plotted = list(csv.DictReader(f))
    for law, columns in laws:
        printed, _ = table(law.split())
        for q in quantities:
            for col in columns[q]:
                suffix = col.split("_", 1)[1] if "_" in col else ""
                label = "%s (%s)" % (law, suffix) if suffix else law
                got = [r for r in plotted if r["label"] == label and r["column"] == col]
                check([float(r["delta"]) for r in got] == printed["delta"] and
                      [float(r["value"]) for r in got] == printed[col],
                      "%s: %s %s plotted %d points unlike the %d printed" % (what, law, col, len(got), len(printed[col])))
    want = {(law, col) for law, columns in laws for q in quantities for col in columns[q]}
    have = {(r["label"].split(" (")[0], r["column"]) for r in plotted}
    check(have == want, "%s: plotted columns %s, want %s" % (what, sorted(have - want), sorted(want - have)))


with tempfile.TemporaryDirectory() as tmp:
    # every law side by side, all three panels
    png, data = os.path.join(tmp, "all.png"), os.path.join(tmp, "all.csv")
    rc, out, err = run(plot_args(png, [l for l, _ in LAWS], "--csv", data))
    check(rc == 0 and out == "" and err == "", "plot of every law: exit %d, stdout %r, stderr %r" % (rc, out[:200], err))
    check_series(data, LAWS, ["force", "area", "stiffness"], "every law")
    w_all, h_all, _ = image(png, "every law")
    size = os.path.getsize(png) if os.path.exists(png) else 0
    check(600 <= w_all <= 1200 and 800 <= h_all <= 1600 and 20e3 < size < 1e6,
          "every law: %d x %d pixels, %d bytes" % (w_all, h_all, size))

    # two laws over the same overlaps: both drawn, in the first two colours
    png = os.path.join(tmp, "pair.png")
    rc, _, err = run(plot_args(png, [LAWS[0][0], LAWS[1][0]]))
    w, h, pixels = image(png, "hertz_elliptic and jkr_elliptic")
    blue, orange = near(pixels, BLUE), near(pixels, ORANGE)
    check(rc == 0 and w == w_all and 800 <= h <= h_all and blue > 1000 and orange > 1000,
          "hertz_elliptic and jkr_elliptic: exit %d, stderr %r, %d x %d pixels, %d blue, %d orange" % (rc, err, w, h, blue, orange))

    # one quantity: one panel, its columns only (gw_rough's stiffness is kn)
    for q in ("force", "area", "stiffness"):
        png, data = os.path.join(tmp, q + ".png"), os.path.join(tmp, q + ".csv")
        laws = [LAWS[1], LAWS[2]]
        rc, out, err = run(plot_args(png, [l for l, _ in laws], "--y", q, "--csv", data))
        check(rc == 0, "--y %s: exit %d, stderr %r" % (q, rc, err))
        check_series(data, laws, [q], "--y " + q)
        w, h, pixels = image(png, "--y " + q)
        check(w == w_all and 250 <= h < h_all / 2 and coloured(pixels) > 1000,
              "--y %s: %d x %d pixels (all: %d x %d), %d coloured" % (q, w, h, w_all, h_all, coloured(pixels)))

    # the tangential laws: cmd_tangential's loop against the displacement u,
    # kalker's creep force against the creepage xi (two creep models); the
    # series are the printed columns
    for laws, q, x in ((["cmd_tangential --r 0.9 --n 15"], "tangential", "u"),
                       (["kalker --xi_max 0.005 --n 20", "kalker --xi_max 0.005 --n 20 --model 0"], "creep", "xi")):
        png, data = os.path.join(tmp, q + ".png"), os.path.join(tmp, q + ".csv")
        rc, out, err = run(plot_args(png, laws, "--csv", data))
        col = "Ft" if q == "tangential" else "Fx"
        ok = rc == 0 and os.path.exists(data)
        if ok:
            with open(data) as f:
                plotted = list(csv.DictReader(f))
            for law in laws:
                printed, _ = table(law.split())
                got = [r for r in plotted if r["label"] == law and r["column"] == col]
                ok &= [float(r[x]) for r in got] == printed[x] and [float(r["value"]) for r in got] == printed[col]
        w, h, pixels = image(png, q)
        check(ok and coloured(pixels) > 1000, "%s: %s plotted against %s as printed (exit %d, stderr %r)"
              % (" and ".join(laws), col, x, rc, err))
    rc, _, err = run(plot_args(os.path.join(tmp, "mixed.png"), ["kalker", "cmd_tangential"]))
    check(rc == 2 and "drawn against different columns" in err, "kalker with cmd_tangential: exit %d, %r" % (rc, err))

    # a file not named .png is still a PNG
    png = os.path.join(tmp, "plot.pdf")
    rc, _, err = run(plot_args(png, [LAWS[0][0]], "--y", "force"))
    check(rc == 0 and image(png, "--png plot.pdf")[0] == w_all, "--png plot.pdf: exit %d, stderr %r" % (rc, err))

    # bad input: exit 2, a message saying what is wrong, no PNG
    png = os.path.join(tmp, "bad.png")
    law = LAWS[0][0]
    BAD = [
        ("plot", {}, "--png FILE is missing"),
        ("plot --png %s" % png, {}, "no law given"),
        ("plot --png %s --" % png, {}, "no law after '--'"),
        ("plot --png %s -- %s --" % (png, law), {}, "no law after '--'"),
        ("plot --png %s -- nolaw --R1 1" % png, {}, "unknown law 'nolaw'"),
        ("plot --png %s -- %s -- nolaw" % (png, law), {}, "unknown law 'nolaw'"),
        ("plot --png %s --y energy -- %s" % (png, law), {}, "--y 'energy': must be force, area, stiffness, tangential, creep or all"),
        ("plot --png %s --x delta -- %s" % (png, law), {}, "unknown option '--x'"),
        ("plot --png %s --y" % png, {}, "--y needs a value"),
        ("plot --png %s -- hertz_elliptic --R1 abc" % png, {}, "--R1: 'abc' is not a finite number"),
        ("plot --png %s -- %s -- gw_rough --sigma 1e300 --n 3" % (png, law), {}, "dclaw gw_rough: --Estar, --sigma"),
        ("plot --png %s -- jkr_elliptic --summary 1" % png, {}, "jkr_elliptic --summary 1: its table has no delta, u, xi column"),
        ("plot --png %s -- %s" % (os.path.join(tmp, "no", "dir.png"), law), {}, "cannot write %s" % os.path.join(tmp, "no", "dir.png")),
        ("plot --png %s --csv %s -- %s" % (png, os.path.join(tmp, "no", "dir.csv"), law), {}, "cannot write"),
        ("plot --png %s -- %s" % (png, law), {"DCLAW_PYTHON": os.path.join(tmp, "python3")}, "python3-matplotlib"),
        ("plot --png %s -- %s" % (png, law), {"DCLAW_PLOT_SCRIPT": os.path.join(tmp, "plot.py")}, "cannot read the plotting script"),
    ]
    # a python3 whose matplotlib cannot be imported
    fake = os.path.join(tmp, "fake", "matplotlib")
    os.makedirs(fake)
    with open(os.path.join(fake, "__init__.py"), "w") as f:
        f.write("raise ImportError('matplotlib hidden by check_dclaw_plot')\n")
    BAD.append(("plot --png %s -- %s" % (png, law), {"PYTHONPATH": os.path.dirname(fake)},
                "has no matplotlib (matplotlib hidden by check_dclaw_plot): install the Debian package python3-matplotlib"))
    for args, env, message in BAD:
        rc, out, err = run(shlex.split(args), env)
        check(rc == 2 and message in err and out == "" and not os.path.exists(png),
              "%s %s: exit %d (want 2), stdout %r, stderr %r (want %r)" % (env, args, rc, out[:200], err.strip(), message))
        if os.path.exists(png):
            os.remove(png)

    # help: dclaw plot's, a law's inside a plot, and dclaw's naming plot
    rc, out, _ = run(["plot", "--help"])
    check(rc == 0 and out.startswith("usage: dclaw plot --png FILE") and "python3-matplotlib" in out, "dclaw plot --help: %r" % out)
    rc, out, _ = run(["plot", "--png", png, "--"] + law.split() + ["--", "jkr_elliptic", "--help"])
    check(rc == 0 and out.startswith("usage: dclaw jkr_elliptic") and not os.path.exists(png), "plot -- jkr_elliptic --help: %r" % out)
    rc, out, _ = run(["--help"])
    check(rc == 0 and "dclaw plot --png FILE" in out, "dclaw --help names plot: %r" % out)

finish()
