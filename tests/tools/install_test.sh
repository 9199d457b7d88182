#!/usr/bin/env bash
# install_test.sh BUILD_DIR WORK_DIR: `cmake --install` into a fresh prefix, then glint
# used as a student would from another folder: render an installed scene, glint bench
# with its default scene (the installed one), glint converge's chart (the installed
# script). Issue #26.
set -euo pipefail
build=$1
work=$2
rm -rf "$work"
mkdir -p "$work/prefix" "$work/elsewhere"
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
glint=$work/prefix/bin/glint
share=$work/prefix/share/glint
status=0
for f in "$share/scenes/cornell.json" "$share/tools/plot_convergence.py" \
         "$work/prefix/share/doc/glint/scene-format.md"; do
  [ -f "$f" ] || { echo "FAIL: not installed: $f"; status=1; }
done
cd "$work/elsewhere"
"$glint" --version
"$glint" render "$share/scenes/cornell.json" --mode mc --size 32 --spp 4 -q -o x.png
head -c 4 x.png | grep -q PNG || { echo "FAIL: no PNG rendered"; status=1; }
"$glint" bench --size 16 --threads 1 --repeat 1 --modes mc --mc-spp 1 2>&1 | tee bench.log
grep -q "glint bench: $share/scenes/cornell.json" bench.log \
  || { echo "FAIL: glint bench did not use the installed scene"; status=1; }
"$glint" render "$share/scenes/cornell.json" --mode mc --size 16 --spp 64 -q -o ref.pfm
"$glint" converge "$share/scenes/cornell.json" --mode mc --size 16 --ladder 1,2,4 \
  --reference ref.pfm --seed 2 --csv c.csv --chart c.png > converge.log 2>&1 \
  || { cat converge.log; echo "FAIL: glint converge"; status=1; }
head -c 4 c.png | grep -q PNG || { echo "FAIL: no chart drawn by the installed script"; status=1; }
[ "$status" -eq 0 ] && echo "install: glint works from another folder with the installed files"
exit $status
