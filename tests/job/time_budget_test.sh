#!/usr/bin/env bash
# time_budget_test.sh GLINT SCENE: `render --time` fills its budget with passes that
# double (1, 2, 4, ... rays per pixel) without overspending it, and with --spp keeps
# passes of that size; --stats reports the rays per pixel of all the passes.
set -u
glint=$1
scene=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
field() { sed -n "s/.*\"$1\": \([0-9.]*\).*/\1/p" "$dir/t.json"; }
if ! "$glint" render "$scene" --mode mc --size 32 --time 0.5 -o "$dir/t.png" \
     --stats "$dir/t.json" -q; then
  echo "FAIL: glint render --time"
  exit 1
fi
spp=$(field spp); passes=$(field passes); seconds=$(field seconds); camera=$(field camera)
echo "doubling: $spp rays/pixel in $passes passes, $seconds s"
python3 - "$spp" "$passes" "$seconds" "$camera" 32 <<'PY' || exit 1
import sys
spp, passes, seconds, camera, size = (float(a) for a in sys.argv[1:])
ok = True
if seconds > 0.5: print(f"FAIL: {seconds} s is over the 0.5 s budget"); ok = False
if camera != spp * size * size: print(f"FAIL: {camera} camera rays for {spp} rays/pixel"); ok = False
# Doubling reaches n rays per pixel in about log2(n) passes (plus a few smaller ones
# at the end); passes of one ray would take n.
if not passes < spp / 8: print(f"FAIL: {passes} passes for {spp} rays/pixel"); ok = False
sys.exit(0 if ok else 1)
PY
if ! "$glint" render "$scene" --mode mc --size 32 --time 0.2 --spp 3 -o "$dir/t.png" \
     --stats "$dir/t.json" -q; then
  echo "FAIL: glint render --time --spp 3"
  exit 1
fi
spp=$(field spp); passes=$(field passes)
echo "fixed: $spp rays/pixel in $passes passes"
if [ "$spp" != $((passes * 3)) ]; then
  echo "FAIL: passes of --spp 3 should give 3 x $passes rays/pixel, not $spp"
  exit 1
fi
echo "PASS"
