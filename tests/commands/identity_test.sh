#!/usr/bin/env bash
# identity_test.sh GLINT SCENE: glint's EXR files say what render they are (scene and its
# hash, mode, walls, sampler, rays per pixel, seed, version), and compare and converge
# read it: a reference of another mode or scene is refused naming the field; two renders
# with one seed are one render; a render given as its own reference is refused.
set -eu
glint=$1
scene=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
status=0
fail() { echo "FAIL: $*"; status=1; }
# expect CODE REGEX COMMAND...: exit code and a line of stderr.
expect() {
  local code=$1 regex=$2
  shift 2
  set +e
  "$@" > out.txt 2>&1
  local got=$?
  set -e
  [ "$got" -eq "$code" ] || fail "$*: exit $got, expected $code: $(cat out.txt)"
  grep -Eq -- "$regex" out.txt || fail "$*: expected /$regex/, found: $(cat out.txt)"
}
r() { "$glint" render "$scene" --size 24 -q "$@"; }
r --mode mc --spp 16 -o a.exr
r --mode mc --spp 32 -o b-same-seed.exr
r --mode mc --spp 32 --seed 3 -o b.exr
r --mode mc --spp 256 --seed 9 -o ref.exr
r --mode whitted -o whitted.exr
r --mode mc --spp 256 --seed 9 --set /objects/1/ior=1.3 -o ref-ior.exr
r --mode mc --spp 64 --seed 3 -o ref-seed3.exr

exrheader a.exr > header.txt
for field in scene scene_hash set size mode walls fresnel sampler spp seed version; do
  grep -q "^glint:$field (type string)" header.txt || fail "a.exr has no glint:$field: $(cat header.txt)"
done
grep -q 'glint:spp (type string): "16"' header.txt || fail "spp: $(grep spp header.txt)"

expect 0 "agree" "$glint" compare a.exr b.exr ref.exr
expect 1 "A and B are the same render \(the same seed\): render B with another --seed" \
  "$glint" compare a.exr b-same-seed.exr ref.exr
expect 1 "A and B are the same render: render B with another --seed" \
  "$glint" compare a.exr a.exr ref.exr
expect 1 "a.exr and a.exr: a render and its reference are the same render" \
  "$glint" compare a.exr b.exr a.exr
expect 1 "b.exr and ref-seed3.exr: a render and its reference are the same render \(the same seed\)" \
  "$glint" compare a.exr b.exr ref-seed3.exr
expect 1 "whitted.exr: a render of another scene or mode: its mode is \"whitted\", a.exr's is \"mc\"" \
  "$glint" compare a.exr b.exr whitted.exr
expect 1 "ref-ior.exr: a render of another scene or mode: its --set is \"/objects/1/ior=1.3\", a.exr's is \"\"" \
  "$glint" compare a.exr b.exr ref-ior.exr
expect 1 "--reference whitted.exr: a render of another scene or mode: its mode is \"whitted\", this render's is \"mc\"" \
  "$glint" converge "$scene" --mode mc --reference whitted.exr --ladder 1,2 --chart ""
expect 1 "--reference ref.exr: a render of another scene or mode: its walls is \"terminal\", this render's is \"diffuse\"" \
  "$glint" converge "$scene" --mode mc --walls diffuse --reference ref.exr --ladder 1,2 --chart ""
expect 1 "--reference ref.exr: expected an image of the render's size 16x16 \(--size\), found 24x24" \
  "$glint" converge "$scene" --mode mc --size 16 --reference ref.exr --ladder 1,2 --chart ""
# The same scene with one more space: another file, another hash.
cp "$scene" mine.json
echo " " >> mine.json
expect 1 "--reference ref.exr: a render of another scene or mode: its scene file \(contents\) is \".*cornell.json, hash [0-9a-f]+\"" \
  "$glint" converge mine.json --mode mc --reference ref.exr --ladder 1,2 --chart ""
exit $status
