#!/usr/bin/env bash
# run-fuzz.sh SOURCE_DIR WORK_DIR SECONDS SOURCES: builds the scene-loader fuzzer with
# clang (-fsanitize=fuzzer,address,undefined) from the library's SOURCES (paths relative
# to SOURCE_DIR, separated by ';', as CMake lists glint_core's) and runs it for a bounded
# time on a copy of the seed corpus. Fails where clang is missing (tools/setup.sh --dev).
set -euo pipefail
src=$1
work=$2
seconds=$3
IFS=';' read -ra sources <<< "$4"
if ! command -v clang++ >/dev/null; then
  echo "fuzz: clang++ is not installed (run: bash tools/setup.sh --dev)"
  exit 1
fi
mkdir -p "$work/obj" "$work/corpus" "$work/artifacts"
flags=(-std=c++20 -O1 -g -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
       -DGLM_FORCE_XYZW_ONLY -I"$src/include" -I"$src" -isystem /usr/include/stb -w
       -ffp-contract=off $(pkg-config --cflags OpenEXR libhwy))
objects=()
pids=()
for s in "${sources[@]}"; do
  obj="$work/obj/$(basename "$s" .cpp).o"
  if [ ! -f "$obj" ] || [ "$src/$s" -nt "$obj" ] || [ -n "$(find "$src/include" -newer "$obj" -name '*.hpp' | head -1)" ]; then
    clang++ "${flags[@]}" -c "$src/$s" -o "$obj" &
    pids+=($!)
  fi
  objects+=("$obj")
  # two compilers at a time; a failed compile fails the run (set -e)
  while [ "$(jobs -rp | wc -l)" -ge 2 ]; do wait -n; done
done
# Every compile's exit code, each waited for by its pid (a bare `wait` returns 0).
for pid in "${pids[@]}"; do
  wait "$pid" || { echo "fuzz: a compile failed"; exit 1; }
done
clang++ "${flags[@]}" -fsanitize=fuzzer "$src/tests/scene/fuzz/scene_fuzzer.cpp" "${objects[@]}" \
  $(pkg-config --libs OpenEXR libhwy) -o "$work/scene_fuzzer"
# The seed corpus must be there: a fuzzer started on nothing would find nothing.
cp "$src"/tests/scene/fuzz/corpus/* "$src"/tests/scene/fuzz/regressions/* "$work/corpus/"
cd "$work"
./scene_fuzzer -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 \
  -artifact_prefix="$work/artifacts/" -print_final_stats=1 corpus/
echo "fuzzer: no crash in ${seconds} s (artifacts, if any, in $work/artifacts)"
