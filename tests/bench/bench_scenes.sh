#!/usr/bin/env bash
# Whole-run (loop) time of the same scene with stock `hertz` and with
# `hertz_elliptic`, for spheres and superquadrics, `gw_rough` (with and
# without cohesion `gw_adhesion`, also on rough superquadrics) and
# `jkr_elliptic` on the sphere packing,
# the superquadric packing on 1 and 2 MPI ranks, a rolling scene with
# and without `rolling_friction kalker`, and settled beds of spheres and of
# superquadrics on 1 and 2 ranks. All runs in one invocation; the
# configurations run
# round-robin REPS times (so that a slow spell of the machine hits all of
# them alike) and the fastest run of each is kept. Prints figures, asserts
# nothing. Usage: bash tests/bench/bench_scenes.sh [REPS]
# With DC_BENCH_BASELINE=/path/to/another/liggghts every configuration also
# runs with that executable in the same round-robin, and a last table gives
# each configuration's time against it (before/after a change).
# DC_BENCH_ONLY="st sth ..." runs only the named configurations (their
# rows print; the others show as n/a). A control row runs the sphere
# configuration se twice (se, se_again): the ratio of two identical
# configurations, i.e. the noise left in a best-of-REPS ratio on this
# machine (up to several per cent on shared machines).
# The settled scenes (tests/bench/in.settled_spheres, in.settled_superquadrics)
# are prepared once per invocation and model, before the timed runs and on 2
# ranks (untimed: a settling run that writes a restart file, 8.5 s for the
# spheres, 37 s for the superquadrics on a quiet machine); every timed run
# starts from that restart, so "Loop time" is the settled segment alone.
# DC_BENCH_PREP=DIR keeps the restart files in DIR and reuses them in a
# later invocation.
# DC_BENCH_MPIRUN="--bind-to none" (for example) passes options to mpirun.
# DC_BENCH_INSTRUCTIONS=1: after the timed runs, each 1-rank configuration
# that ran also runs once under valgrind's callgrind (collected inside
# Verlet::run only; about 20-40x slower than the timed run): instruction
# counts that do not depend on the machine's load, printed beside the
# times in the whole-contact table.
# DC_BENCH_ONLY="contact" runs the configurations of the whole-contact
# table alone (the sub-models' cost around their laws).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
lmp="$root/build/bin/liggghts"
reps=${1:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

sph="$root/tests/bench/in.sphere_packing"
sq="$root/inputs/superquadric_packing/in.superquadric_packing"
roll="$root/tests/bench/in.rolling_scene"
ss="$root/tests/bench/in.settled_spheres"
sqs="$root/tests/bench/in.settled_superquadrics"
rcs="$root/examples/rough_cohesive_superquadrics/in.rough_cohesive_superquadrics"
prep=${DC_BENCH_PREP:-$work/prep}
mkdir -p "$prep"
# name | deck | model | steps | ranks | extra -var pairs
configs=(
  "sh|$sph|hertz|10000|1|"
  "se|$sph|hertz_elliptic|10000|1|"
  # gw_rough's tabulated law reaches 6 sigma before touch (sigma = 2^1/2
  # 1.5e-5 m per pair and sphere-wall): contact distance 1.085 at least
  "sr|$sph|gw_rough|10000|1|-var cdf 1.09"
  "sj|$sph|jkr_elliptic|10000|1|-var cdf 1.02"
  # rough adhesion: gw_rough gwElliptic on with cohesion gw_adhesion (w =
  # 0.05 J/m^2; attached summits pull up to 8 sigma + |delta_break| apart:
  # contact distance 1.114 at least), gw_rough gwElliptic on alone and the
  # default gw_rough at that contact distance
  "sra|$sph|gw_rough|10000|1|-var cdf 1.12 -var coh 1"
  # rough adhesion on superquadrics (the example: 324 blocky particles
  # settling, elliptic summits), with and without the cohesion model
  "qra|$rcs|gw_rough|15000|1|-var cohesion 1"
  "qre|$rcs|gw_rough|15000|1|-var cohesion 0"
  "sre|$sph|gw_rough|10000|1|-var cdf 1.12 -var gwe 1"
  "sr2|$sph|gw_rough|10000|1|-var cdf 1.12"
  # the same on polydisperse spheres (d 2.6-3.4 mm: every contact has its
  # own radius, nothing set up per radius is reused)
  "spa|$sph|gw_rough|10000|1|-var cdf 1.14 -var coh 1 -var poly 1"
  "spe|$sph|gw_rough|10000|1|-var cdf 1.14 -var gwe 1 -var poly 1"
  # the laws' own cost: the same contact distance without the rough law,
  # and each law on the Hertz trajectory (w, sigma practically 0)
  "sh5|$sph|hertz|10000|1|-var cdf 1.09"
  "se2|$sph|hertz_elliptic|10000|1|-var cdf 1.02"
  "sj0|$sph|jkr_elliptic|10000|1|-var cdf 1.02 -var w 1e-9"
  # DMT (jkr_elliptic adhesionLaw dmt), at w = 0.05 J/m^2 and on the Hertz trajectory
  "sjd|$sph|jkr_elliptic|10000|1|-var cdf 1.02 -var tkey adhesionLaw -var tval dmt"
  "sjd0|$sph|jkr_elliptic|10000|1|-var cdf 1.02 -var w 1e-9 -var tkey adhesionLaw -var tval dmt"
  # Maugis-Dugdale (adhesionLaw maugis) at w = 0.05 J/m^2, z0 = 1 um (lambda
  # 0.73-0.92: the transition), and on the Hertz trajectory (w = 1e-9, z0 =
  # 0.4 nm: lambda 0.013-0.017, the zone's reach 0.39 nm)
  "sjm|$sph|jkr_elliptic|10000|1|-var cdf 1.02 -var tkey adhesionLaw -var tval maugis"
  "sjm0|$sph|jkr_elliptic|10000|1|-var cdf 1.02 -var w 1e-9 -var z0 4e-10 -var tkey adhesionLaw -var tval maugis"
  "sh1|$sph|hertz|10000|1|-var cdf 1.0001"
  "sr0|$sph|gw_rough|10000|1|-var cdf 1.0001 -var sigma 1e-12"
  # plasticity: hardness 1e5 Pa yields at 1e-3 r, so settling contacts go plastic
  "sjp|$sph|jamari_ep|10000|1|"
  # the same below first yield (hardness 1e12 Pa): the Hertz trajectory,
  # so that the ratio to hertz_elliptic is the model's own cost (the
  # plastic scene makes 1.43 x the contact evaluations: longer contacts)
  "sje|$sph|jamari_ep|10000|1|-var hardness 1e12"
  # tangential: Cattaneo-Mindlin-Deresiewicz against stock tangential
  # history, on the lattice jittered so that contacts are oblique (unjittered
  # columns fall straight: no tangential motion at all)
  "sth|$sph|hertz|10000|1|-var jitter 2e-4"
  "st|$sph|hertz|10000|1|-var tmodel cmd_tangential -var jitter 2e-4"
  "qt|$sq|hertz_elliptic|15000|1|-var tmodel cmd_tangential"
  # cmd_tangential's bounded memory (cmdMemory turningPoints): the packing,
  # the superquadric packing and the settled bed
  "stp|$sph|hertz_elliptic|10000|1|-var tmodel cmd_tangential -var jitter 2e-4 -var tkey cmdMemory -var tval turningPoints"
  "qtp|$sq|hertz_elliptic|15000|1|-var tmodel cmd_tangential -var tkey cmdMemory -var tval turningPoints"
  "qh|$sq|hertz|15000|1|"
  "qe|$sq|hertz_elliptic|15000|1|"
  "q2|$sq|hertz_elliptic|15000|2|"
  # rolling: spheres rolling down an incline, hertz_elliptic + cmd_tangential
  # without and with rolling_friction kalker, and kalker with nothing rolling
  # (rollingVelocityMin 1e3: cmd_tangential acts everywhere, the hand-over's
  # kinematics are computed all the same)
  "rt|$roll|hertz_elliptic|20000|1|-var rmodel off"
  "rk|$roll|hertz_elliptic|20000|1|-var rmodel kalker"
  "rk0|$roll|hertz_elliptic|20000|1|-var rmodel kalker -var rkey rollingVelocityMin -var rval 1e3"
  # settled beds, 1 and 2 ranks (processors * 1 1: split along the long
  # axis x, the scenes are symmetric about the cut); each model from its own
  # settled restart, prepared once below
  "ssh|$ss|hertz|20000|1|-var rfile $prep/ss_hertz.restart"
  "ssh2|$ss|hertz|20000|2|-var rfile $prep/ss_hertz.restart"
  "sse|$ss|hertz_elliptic|20000|1|-var rfile $prep/ss_hertz_elliptic.restart"
  "sse2|$ss|hertz_elliptic|20000|2|-var rfile $prep/ss_hertz_elliptic.restart"
  "ssc|$ss|hertz_elliptic|20000|1|-var tmodel cmd_tangential -var rfile $prep/ss_hertz_elliptic_cmd.restart"
  "ssc2|$ss|hertz_elliptic|20000|2|-var tmodel cmd_tangential -var rfile $prep/ss_hertz_elliptic_cmd.restart"
  "sst|$ss|hertz_elliptic|20000|1|-var tmodel cmd_tangential -var tkey cmdMemory -var tval turningPoints -var rfile $prep/ss_hertz_elliptic_tp.restart"
  "sqh|$sqs|hertz|10000|1|-var rfile $prep/sq_hertz.restart"
  "sqh2|$sqs|hertz|10000|2|-var rfile $prep/sq_hertz.restart"
  "sqe|$sqs|hertz_elliptic|10000|1|-var rfile $prep/sq_hertz_elliptic.restart"
  "sqe2|$sqs|hertz_elliptic|10000|2|-var rfile $prep/sq_hertz_elliptic.restart"
  # the same with the curvature reused across steps (curvatureTolerance 1e-4)
  "sqr|$sqs|hertz_elliptic|10000|1|-var rfile $prep/sq_hertz_elliptic_t4.restart -var ctol 1e-4"
  # whole-contact cost: each sub-model on the jittered sphere packing
  # against stock hertz + tangential history (sth): hertz_elliptic with
  # stock history, with the contact patch stored, with each classical
  # tangential law (springSliding: stock history's physics) and with
  # cmd_tangential; the classical laws' rows are added below
  "seh|$sph|hertz_elliptic|10000|1|-var jitter 2e-4"
  "sep|$sph|hertz_elliptic|10000|1|-var jitter 2e-4 -var tkey contactPatch -var tval on"
  "stc|$sph|hertz_elliptic|10000|1|-var tmodel cmd_tangential -var jitter 2e-4"
  # rough tangential: gw_rough gwElliptic on with cmd_tangential, without and
  # with tangentialRoughness on (the summits' stiffness, also before touch:
  # friction then acts on the contacts within 3 sigma that do not touch),
  # and the same at sigma = 1e-12 m (the same contacts and trajectory as
  # smooth: the setting's own cost per contact)
  "srt|$sph|gw_rough|10000|1|-var cdf 1.12 -var gwe 1 -var tmodel cmd_tangential -var jitter 2e-4"
  "srr|$sph|gw_rough|10000|1|-var cdf 1.12 -var gwe 1 -var tmodel cmd_tangential -var jitter 2e-4 -var tkey tangentialRoughness -var tval on"
  "srt0|$sph|gw_rough|10000|1|-var cdf 1.0001 -var sigma 1e-12 -var gwe 1 -var tmodel cmd_tangential -var jitter 2e-4"
  "srr0|$sph|gw_rough|10000|1|-var cdf 1.0001 -var sigma 1e-12 -var gwe 1 -var tmodel cmd_tangential -var jitter 2e-4 -var tkey tangentialRoughness -var tval on"
  # control: configuration se again, last in the round-robin; its time
  # against se is what a best-of-REPS ratio carries as noise on this machine
  "se_again|$sph|hertz_elliptic|10000|1|"
)
classical_laws="springSliding coulomb viscous viscousSliding springDashpotSliding diRenzo langston zheng tsuji incremental"
for law in $classical_laws; do
  configs+=("sc_$law|$sph|hertz_elliptic|10000|1|-var tmodel classical -var jitter 2e-4 -var tkey classicalTangential -var tval $law")
done
contact_rows="sth seh sep st stc stp qe qt qtp sst ssh sre sra spe spa rt rk0 se sjp sje ssc ssc2 srt srr srt0 srr0"
for law in $classical_laws; do contact_rows="$contact_rows sc_$law"; done
[ "${DC_BENCH_ONLY:-}" = contact ] && DC_BENCH_ONLY="$contact_rows se_again"
# untimed preparation of the settled scenes: once per restart file named by
# a configuration that runs
for c in "${configs[@]}"; do
  IFS='|' read -r name deck model steps ranks extra <<< "$c"
  if [ -n "${DC_BENCH_ONLY:-}" ] && [[ " $DC_BENCH_ONLY " != *" $name "* ]]; then continue; fi
  [[ "$extra" == *"-var rfile "* ]] || continue
  rf=${extra#*-var rfile }; rf=${rf%% *}
  [ -s "$rf" ] && continue
  d="$work/prep_$name"; mkdir -p "$d"; cd "$d"
  echo "preparing $(basename "$rf") (untimed)" >&2
  mpirun ${DC_BENCH_MPIRUN:-} -np 2 "$lmp" -in "$deck" -var model "$model" -var prep 1 $extra -log log > screen.txt 2>&1 \
    || { echo "preparation of $rf failed, see below" >&2; tail -20 screen.txt >&2; exit 1; }
done
base=${DC_BENCH_BASELINE:-}
declare -A best
for r in $(seq "$reps"); do
  for c in "${configs[@]}"; do
    IFS='|' read -r name deck model steps ranks extra <<< "$c"
    if [ -n "${DC_BENCH_ONLY:-}" ] && [[ " $DC_BENCH_ONLY " != *" $name "* ]]; then continue; fi
    for which in new ${base:+base}; do
      exe=$lmp; key=$name
      [ "$which" = base ] && { exe=$base; key="base_$name"; }
      d="$work/${key}_$r"; mkdir -p "$d"; cd "$d"
      if [ "$ranks" -gt 1 ]; then
        mpirun ${DC_BENCH_MPIRUN:-} -np "$ranks" "$exe" -in "$deck" -var model "$model" -var steps "$steps" $extra -log log > screen.txt 2>&1 \
          || { echo "bench: $key ($exe) failed, see below" >&2; tail -20 screen.txt >&2; exit 1; }
      else
        "$exe" -in "$deck" -var model "$model" -var steps "$steps" $extra -log log > screen.txt 2>&1 \
          || { echo "bench: $key ($exe) failed, see below" >&2; tail -20 screen.txt >&2; exit 1; }
      fi
      t=$(awk '/^Loop time of/ {print $4}' log)
      best[$key]=$(python3 -c "print(min(float('$t'), float('${best[$key]:-1e300}')))")
    done
  done
done
# instruction counts: one callgrind run per 1-rank configuration that ran
declare -A ins
if [ -n "${DC_BENCH_INSTRUCTIONS:-}" ]; then
  for c in "${configs[@]}"; do
    IFS='|' read -r name deck model steps ranks extra <<< "$c"
    if [ -n "${DC_BENCH_ONLY:-}" ] && [[ " $DC_BENCH_ONLY " != *" $name "* ]]; then continue; fi
    [ "$ranks" -eq 1 ] && [ "$name" != se_again ] || continue
    d="$work/cg_$name"; mkdir -p "$d"; cd "$d"
    echo "counting instructions: $name" >&2
    valgrind --tool=callgrind --toggle-collect='LAMMPS_NS::Verlet::run(int)' --callgrind-out-file=cg.out \
      "$lmp" -in "$deck" -var model "$model" -var steps "$steps" $extra -log log > screen.txt 2>&1 \
      || { echo "bench: callgrind run of $name failed, see below" >&2; tail -20 screen.txt >&2; exit 1; }
    ins[$name]=$(awk '/^(summary|totals):/ {print $2; exit}' cg.out)
  done
fi
args=()
for k in "${!best[@]}"; do args+=("$k=${best[$k]}"); done
for k in "${!ins[@]}"; do args+=("ins_$k=${ins[$k]}"); done
python3 - "${args[@]}" <<'PY'
import sys
t = dict(a.split("=") for a in sys.argv[1:])
def row(fmt, *names):
    if all(n in t for n in names):
        v = [float(t[n]) for n in names]
        print(fmt(*v))
    else:
        print("n/a (not run): " + " ".join(names))
print("scene (best of runs, loop time)                     stock hertz  hertz_elliptic  ratio")
row(lambda sh, se: "2888 spheres settling, 10000 steps, 1 rank          %9.3f s   %9.3f s     %.4f" % (sh, se, se / sh), "sh", "se")
row(lambda qh, qe: "324 superquadrics settling, 15000 steps, 1 rank     %9.3f s   %9.3f s     %.4f" % (qh, qe, qe / qh), "qh", "qe")
row(lambda sr, sh: "2888 spheres: gw_rough (tabulated GW law, sigma = 0.01 r) %.3f s = %.4f x stock hertz" % (sr, sr / sh), "sr", "sh")
row(lambda sh5, sr: "    same contact distance (1.09): stock hertz %.3f s; gw_rough = %.4f x" % (sh5, sr / sh5), "sh5", "sr")
row(lambda sra, sre: "2888 spheres: gw_rough gwElliptic on + cohesion gw_adhesion (w = 0.05 J/m^2, contact distance 1.12) "
    "%.3f s = %.4f x gw_rough gwElliptic on (%.3f s)" % (sra, sra / sre, sre)
    + "".join(", %.4f x gw_rough (default law, contact distance %s)" % (sra / float(t[k]), cd)
              for k, cd in (("sr", "1.09"), ("sr2", "1.12")) if k in t), "sra", "sre")
row(lambda spa, spe: "    polydisperse (d 2.6-3.4 mm, contact distance 1.14): with cohesion %.3f s = %.4f x gw_rough "
    "gwElliptic on (%.3f s)" % (spa, spa / spe, spe), "spa", "spe")
row(lambda sh1, sr0: "    sigma = 1e-12 m (same trajectory as Hertz), contact distance 1.0001: stock hertz %.3f s, "
    "gw_rough %.3f s = %.4f x" % (sh1, sr0, sr0 / sh1), "sh1", "sr0")
row(lambda sj, se: "2888 spheres: jkr_elliptic (w = 0.05 J/m^2) %.3f s = %.4f x hertz_elliptic" % (sj, sj / se), "sj", "se")
row(lambda sjd, sj: "    adhesionLaw dmt: %.3f s = %.4f x jkr_elliptic (JKR)" % (sjd, sjd / sj), "sjd", "sj")
row(lambda sjd0, sj0: "    adhesionLaw dmt, w = 1e-9 (the Hertz trajectory): %.3f s = %.4f x jkr_elliptic (JKR)" % (sjd0, sjd0 / sj0),
    "sjd0", "sj0")
row(lambda sjm, sj: "    adhesionLaw maugis (lambda 0.73-0.92): %.3f s = %.4f x jkr_elliptic (JKR)" % (sjm, sjm / sj), "sjm", "sj")
row(lambda sjm0, sj0: "    adhesionLaw maugis, w = 1e-9 (the Hertz trajectory): %.3f s = %.4f x jkr_elliptic (JKR)"
    % (sjm0, sjm0 / sj0), "sjm0", "sj0")
row(lambda se2, sj0: "    w = 1e-9 J/m^2 (same trajectory as Hertz), contact distance 1.02: hertz_elliptic %.3f s, "
    "jkr_elliptic %.3f s = %.4f x" % (se2, sj0, sj0 / se2), "se2", "sj0")
row(lambda sjp, sh: "2888 spheres: jamari_ep (hardness 1e5 Pa: plastic) %.3f s = %.4f x stock hertz" % (sjp, sjp / sh), "sjp", "sh")
row(lambda qra, qre: "324 rough superquadrics settling, 15000 steps: cohesion gw_adhesion %.3f s = %.4f x gw_rough "
    "gwElliptic on alone (%.3f s)" % (qra, qra / qre, qre), "qra", "qre")
row(lambda qe, q2: "324 superquadrics, hertz_elliptic: 1 rank %.3f s, 2 ranks %.3f s, speed-up %.3f" % (qe, q2, qe / q2), "qe", "q2")
row(lambda sth, st: "2888 spheres (jittered), hertz: tangential history %.3f s, cmd_tangential %.3f s = %.4f x"
    % (sth, st, st / sth), "sth", "st")
row(lambda qe, qt: "324 superquadrics, hertz_elliptic: tangential history %.3f s, cmd_tangential %.3f s = %.4f x"
    % (qe, qt, qt / qe), "qe", "qt")
row(lambda rt, rk: "1568 spheres rolling down a 15 degree incline, hertz_elliptic + cmd_tangential: no rolling model "
    "%.3f s, rolling_friction kalker %.3f s = %.4f x" % (rt, rk, rk / rt), "rt", "rk")
row(lambda rt, rk0: "    kalker with nothing rolling (rollingVelocityMin 1e3: cmd_tangential everywhere, plus the "
    "hand-over's kinematics) %.3f s = %.4f x" % (rk0, rk0 / rt), "rt", "rk0")
for tag, what, n in (("ss", "3264 spheres, settled bed", 20000), ("sq", "1056 superquadrics (blockiness 4 4), settled bed", 10000)):
    row(lambda h, e: "%s, %d steps, 1 rank %9.3f s   %9.3f s     %.4f" % (what, n, h, e, e / h), tag + "h", tag + "e")
    row(lambda h, e: "%s, %d steps, 2 ranks %9.3f s   %9.3f s     %.4f" % (what, n, h, e, e / h), tag + "h2", tag + "e2")
    row(lambda h, h2, e, e2: "    speed-up 2 ranks / 1 rank: stock hertz %.3f, hertz_elliptic %.3f" % (h / h2, e / e2),
        tag + "h", tag + "h2", tag + "e", tag + "e2")
row(lambda h, e, r: "    superquadrics, hertz_elliptic with curvatureTolerance 1e-4, 1 rank %9.3f s = %.4f x stock hertz "
    "(%.4f x without)" % (r, r / h, e / h), "sqh", "sqe", "sqr")
# the whole-contact table: each sub-model's run against its reference run
contact = [("hertz_elliptic + tangential history", "seh", "sth", None),
           ("hertz_elliptic + classical springSliding (stock's physics)", "sc_springSliding", "sth", 1.03)]
contact += [("hertz_elliptic + classical %s" % k[3:], k, "sth", 1.06) for k in sorted(t) if k.startswith("sc_")
            and k != "sc_springSliding" and not k.startswith("base_")]
contact += [("stock hertz + cmd_tangential", "st", "sth", None),
            ("hertz_elliptic + cmd_tangential", "stc", "sth", 1.25),
            ("hertz_elliptic + cmd_tangential cmdMemory turningPoints", "stp", "sth", 1.10),
            ("superquadrics: cmd_tangential over hertz_elliptic + history", "qt", "qe", 1.08),
            ("superquadrics: cmdMemory turningPoints over hertz_elliptic + history", "qtp", "qe", 1.05),
            ("settled bed (3264): hertz_elliptic + cmd_tangential over stock hertz + history", "ssc", "ssh", None),
            ("settled bed (3264): cmdMemory turningPoints over stock hertz + history", "sst", "ssh", 1.10),
            ("contactPatch on over off (hertz_elliptic + history)", "sep", "seh", 1.02),
            ("cohesion gw_adhesion over gw_rough gwElliptic on", "sra", "sre", 1.12),
            ("    polydisperse", "spa", "spe", 1.12),
            ("rolling_friction kalker, nothing rolling, over none", "rk0", "rt", 1.03),
            ("jamari_ep (plastic) over hertz_elliptic (unjittered)", "sjp", "se", 1.10),
            ("    jamari_ep below yield (the Hertz trajectory) over hertz_elliptic", "sje", "se", None),
            ("speed-up 1 rank / 2 ranks, settled bed (3264), hertz_elliptic + cmd_tangential", "ssc", "ssc2", -1.85),
            ("gw_rough gwElliptic on + cmd_tangential, sigma 1e-12: tangentialRoughness on over off", "srr0", "srt0", 1.05),
            ("    sigma 1.5e-5 per sphere (friction also before touch)", "srr", "srt", None)]
if any(k in t for _, k, _, _ in contact):
    print()
    print("whole-contact cost (2888 spheres jittered 2e-4, 10000 steps, 1 rank, unless named; best of runs)")
    print("%-72s %9s %9s %8s %8s %7s" % ("configuration / against", "time", "against", "ratio", "instr.", "target"))
    for what, k, ref, target in contact:
        if k not in t or ref not in t:
            continue
        r = float(t[k]) / float(t[ref])
        ri = "%.4f" % (float(t["ins_" + k]) / float(t["ins_" + ref])) if "ins_" + k in t and "ins_" + ref in t else "n/a"
        goal = "" if not target else "<= %.2f" % target if target > 0 else ">= %.2f" % -target
        print("%-72s %8.3fs %8.3fs %8.4f %8s %7s" % (what + " / " + ref, float(t[k]), float(t[ref]), r, ri, goal))
    if "ins_sth" in t:
        print("instructions (callgrind, inside Verlet::run): " +
              ", ".join("%s %.4g" % (k[4:], float(v)) for k, v in sorted(t.items()) if k.startswith("ins_")))
row(lambda se, sa: "control: the same configuration (spheres, hertz_elliptic) run twice, second and last in the "
    "round-robin: %.3f s and %.3f s, ratio %.4f (the noise in this run's ratios)" % (se, sa, sa / se), "se", "se_again")
PY
if [ -n "$base" ]; then
  echo
  echo "configuration        baseline       this build     ratio (best of $reps, same round-robin)"
  for c in "${configs[@]}"; do
    IFS='|' read -r name deck model steps ranks extra <<< "$c"
    if [ -n "${DC_BENCH_ONLY:-}" ] && [[ " $DC_BENCH_ONLY " != *" $name "* ]]; then continue; fi
    python3 -c "print('%-20s %9.3f s    %9.3f s     %.4f' % ('$name $model', ${best[base_$name]}, ${best[$name]}, ${best[$name]} / ${best[base_$name]}))"
  done
fi
