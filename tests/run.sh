#!/usr/bin/env bash
# Builds everything (plugin/setup.sh) and runs every test: c_core unit tests,
# regression decks (1 and 2 MPI ranks). Ends with 'N passed, N failed'.
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/plugin/setup.sh" || exit 1
cd "$root/build"
ctest --output-on-failure -j1 2>&1 | tee ctest.log
total=$(grep -Eo "tests failed out of [0-9]+" ctest.log | grep -Eo "[0-9]+$")
failed=$(grep -Eo "[0-9]+ tests failed out of" ctest.log | grep -Eo "^[0-9]+")
total=${total:-0}; failed=${failed:-0}
echo "tests: $((total - failed)) passed, $failed failed"
[ "$total" -gt 0 ] && [ "$failed" -eq 0 ]
