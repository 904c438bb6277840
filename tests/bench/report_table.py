#!/usr/bin/env python3
"""Table of the speed-versus-error report (tests/bench/report.sh): merges
the kernel programs' rows (bench_report_*.c) with the LIGGGHTS scenes'
(report_scenes.py) and writes table.csv and table.md.

A kernel row takes the whole-run ratio of its family's LIGGGHTS run of the
same law; a packing row takes the ns per call of the kernel row it names.

Usage: report_table.py OUT_DIR SCENES_CSV KERNEL_CSV..."""
import csv
import sys

COLUMNS = ["family", "scene", "law", "exact", "ns_per_call", "run_ratio", "error", "error_rms", "metric", "note"]
FAMILIES = ["superquadric", "rough", "adhesion", "classical normal", "tangential"]


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def merge(kernel, scenes):
    """The table rows, by family then scene in the order given."""
    ratio = {(s["family"], s["law"]): s["run_ratio"] for s in scenes if not s["scene"]}
    ns = {}
    for k in kernel:
        ns.setdefault((k["family"], k["law"]), k["ns_per_call"])
    rows = [dict(k, run_ratio=ratio.get((k["family"], k["law"]), "")) for k in kernel]
    rows += [dict(s, ns_per_call=ns.get((s["family"], s["kernel_law"]), ""), error_rms="")
             for s in scenes if s["scene"]]
    return sorted(rows, key=lambda r: FAMILIES.index(r["family"]))


def fmt(v, digits=3):
    return "n/a" if v == "" else "%.*g" % (digits, float(v))


def markdown(rows):
    out = []
    for family in FAMILIES:
        scenes = []
        for r in rows:
            if r["family"] == family and r["scene"] not in scenes:
                scenes.append(r["scene"])
        if not scenes:
            continue
        out.append("### %s\n" % family)
        for scene in scenes:
            sel = [r for r in rows if r["family"] == family and r["scene"] == scene]
            out.append("%s. Error: %s.\n" % (scene, sel[0]["metric"]))
            out.append("| law | ns per call | run time / stock hertz | error | error rms | note |")
            out.append("| --- | ---: | ---: | ---: | ---: | --- |")
            for r in sel:
                law = "**%s**" % r["law"] if r["exact"] == "1" else r["law"]
                rms = fmt(r["error_rms"], 2) if r["error_rms"] else ""
                out.append("| %s | %s | %s | %s | %s | %s |" % (law, fmt(r["ns_per_call"]), fmt(r["run_ratio"]),
                                                         fmt(r["error"], 2), rms, r["note"]))
            out.append("")
    return "\n".join(out)


def main():
    out_dir, scenes_csv = sys.argv[1:3]
    kernel = [r for path in sys.argv[3:] for r in read(path)]
    rows = merge(kernel, read(scenes_csv))
    with open(out_dir + "/table.csv", "w", newline="") as f:
        w = csv.DictWriter(f, COLUMNS, extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)
    with open(out_dir + "/table.md", "w") as f:
        f.write("Laws in bold: the exact law of the scene. ns per call: the kernel (c_core), best of "
                "repetitions. Run time: the LIGGGHTS scene of the family, as a ratio to stock `hertz` in the "
                "same run (n/a: no LIGGGHTS run of that law).\n\n")
        f.write(markdown(rows))


if __name__ == "__main__":
    main()
