#!/usr/bin/env bash
# interrupt_test.sh GLINT SCENE: SIGINT and SIGTERM stop a long render within a second,
# leave an existing output untouched, save a clearly named partial image and leave no
# temporary file behind.
set -u
glint=$1
scene=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
status=0
for sig in INT TERM; do
  printf 'yesterday' > "$dir/out.png"
  "$glint" render "$scene" --mode mc --size 64 --spp 1000000 -q -o "$dir/out.png" 2>"$dir/err" &
  pid=$!
  sleep 0.5
  start=$(date +%s%N)
  kill -s "$sig" "$pid"
  wait "$pid"
  code=$?
  took_ms=$(( ($(date +%s%N) - start) / 1000000 ))
  expected=$([ "$sig" = INT ] && echo 130 || echo 143)
  echo "SIG$sig: exit $code after ${took_ms} ms: $(cat "$dir/err")"
  [ "$code" -eq "$expected" ] || { echo "FAIL: exit code $code, expected $expected"; status=1; }
  [ "$took_ms" -lt 1000 ] || { echo "FAIL: took ${took_ms} ms to stop"; status=1; }
  [ "$(cat "$dir/out.png")" = yesterday ] || { echo "FAIL: the existing output was changed"; status=1; }
  head -c 4 "$dir/out.partial.png" | grep -q PNG || { echo "FAIL: no partial PNG"; status=1; }
  grep -q "out.partial.png" "$dir/err" || { echo "FAIL: the message does not name the partial file"; status=1; }
  leftovers=$(ls -A "$dir" | grep -v -E '^(out.png|out.partial.png|err)$')
  [ -z "$leftovers" ] || { echo "FAIL: left behind: $leftovers"; status=1; }
  rm -f "$dir/out.partial.png"
done
exit $status
