#!/usr/bin/env bash
# validate_cycles.sh GLINT SOURCE_DIR WORK_DIR: glint against Blender's Cycles on the same
# scenes (issue #15). For each scene and wall mode, two glint renders (seeds 1, 2) and two
# Cycles renders (seeds 1, 2) at 64x64, judged by `glint compare` (which takes the
# references' noise from their spread). Then Blender reads glint's EXR as its PFM.
# Blender comes from `tools/setup.sh --dev`; without it the test fails, it does not skip.
set -euo pipefail
glint=$1
src=$2
work=$3
mkdir -p "$work"
cd "$work"
if ! command -v blender > /dev/null; then
  echo "validate.cycles: blender is not installed; run: bash tools/setup.sh --dev" >&2
  exit 1
fi
status=0
rm -f ./*-cycles-*.pfm  # Cycles' renders are made once a run, and shared by its checks
check() {  # scene (in scenes/, or a path) walls glint_spp cycles_spp [glint's switches...]
  local scene=$1 walls=$2 gspp=$3 cspp=$4 name cname
  shift 4
  cname=$(basename "$scene" .json)-$walls
  name=$cname$(printf '%s' "$*" | tr -c 'a-z0-9' '-')
  case $scene in /*) ;; *) scene=$src/scenes/$scene ;; esac
  for seed in 1 2; do
    "$glint" render "$scene" --mode mc --walls "$walls" --size 64 --spp "$gspp" \
      --seed "$seed" -q -o "$name-glint-$seed.pfm" "$@"
    [ -f "$cname-cycles-$seed.pfm" ] || "$src/tools/cycles-render" "$scene" --mode mc \
      --walls "$walls" --size 64 --spp "$cspp" --seed "$seed" -o "$cname-cycles-$seed.pfm"
  done
  echo "$name:"
  if ! "$glint" compare "$name-glint-1.pfm" "$name-glint-2.pfm" \
      "$cname-cycles-1.pfm" "$cname-cycles-2.pfm"; then
    status=1
  fi
}
check cornell-mirror.json terminal 1024 2048
check cornell-mirror.json diffuse 4096 2048
# Light tracing's caustics (--caustics light) against the same Cycles renders.
check cornell-mirror.json diffuse 2048 2048 --caustics light
check cornell-lambert.json terminal 1024 2048
check cornell-lambert.json diffuse 4096 2048
# The view plane twice as far (its size kept): half the field of view, in both renderers.
python3 -c 'import json, sys; s = json.load(open(sys.argv[1])); s["camera"]["view_plane_distance"] = 3.0; json.dump(s, open(sys.argv[2], "w"))' \
  "$src/scenes/cornell-mirror.json" "$work/narrow.json"
check "$work/narrow.json" terminal 1024 2048

# Every Blender property goes through a helper that refuses unknown names.
blender -b --factory-startup --python-exit-code 1 -P "$src/tests/tools/blender_set_property.py" -- \
  "$src/tools" > blender-set.log 2>&1 || { cat blender-set.log; status=1; }
grep '^blender_set_property:' blender-set.log
# A Phong object has no Cycles equivalent: refused, with the reason.
if "$src/tools/cycles-render" "$src/scenes/cornell.json" --size 8 --spp 1 -o phong.pfm \
    2> phong.log; then
  echo "validate.cycles: a Phong scene was not refused"
  status=1
fi
grep -q "objects/0/material: expected mirror, glass or lambertian, found \"phong\"" phong.log \
  || { cat phong.log; status=1; }
cat phong.log

# Blender reads glint's EXR as the same radiance as glint's PFM.
"$glint" render "$src/scenes/cornell.json" --mode mc --size 48x32 --spp 16 -q -o exr.exr -o exr.pfm
blender -b --factory-startup --python-exit-code 1 -P "$src/tests/tools/blender_reads_exr.py" -- \
  exr.exr exr.pfm > blender-exr.log 2>&1 || { cat blender-exr.log; status=1; }
grep '^blender_reads_exr:' blender-exr.log || { cat blender-exr.log; status=1; }
exit $status
