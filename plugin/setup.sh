#!/usr/bin/env bash
# Installs what the project needs (Debian packages, the LIGGGHTS and LAMMPS
# sources) and builds c_core, the tools, a LIGGGHTS executable with the
# plugin models (plugin/liggghts) into build/ and a LAMMPS executable with
# the project's sub-models (plugin/lammps) into build/lammps/. Re-running
# reuses build/ and ccache: only what changed rebuilds.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

# python3-vtk9: VTK's Python bindings for the system python3, with which
# tests/regression/check_paraview.py reads the ParaView files back;
# python3-matplotlib: the plotting library with which dclaw plot draws PNGs
# (c_core/cli/plot.py) and the speed-versus-error report
# (tests/bench/report.sh) its plots; python3-numpy: the report measures the
# packings of its LIGGGHTS scenes with it
packages="build-essential cmake ccache dpkg-dev patch xz-utils libopenmpi-dev openmpi-bin libgsl-dev python3 python3-vtk9 python3-matplotlib python3-numpy"
missing=""
for p in $packages; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "setup: installing Debian packages:$missing"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q >/dev/null
  apt-get install -y -q $missing >/dev/null
fi

"$root/plugin/liggghts/fetch_liggghts.sh" "$root/.deps/liggghts-3.8.0"

mkdir -p "$root/build"
# DC_DECKS: the user's decks (space-separated paths) whose contact-model
# combinations are compiled too (kept for later builds)
user_decks=()
for d in ${DC_DECKS:-}; do
  [ -f "$d" ] || { echo "setup: DC_DECKS: no deck $d" >&2; exit 1; }
  user_decks+=("$(cd "$(dirname "$d")" && pwd)/$(basename "$d")")
done
decks_arg=()
[ -n "${DC_DECKS:-}" ] && decks_arg=("-DDC_USER_DECKS=$(IFS=';'; echo "${user_decks[*]}")")
export CCACHE_BASEDIR="$root"
export CCACHE_MAXSIZE=${CCACHE_MAXSIZE:-4G}
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release -DDC_WITH_LIGGGHTS=ON \
      -DLIGGGHTS_SOURCE_DIR="$root/.deps/liggghts-3.8.0" "${decks_arg[@]}" \
      -DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache >"$root/build/configure.log" 2>&1 \
  || { cat "$root/build/configure.log"; exit 1; }
echo "setup: building (first build of LIGGGHTS takes several minutes on 2 cores; log in build/build.log)"
if ! cmake --build "$root/build" -j"$(nproc)" >"$root/build/build.log" 2>&1; then
  grep -E "error|Error" "$root/build/build.log" | head -40
  echo "setup: build failed, see build/build.log" >&2
  exit 1
fi
echo "setup: built $root/build/bin/liggghts and $root/build/c_core/dclaw"
"$root/plugin/lammps/build.sh"
