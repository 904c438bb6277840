#!/usr/bin/env bash
# Builds LAMMPS (stable 4 Feb 2025: GRANULAR, MPI) with the project's
# GRANULAR sub-models (plugin/lammps/GRANULAR) and c_core into build/lammps
# (executable build/lammps/lmp). Fetches the source first
# (plugin/lammps/fetch_lammps.sh). ccache keeps rebuilds short: the first
# build compiles about 420 files (5 minutes on 2 idle cores, more on busy ones), a rebuild
# with a warm cache takes about a minute. Called by plugin/setup.sh.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
src="$root/.deps/lammps-4Feb2025"
out="$root/build/lammps"
"$root/plugin/lammps/fetch_lammps.sh" "$src"

# the project's sub-models into LAMMPS' GRANULAR package (only changed files
# are rewritten; files of ours that left the project are removed)
pkg="$src/src/GRANULAR"
for f in "$pkg"/gran_sub_mod_dc_* "$pkg"/dc_*; do
  [ -e "$f" ] && [ ! -e "$root/plugin/lammps/GRANULAR/$(basename "$f")" ] && rm -f "$f"
done
for f in "$root"/plugin/lammps/GRANULAR/*; do
  install -C -m 644 "$f" "$pkg/"
done

mkdir -p "$out"
export CCACHE_BASEDIR="$root"
export CCACHE_MAXSIZE=${CCACHE_MAXSIZE:-4G}
cmake -S "$src/cmake" -B "$out" -DCMAKE_BUILD_TYPE=Release -DBUILD_MPI=yes -DBUILD_OMP=no \
      -DPKG_GRANULAR=yes -DWITH_JPEG=no -DWITH_PNG=no -DWITH_FFMPEG=no -DWITH_GZIP=no -DBUILD_TOOLS=no \
      -DDC_ROOT="$root" -DCMAKE_PROJECT_lammps_INCLUDE="$root/plugin/lammps/dc_lammps.cmake" \
      -DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache >"$out/configure.log" 2>&1 \
  || { cat "$out/configure.log"; exit 1; }
echo "setup: building LAMMPS with the project's sub-models (the first build takes about 5 minutes on 2 idle cores; log in build/lammps/build.log)"
if ! cmake --build "$out" -j"$(nproc)" --target lmp >"$out/build.log" 2>&1; then
  grep -E "error|Error" "$out/build.log" | head -40
  echo "setup: LAMMPS build failed, see build/lammps/build.log" >&2
  exit 1
fi
echo "setup: built $out/lmp"
