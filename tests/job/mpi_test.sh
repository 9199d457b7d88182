#!/usr/bin/env bash
# mpi_test.sh GLINT SCENE: glint under mpirun (OpenMPI from tools/setup.sh). The image of
# 1, 2 and 3 ranks is the same, bit for bit, as one process's, in both modes and both wall
# modes, and with light tracing's splats (--caustics light); --time holds across 2 ranks; bad input fails fast with one message; an interrupt
# saves the partial image; ranks default to the node's cores divided among them.
set -u
glint=$1
scene=$2
mpirun=(mpirun --allow-run-as-root --oversubscribe -q)
command -v mpirun > /dev/null || { echo "FAIL: mpirun is not installed (tools/setup.sh)"; exit 1; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
status=0
for mode in "whitted" "mc" "mc --walls diffuse" "mc --walls diffuse --caustics light"; do
  read -ra m <<< "--mode $mode"
  "$glint" render "$scene" "${m[@]}" --size 48x40 --spp 16 --seed 7 -q -o "$dir/one.pfm"
  for np in 1 2 3; do
    rm -f "$dir/np$np.pfm"
    "${mpirun[@]}" -np "$np" "$glint" render "$scene" "${m[@]}" --size 48x40 --spp 16 --seed 7 \
      -q -o "$dir/np$np.pfm" || { echo "FAIL: -np $np ${m[*]} failed"; status=1; }
    if cmp -s "$dir/one.pfm" "$dir/np$np.pfm"; then
      echo "${m[*]}: $np rank(s): the same image as one process"
    else
      echo "FAIL: ${m[*]}: $np rank(s) differ from one process"
      status=1
    fi
  done
done
# --time across 2 ranks: one stop decision, within the budget's tolerance.
start=$(date +%s%N)
"${mpirun[@]}" -np 2 "$glint" render "$scene" --mode mc --size 64 --time 1 -o "$dir/t.pfm" \
  2> "$dir/t.err"
code=$?
ms=$(( ($(date +%s%N) - start) / 1000000 ))
cat "$dir/t.err"
[ "$code" -eq 0 ] || { echo "FAIL: --time under mpirun exited $code"; status=1; }
grep -Eq "rays/pixel \([0-9]+ passes\), 2 ranks x 1 thread: (0\.9[0-9]*|1\.000) s" "$dir/t.err" \
  || { echo "FAIL: not 2 ranks x 1 thread within the 1 s budget"; status=1; }
echo "--time 1 under mpirun -np 2: ${ms} ms in all (with MPI's start and end)"
# Bad input: one message, every rank out within seconds.
start=$(date +%s%N)
out=$("${mpirun[@]}" -np 2 "$glint" render "$scene" --set /objects/0/radius=-1 -o "$dir/x.png" 2>&1)
code=$?
ms=$(( ($(date +%s%N) - start) / 1000000 ))
echo "bad scene: exit $code after $ms ms: $out"
[ "$code" -ne 0 ] || { echo "FAIL: a bad scene exited 0 under mpirun"; status=1; }
[ "$(echo "$out" | grep -c '^glint:')" -eq 1 ] || { echo "FAIL: not one message"; status=1; }
[ "$ms" -lt 10000 ] || { echo "FAIL: took $ms ms to fail"; status=1; }
# An interrupt under mpirun saves the partial image.
for sig in INT TERM; do
  rm -f "$dir"/long*
  "${mpirun[@]}" -np 2 "$glint" render "$scene" --mode mc --size 64 --spp 1000000 \
    -o "$dir/long.png" 2> "$dir/long.err" &
  pid=$!
  sleep 1.5
  start=$(date +%s%N)
  kill -s "$sig" "$pid"
  wait "$pid"
  ms=$(( ($(date +%s%N) - start) / 1000000 ))
  echo "SIG$sig to mpirun: stopped after $ms ms: $(grep '^glint:' "$dir/long.err")"
  head -c 4 "$dir/long.partial.png" 2>/dev/null | grep -q PNG \
    || { echo "FAIL: no partial image after SIG$sig"; status=1; }
  [ ! -f "$dir/long.png" ] || { echo "FAIL: a full image after SIG$sig"; status=1; }
  [ "$(grep -c '^glint:' "$dir/long.err")" -eq 1 ] || { echo "FAIL: not one message"; status=1; }
  [ "$ms" -lt 10000 ] || { echo "FAIL: took $ms ms to stop"; status=1; }
done
# The bench reports scaling over ranks.
"${mpirun[@]}" -np 2 "$glint" bench "$scene" --size 32 --repeat 1 --mc-spp 4 > "$dir/bench" \
  || status=1
cat "$dir/bench"
grep -Eq "^mc +4 +2 " "$dir/bench" || { echo "FAIL: no 2-rank row in the bench"; status=1; }
exit $status
