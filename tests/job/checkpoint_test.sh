#!/usr/bin/env bash
# checkpoint_test.sh GLINT SCENE [LAUNCHER...]: a render killed with SIGKILL in the middle
# and resumed from its checkpoint ends with the same image, bit for bit, as one that ran
# through; a checkpoint of another render is refused. With LAUNCHER (e.g. mpirun -np 2),
# the killed and the resumed renders run under it.
set -u
glint=$1
scene=$2
shift 2
launch=("$@")
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
status=0
flags=(--mode mc --size 96 --spp 4096 -q)
"$glint" render "$scene" "${flags[@]}" -o "$dir/through.pfm"
"${launch[@]}" "$glint" render "$scene" "${flags[@]}" -o "$dir/killed.pfm" \
  --checkpoint "$dir/ck" --checkpoint-every 0.1 &
pid=$!
# Kill once a checkpoint exists and has been replaced at least once (mid-render).
for _ in $(seq 1 200); do
  [ -f "$dir/ck" ] && break
  sleep 0.02
done
sleep 0.4
kill -KILL "$pid"
wait "$pid" 2>/dev/null
pkill -KILL -f "$dir/killed.pfm" 2>/dev/null  # a launcher's children, if any survived it
[ -f "$dir/ck" ] || { echo "FAIL: no checkpoint after SIGKILL"; exit 1; }
[ ! -f "$dir/killed.pfm" ] || { echo "FAIL: the killed render finished before the kill"; exit 1; }
echo "checkpoint: $(head -c 200 "$dir/ck" | sed -n 2p | cut -c1-150)..."
"${launch[@]}" "$glint" render "$scene" "${flags[@]}" -o "$dir/resumed.pfm" --resume "$dir/ck" \
  || { echo "FAIL: the resume failed"; status=1; }
if cmp -s "$dir/through.pfm" "$dir/resumed.pfm"; then
  echo "resumed after SIGKILL: the same image, bit for bit, as the render that ran through"
else
  echo "FAIL: the resumed image differs from the one that ran through"
  status=1
fi
out=$("$glint" render "$scene" --mode mc --size 96 --spp 4096 --seed 2 -q -o "$dir/x.pfm" \
      --resume "$dir/ck" 2>&1)
code=$?
echo "$out"
[ "$code" -eq 1 ] && echo "$out" | grep -q "a checkpoint of another render: its --seed is 1" \
  || { echo "FAIL: a checkpoint of another seed was not refused (exit $code)"; status=1; }
out=$("$glint" render "$scene" --mode mc --size 80 --spp 4096 -q -o "$dir/x.pfm" \
      --resume "$dir/ck" 2>&1)
echo "$out" | grep -q 'its --size is "96x96"' || { echo "FAIL: another size: $out"; status=1; }
printf 'not a checkpoint' > "$dir/bad"
out=$("$glint" render "$scene" "${flags[@]}" -o "$dir/x.pfm" --resume "$dir/bad" 2>&1)
echo "$out" | grep -q "not a glint checkpoint" || { echo "FAIL: a bad file: $out"; status=1; }
exit $status
