#!/usr/bin/env bash
# converge_test.sh GLINT SCENE: a small convergence study writes a well-formed CSV with
# every variant and rung, a PNG chart, and error that falls as rays per pixel grow.
set -eu
glint=$1
scene=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
"$glint" render "$scene" --mode mc --size 32 --spp 1024 -q -o ref.pfm
"$glint" converge "$scene" --mode mc --reference ref.pfm --ladder 1,4,16,64 \
  --compare strategy=mis,light,brdf --csv c.csv --chart c.png
head -1 c.csv | grep -q '^variant,step,spp,seconds,rmse,rel_mse,block_rmse,bias_r,bias_g,bias_b,firefly_ratio,rel_mse_se,seconds_min,seconds_max,cpu_seconds,repeats,other_cores,slope_rel_mse_time,slope_rel_mse_time_se,slope_rmse_time,slope_rmse_time_se,slope_rel_mse_spp,slope_rel_mse_spp_se,warning$'
[ "$(tail -n +2 c.csv | wc -l)" -eq 12 ] || { echo "FAIL: expected 12 rows"; exit 1; }
for v in mis light brdf; do
  first=$(grep "^strategy=$v,0," c.csv | cut -d, -f5)
  last=$(grep "^strategy=$v,3," c.csv | cut -d, -f5)
  # 64x the rays: the RMSE must at least halve (1/sqrt(64) = 1/8 expected).
  awk -v a="$first" -v b="$last" 'BEGIN { exit !(b < 0.5 * a) }' || { echo "FAIL: $v: $first -> $last"; exit 1; }
done
head -c 8 c.png | grep -q PNG || { echo "FAIL: no chart"; exit 1; }
"$glint" converge "$scene" --reference ref.pfm --ladder 4,2 2>&1 | grep -q "increasing positive numbers" || { echo "FAIL: bad ladder accepted"; exit 1; }
echo "converge: ok"
