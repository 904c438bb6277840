#!/usr/bin/env bash
# Builds what is needed (plugin/setup.sh: Debian packages, the LIGGGHTS
# source, c_core and LIGGGHTS with the plugin models) and runs the main
# example, examples/superquadric_settling, on two MPI ranks.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/plugin/setup.sh"
out="$root/build/examples/superquadric_settling"
mkdir -p "$out"
cd "$out"
echo "run: examples/superquadric_settling on 2 MPI ranks (about half a minute)"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
extra=""
[ "$(nproc)" -ge 2 ] || extra="--oversubscribe"
mpirun -np 2 $extra "$root/build/bin/liggghts" -in "$root/examples/superquadric_settling/in.superquadric_settling" -log log.liggghts
echo
echo "run: results in $out:"
echo "  settling.txt    step, kinetic energy, mean and max height every 1000 steps"
echo "  post/dump*.sq   particle positions, orientations, shapes and forces"
echo "  log.liggghts    the LIGGGHTS log"
