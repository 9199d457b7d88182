"""blender -b -P blender_set_property.py -- TOOLS_DIR: cycles_render.SetProperty refuses a
name its owner lacks (Blender itself would accept a misspelt attribute silently) and sets a
real one."""
import sys

import bpy

sys.path.insert(0, sys.argv[-1])
import cycles_render  # noqa: E402

cycles = bpy.context.scene.cycles
try:
    cycles.sampels = 7  # what a bare setattr does with a misspelt name: nothing is said
    cycles_render.SetProperty(cycles, "sampels", 7)
    print("blender_set_property: a misspelt name was accepted")
    sys.exit(1)
except RuntimeError as e:
    print(f"blender_set_property: refused as it should be: {e}")
cycles_render.SetProperty(cycles, "samples", 7)
if cycles.samples != 7:
    sys.exit(1)
print("blender_set_property: samples set to 7")
