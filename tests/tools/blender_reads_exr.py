"""blender -b -P blender_reads_exr.py -- IMAGE.exr IMAGE.pfm: Blender reads glint's EXR as
the radiance of glint's PFM of the same render (exit 1 if any value differs)."""
import struct
import sys

import bpy

exr, pfm = sys.argv[-2], sys.argv[-1]
image = bpy.data.images.load(exr)
w, h = image.size
pixels = [0.0] * (w * h * 4)
image.pixels.foreach_get(pixels)  # bottom row first, as PFM
with open(pfm, "rb") as f:
    assert f.readline().strip() == b"PF"
    pw, ph = map(int, f.readline().split())
    f.readline()
    values = struct.unpack("<%df" % (pw * ph * 3), f.read())
if (w, h) != (pw, ph):
    print(f"blender_reads_exr: sizes differ: EXR {w}x{h}, PFM {pw}x{ph}")
    sys.exit(1)
worst = max(abs(pixels[4 * i + k] - values[3 * i + k]) for i in range(w * h) for k in range(3))
mean = sum(values) / len(values)
print(f"blender_reads_exr: {w}x{h}, colour space {image.colorspace_settings.name}, mean "
      f"{mean:.6f}, largest difference from the PFM {worst:g}")
sys.exit(0 if worst == 0.0 and image.colorspace_settings.name == "Linear" else 1)
