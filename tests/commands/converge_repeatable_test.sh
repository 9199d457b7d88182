#!/usr/bin/env bash
# converge_repeatable_test.sh GLINT SCENE: the same glint converge run twice, with one core
# kept busy by another process, gives slopes that agree within their error bars
# (|s1 - s2| < 3 sqrt(se1^2 + se2^2): the error bars are honest, and short rungs do not
# swing with one preempted time slice), and says the machine was busy.
set -eu
glint=$1
scene=$2
dir=$(mktemp -d)
busy() { while :; do :; done; }
busy &
hog=$!
trap 'kill $hog 2>/dev/null || true; rm -rf "$dir"' EXIT
cd "$dir"
"$glint" render "$scene" --mode mc --size 64 --spp 4096 --seed 99 -q -o ref.pfm
for compare in strategy=mis,brdf sampler=random,sobol; do
  for run in 1 2; do
    "$glint" converge "$scene" --mode mc --size 64 --ladder 1,2,4,8,16,32,64,128 \
      --compare "$compare" --reference ref.pfm --csv "$compare-$run.csv" --chart "" \
      > "$compare-$run.out" 2> "$compare-$run.err"
    cat "$compare-$run.out"
  done
done
kill $hog
/usr/bin/python3 - <<'PY'
import csv, glob, math
status = 0
for first in sorted(glob.glob("*-1.csv")):
    second = first[:-6] + "-2.csv"
    a = {r["variant"]: r for r in csv.DictReader(open(first))}
    b = {r["variant"]: r for r in csv.DictReader(open(second))}
    for v in a:
        for key in ("slope_rel_mse_time", "slope_rmse_time"):
            s1, e1 = float(a[v][key]), float(a[v][key + "_se"])
            s2, e2 = float(b[v][key]), float(b[v][key + "_se"])
            z = abs(s1 - s2) / math.sqrt(e1 * e1 + e2 * e2) if e1 + e2 > 0 else math.inf
            ok = z < 3
            status |= not ok
            print(f"{v} {key}: {s1:.3f} ± {e1:.3f} and {s2:.3f} ± {e2:.3f}: "
                  f"{z:.2f} standard errors apart {'ok' if ok else 'FAIL'}")
    busy = max(float(r["other_cores"]) for r in csv.DictReader(open(first)))
    print(f"{first}: other processes took up to {busy:.0%} of a core")
    if busy < 0.5:
        print("FAIL: the busy loop did not show in other_cores")
        status = 1
raise SystemExit(status)
PY
grep -q "the machine was busy" ./*-1.err || { echo "FAIL: no busy warning"; exit 1; }
