#!/usr/bin/env bash
# simd_targets_test.sh GLINT SCENE: the image is the same, byte for byte, for every --simd
# target this CPU runs (TerminalWallLanes, WhittedWallLanes, CameraHitLanes) as for the scalar lane, in
# both modes, for each sampler and each Monte Carlo switch the lanes meet, with 1 and 2
# threads and over 2 MPI ranks; a target the CPU lacks is refused with a message that
# names what it runs.
set -u
glint=$1
scene=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
status=0
targets=()
for t in scalar sse4 avx2 avx512; do
  if out=$("$glint" render "$scene" --mode mc --simd "$t" --size 4 --spp 1 -q -o "$dir/probe.pfm" 2>&1); then
    targets+=("$t")
  elif printf '%s' "$out" | grep -q "this CPU does not run it; it runs scalar"; then
    echo "$t: refused, as it should be on this CPU: $out"
  else
    echo "FAIL: --simd $t: $out"
    status=1
  fi
done
echo "targets this CPU runs: ${targets[*]}"
[ "${#targets[@]}" -ge 2 ] || { echo "FAIL: not one SIMD target beside scalar"; status=1; }
render() {  # render NAME ARGS...: the scene at 48x40, 11 rays per pixel (spare lanes)
  local name=$1
  shift
  "$glint" render "$scene" --size 48x40 --spp 11 --seed 3 -q -o "$dir/$name.exr" "$@" ||
    { echo "FAIL: render $*"; status=1; }
}
for sampler in random stratified sobol; do
  for switches in "--mode whitted" "--mode whitted --fresnel small-angle" "--mode mc" \
                  "--mode mc --glass choose --fresnel small-angle" \
                  "--mode mc --strategy light --branches 3" "--mode mc --strategy brdf" \
                  "--mode mc --walls diffuse" "--mode mc --walls diffuse --caustics light" \
                  "--mode mc --walls diffuse --mirror-light brdf"; do
    read -ra s <<< "--sampler $sampler $switches"
    render scalar "${s[@]}" --simd scalar --threads 1
    for t in "${targets[@]}"; do
      for threads in 1 2; do
        render "$t" "${s[@]}" --simd "$t" --threads "$threads"
        if cmp -s "$dir/scalar.exr" "$dir/$t.exr"; then
          echo "${s[*]}: $t, $threads thread(s): the scalar image"
        else
          echo "FAIL: ${s[*]}: --simd $t --threads $threads differs from --simd scalar"
          status=1
        fi
      done
    done
  done
done
# Over 2 MPI ranks with the widest target: the scalar image of one process.
if command -v mpirun > /dev/null; then
  for mode in mc whitted; do
    render scalar --mode "$mode" --simd scalar
    mpirun --allow-run-as-root --oversubscribe -q -np 2 "$glint" render "$scene" --mode "$mode" \
      --size 48x40 --spp 11 --seed 3 -q -o "$dir/ranks.exr" || { echo "FAIL: mpirun"; status=1; }
    if cmp -s "$dir/scalar.exr" "$dir/ranks.exr"; then
      echo "$mode, 2 ranks, --simd auto: the scalar image"
    else
      echo "FAIL: $mode: 2 ranks with --simd auto differ from one process with --simd scalar"
      status=1
    fi
  done
else
  echo "FAIL: mpirun is not installed (tools/setup.sh)"
  status=1
fi
exit $status
