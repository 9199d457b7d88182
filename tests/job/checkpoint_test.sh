#!/usr/bin/env bash
# checkpoint_test.sh GLINT SCENE [LAUNCHER...]: a render killed with SIGKILL in the middle
# and resumed from its checkpoint ends with the same image, bit for bit, as one that ran
# through; a checkpoint of another render is refused. With LAUNCHER (e.g. mpirun -np 2),
# the killed and the resumed renders run under it. The resumed render's --stats prove that
# it traced only what the checkpoint did not hold.
set -u
glint=$1
scene=$2
shift 2
launch=("$@")
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
status=0
# Two threads wherever it runs: a many-core machine would finish before the kill. First
# with light tracing (its splats land anywhere in the image, and a chunk's go with its
# first pixel), then the design's terminal walls, whose checkpoint the checks below use.
for case in "--walls diffuse --caustics light --spp 1024" "--spp 4096"; do
  read -ra extra <<< "$case"
  flags=(--mode mc --size 96 --threads 2 -q "${extra[@]}")
  rm -f "$dir"/through.* "$dir"/killed.* "$dir"/resumed.* "$dir/ck"
  echo "== $case"
  "$glint" render "$scene" "${flags[@]}" -o "$dir/through.pfm" --stats "$dir/through.json"
  "${launch[@]}" "$glint" render "$scene" "${flags[@]}" -o "$dir/killed.pfm" \
    --checkpoint "$dir/ck" --checkpoint-every 0.1 &
  pid=$!
  # Kill as soon as the first checkpoint appears (written atomically: complete when seen).
  for _ in $(seq 1 1000); do
    [ -f "$dir/ck" ] && break
    sleep 0.01
  done
  kill -KILL "$pid"
  wait "$pid" 2>/dev/null
  pkill -KILL -f "$dir/killed.pfm" 2>/dev/null  # a launcher's children, if any survived it
  [ -f "$dir/ck" ] || { echo "FAIL: no checkpoint after SIGKILL"; exit 1; }
  [ ! -f "$dir/killed.pfm" ] || { echo "FAIL: the killed render finished before the kill"; exit 1; }
  echo "checkpoint: $(head -c 200 "$dir/ck" | sed -n 2p | cut -c1-150)..."
  "${launch[@]}" "$glint" render "$scene" "${flags[@]}" -o "$dir/resumed.pfm" --resume "$dir/ck" \
    --stats "$dir/resumed.json" || { echo "FAIL: the resume failed"; status=1; }
  # The resumed render's counters: the checkpoint's part and this session's add up to the
  # render that ran through, camera ray for camera ray, and this session traced only the
  # rest (a resume that ignored the checkpoint would trace all of it again).
  /usr/bin/python3 - "$dir/through.json" "$dir/resumed.json" <<'PY' || status=1
import json, sys
through, resumed = (json.load(open(p)) for p in sys.argv[1:3])
total = through["rays"]["camera"]
before = resumed["resumed"]["camera"]
session = resumed["rays"]["camera"] - before
print(f"camera rays: {total} in the render that ran through; the checkpoint held {before}, "
      f"the resumed session traced {session} ({100.0 * session / total:.1f}%)")
ok = resumed["rays"]["camera"] == total and 0 < before < total and 0 < session < total
if not ok:
    print("FAIL: the resumed render did not trace exactly what the checkpoint lacked")
sys.exit(0 if ok else 1)
PY
  if cmp -s "$dir/through.pfm" "$dir/resumed.pfm"; then
    echo "resumed after SIGKILL: the same image, bit for bit, as the render that ran through"
  else
    echo "FAIL: the resumed image differs from the one that ran through"
    status=1
  fi
done
out=$("$glint" render "$scene" --mode mc --size 96 --spp 4096 --seed 2 -q -o "$dir/x.pfm" \
      --resume "$dir/ck" 2>&1)
code=$?
echo "$out"
[ "$code" -eq 1 ] && echo "$out" | grep -q "a checkpoint of another render: its --seed is 1" \
  || { echo "FAIL: a checkpoint of another seed was not refused (exit $code)"; status=1; }
out=$("$glint" render "$scene" --mode mc --size 80 --spp 4096 -q -o "$dir/x.pfm" \
      --resume "$dir/ck" 2>&1)
echo "$out" | grep -q 'its --size is "96x96"' || { echo "FAIL: another size: $out"; status=1; }
# A checkpoint's counters: 9 (the build before the SIMD lanes' laneRays) are read, 8 are
# refused by name.
"$glint" render "$scene" --mode mc --size 16 --spp 2 -q -o "$dir/c.pfm" --checkpoint "$dir/c10"
for n in 9 8; do
  /usr/bin/python3 - "$dir/c10" "$dir/c$n" "$n" <<'PY'
import json, sys
data = open(sys.argv[1], "rb").read()
lines = data.split(b"\n", 2)  # magic line, JSON header, pixels
header = json.loads(lines[1])
header["stats"] = header["stats"][:int(sys.argv[3])]
open(sys.argv[2], "wb").write(lines[0] + b"\n" + json.dumps(header).encode() + b"\n" + lines[2])
PY
  out=$("$glint" render "$scene" --mode mc --size 16 --spp 2 -q -o "$dir/c$n.pfm" --resume "$dir/c$n" 2>&1)
  code=$?
  if [ "$n" = 9 ]; then
    { [ "$code" -eq 0 ] && cmp -s "$dir/c.pfm" "$dir/c$n.pfm"; } ||
      { echo "FAIL: a checkpoint with 9 counters: exit $code: $out"; status=1; }
  else
    { [ "$code" -eq 1 ] && echo "$out" | grep -q "field stats: expected 10 counters, found 8"; } ||
      { echo "FAIL: a checkpoint with 8 counters: exit $code: $out"; status=1; }
  fi
done
printf 'not a checkpoint' > "$dir/bad"
out=$("$glint" render "$scene" "${flags[@]}" -o "$dir/x.pfm" --resume "$dir/bad" 2>&1)
echo "$out" | grep -q "not a glint checkpoint" || { echo "FAIL: a bad file: $out"; status=1; }
exit $status
