#!/usr/bin/env python3
"""layout_test.py SOURCE_DIR: the layout that README.md's "How the code is organised" shows.

1. Layers: a file includes only from its own folder's layer or one below it (the
   commands use the renderer, never the reverse); the order is LAYERS below.
2. One convention for headers: the library's under include/glint/<layer>/ beside
   src/<layer>/; the program's (job, commands, cli) beside their sources, never under
   include/.
3. The map: every folder the README's map names exists, and every folder of src/,
   include/glint/ and tests/ is named in it.
"""
import os
import re
import sys

LAYERS = ["core", "sampling", "image", "scene", "camera", "transport",  # the library
          "job", "commands", "cli"]                                      # the program
LIBRARY = LAYERS[:6]

src = sys.argv[1]
problems = []
include = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def layer_of_include(path):
    parts = path.split("/")
    if parts[0] == "glint" and len(parts) == 3:
        return parts[1]
    if len(parts) == 2 and parts[0] in LAYERS[6:]:
        return parts[0]
    return None


for top in ("src", "include/glint"):
    for dirpath, _, files in os.walk(os.path.join(src, top)):
        rel = os.path.relpath(dirpath, os.path.join(src, top))
        if rel == ".":
            for f in files:
                problems.append(f"{top}/{f}: a file outside the layers' folders")
            continue
        layer = rel.split(os.sep)[0]
        if layer not in LAYERS:
            problems.append(f"{top}/{rel}: not a layer ({', '.join(LAYERS)})")
            continue
        if top == "include/glint" and layer not in LIBRARY:
            problems.append(f"{top}/{rel}: the program's headers live beside its sources")
        for f in files:
            if not f.endswith((".hpp", ".cpp")):
                continue
            name = os.path.join(top, rel, f)
            if top == "src" and layer in LIBRARY and f.endswith(".hpp"):
                problems.append(f"{name}: a library header belongs in include/glint/{layer}/")
            text = open(os.path.join(src, name), encoding="utf-8").read()
            for inc in include.findall(text):
                target = layer_of_include(inc)
                if target is None:
                    if not inc.startswith(("nlohmann/", "stb_")):
                        problems.append(f"{name}: includes \"{inc}\", not a layer's file")
                    continue
                if LAYERS.index(target) > LAYERS.index(layer):
                    problems.append(f"{name} ({layer}) includes \"{inc}\" from the layer "
                                    f"above it ({target})")

readme = open(os.path.join(src, "README.md"), encoding="utf-8").read()
start = readme.find("## How the code is organised")
if start < 0:
    problems.append("README.md: no section \"How the code is organised\"")
else:
    end = readme.find("\n## ", start + 1)
    section = readme[start:end if end > 0 else len(readme)]
    named = set(re.findall(r"`((?:src|include/glint|tests)/[A-Za-z0-9_/.-]*?)/?`", section))
    for folder in sorted(named):
        if not os.path.exists(os.path.join(src, folder)):
            problems.append(f"README.md's map names {folder}, which does not exist")
    for top in ("src", "include/glint", "tests"):
        for dirpath, dirs, _ in os.walk(os.path.join(src, top)):
            dirs[:] = [d for d in dirs if d not in ("corpus", "regressions", "bad-scenes")]
            rel = os.path.relpath(dirpath, src)
            if rel in (top,):
                continue
            if rel not in named:
                problems.append(f"README.md's map does not name the folder {rel}/")

for p in problems:
    print("layout:", p)
if problems:
    sys.exit(1)
print(f"layout: {len(LAYERS)} layers, no include from a layer above, the map matches the tree")
