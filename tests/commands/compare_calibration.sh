#!/usr/bin/env bash
# compare_calibration.sh GLINT SCENE WORK_DIR: `glint compare` is calibrated at the
# settings of validate.cycles (64x64): two independent pairs of glint renders agree; the
# same scaled by 1.005 disagree with terminal walls, by 1.01 with diffuse walls.
set -euo pipefail
glint=$1
scene=$2
work=$3
mkdir -p "$work"
cd "$work"
fail=0
calibrate() {  # walls spp scale
  local walls=$1 spp=$2 scale=$3
  for seed in 11 12 13 14; do
    "$glint" render "$scene" --mode mc --walls "$walls" --size 64 --spp "$spp" --seed "$seed" \
      -q -o "$walls-$seed.pfm"
  done
  # Exit 0: agree; exit 3: disagree (kExitDisagree); anything else (a bad option, an
  # unreadable file) is an error of the test, never "a bias seen".
  local code
  echo "$walls walls, unscaled:"
  code=0
  "$glint" compare "$walls-11.pfm" "$walls-12.pfm" "$walls-13.pfm" "$walls-14.pfm" || code=$?
  [ "$code" -eq 0 ] || { echo "compare_calibration: independent renders: exit $code, expected 0"; fail=1; }
  echo "$walls walls, A and B scaled by $scale:"
  code=0
  "$glint" compare "$walls-11.pfm" "$walls-12.pfm" "$walls-13.pfm" "$walls-14.pfm" \
    --scale "$scale" || code=$?
  if [ "$code" -ne 3 ]; then
    echo "compare_calibration: a bias of $scale: exit $code, expected 3 (disagree)"
    fail=1
  fi
}
calibrate terminal 1024 1.005
calibrate diffuse 4096 1.01
exit $fail
