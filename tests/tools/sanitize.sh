#!/usr/bin/env bash
# sanitize.sh SOURCE_DIR BUILD_DIR: builds the unit tests with AddressSanitizer and
# UndefinedBehaviorSanitizer and runs them; any report fails the run.
set -euo pipefail
src=$1
build=$2
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGLINT_SANITIZE=ON > "$build.log" 2>&1 \
  || { cat "$build.log"; exit 1; }
cmake --build "$build" -j"$(nproc)" --target glint_tests glint >> "$build.log" 2>&1 \
  || { tail -50 "$build.log"; exit 1; }
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
"$build/tests/glint_tests" --gtest_brief=1
"$build/glint" render "$src/scenes/cornell.json" --mode mc --size 32 --spp 8 --walls diffuse -q \
  -o "$build/sanitized.png"
echo "sanitizers: clean"
