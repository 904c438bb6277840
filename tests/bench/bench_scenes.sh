#!/usr/bin/env bash
# Whole-run (loop) time of the same scene with stock `hertz` and with
# `hertz_elliptic`, for spheres and superquadrics, `gw_rough` and
# `jkr_elliptic` on the sphere packing, and the superquadric packing on 1
# and 2 MPI ranks. All runs in one invocation, back to back;
# each configuration runs REPS times and the fastest is kept. Prints figures,
# asserts nothing. Usage: bash tests/bench/bench_scenes.sh [REPS]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
lmp="$root/build/bin/liggghts"
reps=${1:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# loop time of one configuration, best of $reps: deck model steps ranks [extra -var pairs]
loop_time() {
  local best=""
  for r in $(seq "$reps"); do
    local d="$work/$2_$4_$r"; mkdir -p "$d"; cd "$d"
    if [ "$4" -gt 1 ]; then
      mpirun -np "$4" "$lmp" -in "$1" -var model "$2" -var steps "$3" ${5:-} -log log > screen.txt 2>&1
    else
      "$lmp" -in "$1" -var model "$2" -var steps "$3" ${5:-} -log log > screen.txt 2>&1
    fi
    local t; t=$(awk '/^Loop time of/ {print $4}' log)
    best=$(python3 -c "print(min(float('$t'), float('${best:-1e300}')))")
  done
  echo "$best"
}

sph="$root/tests/bench/in.sphere_packing"
sq="$root/inputs/superquadric_packing/in.superquadric_packing"
t_sh=$(loop_time "$sph" hertz 10000 1)
t_se=$(loop_time "$sph" hertz_elliptic 10000 1)
t_sr=$(loop_time "$sph" gw_rough 10000 1 "-var cdf 1.05")
t_sj=$(loop_time "$sph" jkr_elliptic 10000 1 "-var cdf 1.02")
# the same contact distance without the rough law, and the JKR solve on a
# (practically) non-adhesive trajectory: the laws' own cost
t_sh5=$(loop_time "$sph" hertz 10000 1 "-var cdf 1.05")
t_se2=$(loop_time "$sph" hertz_elliptic 10000 1 "-var cdf 1.02")
t_sj0=$(loop_time "$sph" jkr_elliptic 10000 1 "-var cdf 1.02 -var w 1e-9")
t_qh=$(loop_time "$sq" hertz 15000 1)
t_qe=$(loop_time "$sq" hertz_elliptic 15000 1)
t_q2=$(loop_time "$sq" hertz_elliptic 15000 2)
python3 - "$t_sh" "$t_se" "$t_qh" "$t_qe" "$t_q2" "$t_sr" "$t_sj" "$t_sh5" "$t_se2" "$t_sj0" <<'PY'
import sys
sh, se, qh, qe, q2, sr, sj, sh5, se2, sj0 = map(float, sys.argv[1:])
print("scene (best of runs, loop time)                     stock hertz  hertz_elliptic  ratio")
print("2888 spheres settling, 10000 steps, 1 rank          %9.3f s   %9.3f s     %.4f" % (sh, se, se / sh))
print("324 superquadrics settling, 15000 steps, 1 rank     %9.3f s   %9.3f s     %.4f" % (qh, qe, qe / qh))
print("2888 spheres: gw_rough (Feng, sigma = 0.01 r) %.3f s = %.4f x stock hertz" % (sr, sr / sh))
print("    same contact distance (1.05): stock hertz %.3f s; gw_rough = %.4f x" % (sh5, sr / sh5))
print("2888 spheres: jkr_elliptic (w = 0.05 J/m^2) %.3f s = %.4f x hertz_elliptic" % (sj, sj / se))
print("    w = 1e-9 J/m^2 (same trajectory as Hertz), contact distance 1.02: hertz_elliptic %.3f s, "
      "jkr_elliptic %.3f s = %.4f x" % (se2, sj0, sj0 / se2))
print("324 superquadrics, hertz_elliptic: 1 rank %.3f s, 2 ranks %.3f s, speed-up %.3f" % (qe, q2, qe / q2))
PY
