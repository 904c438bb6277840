#!/usr/bin/env bash
# Whole-run (loop) time of the LAMMPS packing (tests/bench/in.lammps_sphere_packing,
# jitter 2e-4: oblique contacts) with LAMMPS' hertz/material + mindlin and
# with the project's sub-models in its place: dc/hertz_elliptic + mindlin,
# dc/hertz_elliptic + dc/cmd_tangential (the bounded memory and the exact
# profile). The configurations run round-robin REPS times, the fastest of
# each is kept; a control row runs hertz/material + mindlin twice (the noise
# left in a ratio). Prints figures, asserts nothing.
# Usage: bash tests/bench/bench_lammps.sh [REPS]
# DC_BENCH_INSTRUCTIONS=1: each configuration also runs once under
# valgrind's callgrind (collected inside Verlet::run only): instruction
# counts that do not depend on the machine's load.
# DC_BENCH_STEPS (default 10000), DC_BENCH_ONLY="hm he ..." (a subset).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
lmp=${DC_LMP:-$root/build/lammps/lmp}
reps=${1:-3}
steps=${DC_BENCH_STEPS:-10000}
deck="$root/tests/bench/in.lammps_sphere_packing"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# name | normal | tangential
configs=(
  "hm|hertz/material 5e6 0.5 0.3|mindlin NULL 1.0 0.5"
  "hm_again|hertz/material 5e6 0.5 0.3|mindlin NULL 1.0 0.5"
  "he|dc/hertz_elliptic 5e6 0.5 0.3|mindlin NULL 1.0 0.5"
  "tp|dc/hertz_elliptic 5e6 0.5 0.3|dc/cmd_tangential 0.5 1 0 0"
  "cp|dc/hertz_elliptic 5e6 0.5 0.3|dc/cmd_tangential 0.5 0 0 0"
)
only=" ${DC_BENCH_ONLY:-hm hm_again he tp cp} "
declare -A best
for ((r = 1; r <= reps; r++)); do
  for c in "${configs[@]}"; do
    IFS='|' read -r name normal tang <<<"$c"
    [[ "$only" == *" $name "* ]] || continue
    d="$work/$name"; mkdir -p "$d"
    (cd "$d" && "$lmp" -in "$deck" -nocite -log log -screen none -var jitter 2e-4 -var steps "$steps" \
       -var normal "$normal" -var tangential "$tang") \
      || { echo "bench: $name failed:" >&2; tail -5 "$d/log" >&2; exit 1; }
    t=$(awk '/^Loop time of/ {print $4}' "$d/log")
    if [ -z "${best[$name]:-}" ] || awk "BEGIN{exit !($t < ${best[$name]})}"; then best[$name]=$t; fi
  done
done
declare -A instr
if [ "${DC_BENCH_INSTRUCTIONS:-0}" = 1 ]; then
  for c in "${configs[@]}"; do
    IFS='|' read -r name normal tang <<<"$c"
    [[ "$only" == *" $name "* && "$name" != hm_again ]] || continue
    d="$work/$name"
    (cd "$d" && valgrind --tool=callgrind --toggle-collect='LAMMPS_NS::Verlet::run(int)' --callgrind-out-file=cg.out \
       "$lmp" -in "$deck" -nocite -log none -screen none -var jitter 2e-4 -var steps "$steps" \
       -var normal "$normal" -var tangential "$tang" >cg.txt 2>&1) \
      || { echo "bench: callgrind run of $name failed" >&2; tail -5 "$d/cg.txt" >&2; exit 1; }
    instr[$name]=$(awk '/^summary:/ {print $2}' "$d/cg.out")
  done
fi
printf "LAMMPS packing, 2888 spheres, %s steps, best of %s (wall s; instructions inside Verlet::run)\n" "$steps" "$reps"
printf "%-9s %-28s %-30s %9s %7s %14s %7s\n" config normal tangential "loop s" "ratio" instructions ratio
for c in "${configs[@]}"; do
  IFS='|' read -r name normal tang <<<"$c"
  [ -n "${best[$name]:-}" ] || continue
  ratio=$(awk "BEGIN{printf \"%.3f\", ${best[$name]} / ${best[hm]:-${best[$name]}}}")
  ins=${instr[$name]:-}
  iratio=""
  [ -n "$ins" ] && [ -n "${instr[hm]:-}" ] && iratio=$(awk "BEGIN{printf \"%.3f\", $ins / ${instr[hm]}}")
  printf "%-9s %-28s %-30s %9s %7s %14s %7s\n" "$name" "${normal%% *}" "${tang}" "${best[$name]}" "$ratio" "${ins:--}" "${iratio:--}"
done
echo "(ratio: against hm, LAMMPS' hertz/material + mindlin; hm_again is the control: the noise left in a ratio)"
