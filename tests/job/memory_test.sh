#!/usr/bin/env bash
# memory_test.sh GLINT SCENE: peak memory of Monte Carlo renders at 1024x1024 must not
# depend on the rays per pixel or on --branches (ray trees are released ray by ray into
# a per-thread arena that is reset, not freed), and what is not image buffers must stay
# under 64 MiB (issue #8).
set -u
glint=$1
scene=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
size=1024
# Image buffers: the Pixel array (32 B), the linear Image (24 B), the PFM's floats (12 B).
buffers=$(( size * size * (32 + 24 + 12) / 1048576 ))
peaks=()
for cfg in "--spp 1" "--spp 16" "--spp 1 --branches 64" "--spp 2 --branches 16 --walls diffuse"; do
  # shellcheck disable=SC2086
  if ! "$glint" render "$scene" --mode mc --size $size $cfg -o "$dir/m.pfm" --stats "$dir/m.json" -q; then
    echo "FAIL: glint render $cfg"
    exit 1
  fi
  peak=$(sed -n 's/.*"peak_rss_mib": \([0-9.]*\).*/\1/p' "$dir/m.json")
  echo "$cfg: peak $peak MiB (image buffers $buffers MiB)"
  peaks+=("$peak")
done
python3 - "$buffers" "${peaks[@]}" <<'PY'
import sys
buffers = float(sys.argv[1])
peaks = [float(p) for p in sys.argv[2:]]
spread = max(peaks) - min(peaks)
rest = max(peaks) - buffers
print(f"spread {spread:.2f} MiB over rays per pixel and branches; beyond the buffers {rest:.1f} MiB")
ok = spread < 2.0 and rest < 64.0
if not ok:
    print("FAIL: peak memory depends on spp/branches or exceeds 64 MiB beyond the image buffers")
sys.exit(0 if ok else 1)
PY
