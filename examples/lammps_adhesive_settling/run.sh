#!/usr/bin/env bash
# The LAMMPS example: builds what is needed (plugin/setup.sh: both engines),
# runs examples/lammps_adhesive_settling on two MPI ranks with the project's
# LAMMPS sub-models and converts its dumps for ParaView (tools/dump2vtk.py).
# Usage: bash examples/lammps_adhesive_settling/run.sh [OUTDIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
"$root/plugin/setup.sh"
out=${1:-$root/build/examples/lammps_adhesive_settling}
mkdir -p "$out"
cd "$out"
echo "run: examples/lammps_adhesive_settling in LAMMPS on 2 MPI ranks (about 3 minutes)"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
extra=""
[ "$(nproc)" -ge 2 ] || extra="--oversubscribe"
mpirun -np 2 $extra "$root/build/lammps/lmp" -in "$root/examples/lammps_adhesive_settling/in.lammps_adhesive_settling" \
  -log log.lammps -nocite
echo
echo "run: converting the dumps for ParaView"
python3 "$root/tools/dump2vtk.py" 'post/dump*.adh' -o paraview --surfaces 8 --dt 2e-7
echo
echo "run: results in $out:"
echo "  settling.txt     time, contacts, kinetic energy, mean and max height every 5000 steps"
echo "  post/dump*.adh   particle positions, radii, velocities, angular velocities, forces, contacts per atom"
echo "  log.lammps       the LAMMPS log"
echo "  ParaView (File > Open; doc/paraview.md says how to draw them):"
echo "    $out/paraview/particles.pvd          particles as points (radius, v, omega, f, c_nc)"
echo "    $out/paraview/particles_surface.pvd  the particles' surfaces as polygons"
