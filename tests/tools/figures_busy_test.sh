#!/usr/bin/env bash
# figures_busy_test.sh SOURCE_DIR GLINT OUT: the scaling study, run while two other
# processes keep both cores busy, says the machine was busy instead of stating a speedup
# as glint's; and --only refuses a study it does not know.
set -eu
src=$1
glint=$2
out=$3
busy() { while :; do :; done; }
busy &
one=$!
busy &
two=$!
trap 'kill $one $two 2>/dev/null || true' EXIT
rm -rf "$out"
"$src/tools/figures" --quick --only scaling --glint "$glint" --out "$out"
kill $one $two
grep -q "The machine was busy ([0-9]*% of a core taken by other processes): the speedup is not glint's alone" \
  "$out/README.md" || { echo "FAIL: no busy caption: $(cat "$out/README.md")"; exit 1; }
/usr/bin/python3 "$src/tests/tools/captions_check.py" "$out"
if "$src/tools/figures" --only scalng --out "$out" 2> err.txt; then
  echo "FAIL: --only scalng accepted"; exit 1
fi
grep -q "no study 'scalng'" err.txt || { echo "FAIL: $(cat err.txt)"; exit 1; }
