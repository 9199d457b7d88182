#!/usr/bin/env bash
# converge_compare_test.sh GLINT SCENE SWITCH VALUES [RENDER FLAGS...]: `glint converge
# --compare SWITCH=VALUES` against a Monte Carlo reference of the same scene and flags (a
# long glint render with another seed): one row per value and rung, and for each value
# relative MSE that falls with the rays and ends small. A Whitted reference would give
# relative MSEs of order 1 that fall nowhere, and a grep for "relative MSE" would pass.
set -eu
glint=$1
scene=$2
switch=$3
values=$4
shift 4
flags=("$@")
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
"$glint" render "$scene" --mode mc "${flags[@]}" --size 48 --spp 4096 --seed 77 -q -o ref.pfm
"$glint" converge "$scene" --mode mc "${flags[@]}" --size 48 --reference ref.pfm \
  --ladder 4,64 --compare "$switch=$values" --csv c.csv --chart c.png
rows=$(tail -n +2 c.csv | wc -l)
count=$(echo "$values" | tr ',' '\n' | wc -l)
[ "$rows" -eq $((2 * count)) ] || { echo "FAIL: $rows rows, expected $((2 * count))"; exit 1; }
status=0
for v in $(echo "$values" | tr ',' ' '); do
  first=$(grep "^$switch=$v,0," c.csv | cut -d, -f6)
  last=$(grep "^$switch=$v,1," c.csv | cut -d, -f6)
  echo "$switch=$v: relative MSE $first at 4 rays/pixel, $last at 64"
  # 16x the rays: relative MSE at least 3x lower (16x for an unbiased estimator against
  # an exact reference; the reference's own noise and a sampler's head start take some),
  # and below 0.2 at 64 rays per pixel. Against a reference of the other mode both fail.
  awk -v a="$first" -v b="$last" 'BEGIN { exit !(b < a / 3 && b < 0.2) }' \
    || { echo "FAIL: $switch=$v: relative MSE $first -> $last"; status=1; }
done
head -c 8 c.png | grep -q PNG || { echo "FAIL: no chart"; status=1; }
exit $status
