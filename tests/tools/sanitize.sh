#!/usr/bin/env bash
# sanitize.sh SOURCE_DIR BUILD_DIR: builds the unit tests with AddressSanitizer and
# UndefinedBehaviorSanitizer and runs what they need to see every code path of the
# renderer once; any report fails the run. Only what it needs: the library and its unit
# tests (their renders go through Camera, Pixel and both integrators in every mode; the
# command line's own code is the fuzzer's and the CLI tests' part), at -O1 (an optimised
# build's inlining costs compile time and finds nothing more), and every unit test but
# the statistical ones that repeat one path millions of times for their error bars (they
# run, unsanitized, in the main build).
set -euo pipefail
src=$1
build=$2
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" \
  -DGLINT_SANITIZE=ON -DGLINT_BUILD_BENCH=OFF > "$build.log" 2>&1 \
  || { cat "$build.log"; exit 1; }
cmake --build "$build" -j"$(nproc)" --target glint_tests >> "$build.log" 2>&1 \
  || { tail -50 "$build.log"; exit 1; }
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
repeats="Sampler.ImagesOfTheThreeSamplersAgreeBlockByBlock:MonteCarlo.LightBrdfAndMisSampling*"
repeats+=":MonteCarlo.GlassSplitAndChooseAgree:MirroredLight.AgreesWithRays*"
repeats+=":MirroredLight.ImagesWithAndWithoutIt*:MonteCarlo.PhongAlbedo*"
repeats+=":Sampler.EverySamplerIsUnbiased*:Sampler.NeighbouringPixels*"
repeats+=":MonteCarlo.PhongRadianceAgrees*:MonteCarlo.RussianRoulette*"
"$build/tests/glint_tests" --gtest_brief=1 --gtest_filter="-$repeats"
echo "sanitizers: clean"
