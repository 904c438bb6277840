#!/usr/bin/env bash
# The speed-versus-error report: every law of the project on fixed scenes,
# its cost (ns per kernel call; whole-run time of a LIGGGHTS scene as a
# ratio to stock hertz in the same run) against its error (against the
# exact law of the same physics on the same scene). Builds what is needed
# (plugin/setup.sh), then writes into build/report/:
#   table.md, table.csv   one row per law and scene
#   <family>.png          error against cost per family, Pareto fronts marked
#   kernels_*.csv, scenes.csv, calibration.txt   the parts the table is made of
# Families, scenes and metrics: doc/speed_vs_error.md.
# Usage: bash tests/bench/report.sh [REPS]   (LIGGGHTS repetitions, default 2;
# about 7 minutes on 2 shared cores). DC_REPORT_REPS sets the kernel
# repetitions (default 5).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
reps=${1:-2}
"$root/plugin/setup.sh"
out="$root/build/report"
rm -rf "$out"
mkdir -p "$out/runs"
bin="$root/build/tests"
start=$SECONDS
echo "report: kernels (c_core)"
"$bin/bench_report_superquadric" > "$out/kernels_superquadric.csv"
"$bin/bench_report_rough" > "$out/kernels_rough.csv"
"$bin/bench_report_adhesion" > "$out/kernels_adhesion.csv"
"$bin/bench_report_impact" "$out/calibration.txt" > "$out/kernels_impact.csv"
"$bin/bench_report_shear" > "$out/kernels_shear.csv"
echo "report: LIGGGHTS scenes, $reps round-robin repetitions"
# Debian's python3 (python3-numpy, python3-matplotlib from plugin/setup.sh)
py=/usr/bin/python3
$py "$root/tests/bench/report_scenes.py" "$root/build/bin/liggghts" "$out/calibration.txt" \
    "$out/scenes.csv" "$out/runs" "$reps"
$py "$root/tests/bench/report_table.py" "$out" "$out/scenes.csv" "$out"/kernels_*.csv
$py "$root/tests/bench/report_plot.py" "$out"
rm -rf "$out/runs"
echo "report: done in $((SECONDS - start)) s; $out/table.md, table.csv and:"
ls "$out"/*.png
