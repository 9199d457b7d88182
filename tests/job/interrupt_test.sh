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

# One pass cut short (#26): the finished pixels are kept, the others marked, the message
# says how much was done. Cut between passes (--time), every pixel is there.
"$glint" render "$scene" --mode mc --size 128 --spp 100000 -q -o "$dir/one.pfm" 2>"$dir/err" &
pid=$!
sleep 1
kill -s INT "$pid"
wait "$pid"
echo "one pass: $(cat "$dir/err")"
/usr/bin/python3 - "$dir/one.partial.pfm" "$(cat "$dir/err")" <<'PY' || status=1
import re, sys
import numpy
path, message = sys.argv[1], sys.argv[2]
m = re.search(r"(\d+) of 16384 pixels \([0-9.]+%\) rendered, the first (\d+) rows complete; "
              r"the rest is a magenta and black checkerboard", message)
if not m:
    sys.exit(f"FAIL: the message does not say how much was done: {message}")
done, rows = int(m.group(1)), int(m.group(2))
with open(path, "rb") as f:
    f.readline(); f.readline(); f.readline()
    image = numpy.frombuffer(f.read(), dtype="<f4").reshape(128, 128, 3)[::-1]
magenta = numpy.all(image == numpy.array([1, 0, 1], dtype="<f4"), axis=2)
print(f"{done} pixels rendered, {rows} rows complete, {int(magenta.sum())} magenta pixels")
if not (0 < done < 16384 and rows * 128 <= done):
    sys.exit("FAIL: implausible counts")
if magenta[:rows].any():
    sys.exit("FAIL: a complete row is marked")
# Half the unrendered pixels are magenta, give or take the squares a boundary cuts.
if abs(int(magenta.sum()) - (16384 - done) / 2) > 8 * 128:
    sys.exit("FAIL: the marks do not cover the unrendered pixels")
PY
"$glint" render "$scene" --mode mc --size 64 --time 30 -q -o "$dir/timed.png" 2>"$dir/err" &
pid=$!
sleep 1
kill -s INT "$pid"
wait "$pid"
echo "--time: $(cat "$dir/err")"
grep -Eq "timed.partial.png: every pixel, [0-9]+ complete passes" "$dir/err" \
  || { echo "FAIL: a --time render cut short should keep every pixel"; status=1; }
exit $status
