#!/usr/bin/env bash
# converge_checks_test.sh GLINT SCENE: what glint converge measures and warns about.
# Every rung repeated (at least 3 runs, the median between the fastest and the slowest),
# a slope with a finite standard error in every row; warnings, on stderr and in the
# CSV's warning column, for a ladder of fewer than 4 rungs, for rungs that could not
# run the floor of 0.2 s, and for a reference whose mean is off by more than 2x.
set -eu
glint=$1
scene=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
status=0
fail() { echo "FAIL: $*"; status=1; }
"$glint" render "$scene" --mode mc --size 48 --spp 512 --seed 5 -q -o ref.pfm

# A good study: no warning (but that the machine was busy: ctest runs other tests beside
# this one); rows well formed.
"$glint" converge "$scene" --mode mc --reference ref.pfm --ladder 1,4,16,64 \
  --csv good.csv --chart "" > good.out 2> good.err
# (On a busy machine the slope's error bar may pass 0.1: that warning is then right.)
if grep -q "the machine was busy" good.err; then busy=1; else busy=0; fi
expected="the machine was busy"
[ $busy = 1 ] && expected="$expected|standard error"
grep "warning" good.err | grep -Ev "$expected" | grep -q . && fail "warnings in a good study: $(cat good.err)"
/usr/bin/python3 - good.csv $busy <<'PY' || status=1
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
busy = sys.argv[2] == "1"
assert len(rows) == 4, len(rows)
for r in rows:
    lo, med, hi = float(r["seconds_min"]), float(r["seconds"]), float(r["seconds_max"])
    assert int(r["repeats"]) >= 3, r
    assert lo <= med <= hi, r
    assert int(r["repeats"]) * med >= 0.2 * 0.5, r  # the floor, give or take the spread
    assert float(r["cpu_seconds"]) > 0, r
    for k in ("slope_rel_mse_time", "slope_rel_mse_time_se", "slope_rel_mse_spp_se"):
        assert math.isfinite(float(r[k])), (k, r)
    assert 0 < float(r["slope_rel_mse_time_se"]) < (2.0 if busy else 0.5), r
    allowed = ("the machine was busy", "standard error") if busy else ("the machine was busy",)
    assert all(any(a in w for a in allowed) for w in r["warning"].split("; ") if w), r
print("good study: ok")
PY
grep -q "default: slope -[0-9.]* ± [0-9.]* of log relative MSE against log seconds" good.out \
  || fail "no slope with its error bar on stdout: $(cat good.out)"

# Three rungs: a slope says little.
"$glint" converge "$scene" --mode mc --reference ref.pfm --ladder 1,4,16 --csv few.csv \
  --chart "" > /dev/null 2> few.err
grep -q "warning: default: a slope through 3 rungs says little" few.err || fail "3 rungs: $(cat few.err)"
grep -q "a slope through 3 rungs says little" few.csv || fail "3 rungs: not in the CSV"

# 4x4 pixels on one thread: a rung runs 999 times in less than 0.2 s.
"$glint" render "$scene" --mode mc --size 4 --spp 64 -q -o ref8.pfm
"$glint" converge "$scene" --mode mc --threads 1 --reference ref8.pfm --ladder 1,2,4,8 --csv tiny.csv \
  --chart "" > /dev/null 2> tiny.err
grep -q "warning: rung 0 ran 0.[0-9]* s in all: under the floor of 0.2 s" tiny.err \
  || fail "tiny rungs: $(cat tiny.err)"
grep -q "under the floor" tiny.csv || fail "tiny rungs: not in the CSV"

# A reference of the other mode (a PFM: no attributes to tell): the means say it.
"$glint" render "$scene" --size 48 -q -o whitted.pfm
"$glint" converge "$scene" --mode mc --reference whitted.pfm --ladder 1,2,4,8 --csv w.csv \
  --chart "" > /dev/null 2> w.err
grep -q "warning: default: the render's mean radiance [0-9.]* is less than half the reference's [0-9.]*" w.err \
  || fail "Whitted reference: $(cat w.err)"
exit $status
