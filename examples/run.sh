#!/usr/bin/env bash
# Builds what is needed (plugin/setup.sh: Debian packages, the LIGGGHTS
# source, c_core and LIGGGHTS with the plugin models), runs the main
# example, examples/superquadric_settling, on two MPI ranks, and converts
# its dumps for ParaView (tools/dump2vtk.py).
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
echo "run: converting the dumps for ParaView"
python3 "$root/tools/dump2vtk.py" 'post/dump*.sq' 'post/contacts*.local' --log log.liggghts -o paraview --surfaces 8
echo
echo "run: results in $out:"
echo "  settling.txt         step, kinetic energy, mean and max height every 1000 steps"
echo "  post/dump*.sq        particle positions, orientations, shapes, velocities and forces"
echo "  post/contacts*.local the contact network (compute pair/gran/local with the contact patch)"
echo "  log.liggghts         the LIGGGHTS log"
echo "  ParaView (File > Open; doc/paraview.md says how to draw them):"
echo "    $out/paraview/particles.pvd          particles as points (shape, blockiness, quat, sq_tensor, v, f)"
echo "    $out/paraview/particles_surface.pvd  the particles' surfaces as polygons"
echo "    $out/paraview/contacts.pvd           the contact network: lines with force and contact patch"
