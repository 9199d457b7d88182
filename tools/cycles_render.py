"""Builds a glint scene file in Blender's Cycles and renders it (run by tools/cycles-render).

    blender -b --factory-startup -P tools/cycles_render.py -- SCENE.json --mode mc \
        --walls terminal|diffuse --size N|WxH --spp S --seed K -o OUT.pfm|OUT.exr

What it builds (the trust issue, #15):
- walls: inward-facing Lambertian quads (Diffuse BSDF, the albedo of the wall) that cast no
  shadow (the room is convex: in glint no wall blocks a shadow ray either); the ceiling
  has a hole exactly where the light is, so nothing is coplanar with the emitter;
- the light: a one-sided emitter of radiance L_e facing down (an Emission shader of
  strength 1 gives radiance equal to its colour; its back emits nothing);
- spheres: smooth UV spheres fine enough that their chord error is far below a pixel;
- cubes: six quads;
- materials: `mirror` a sharp Glossy BSDF, `glass` a sharp Glass BSDF, `lambertian` a
  Diffuse BSDF; `phong` is refused: glint's lobe is zero where R.psi <= 0, which no Cycles
  BSDF reproduces (not even at exponent 0, which is Lambertian only at normal incidence);
- the camera as glint's: at the eye, looking down -z, its vertical field of view spanning
  the view plane (the room's height) at the scene's `view_plane_distance`, or by the
  design's set-up rule the room's front opening;
- a box pixel filter one pixel wide, no denoising, no adaptive sampling, no clamping,
  caustics on, bounce limits 64; terminal walls are `max diffuse bounces = 0`.
Every Blender property goes through SetProperty, which refuses a name its owner lacks:
Blender silently accepts a misspelt attribute and leaves the real setting at its default.
Output: linear radiance, PFM (bottom row first) or 32-bit float OpenEXR.
"""
import argparse
import json
import math
import os
import struct
import sys
import time

PREFIX = "cycles-render:"


class UsageError(Exception):
    pass


def Fail(message):
    print(f"{PREFIX} {message}", flush=True)
    sys.exit(1)


class Parser(argparse.ArgumentParser):
    def error(self, message):
        raise UsageError(message)


def ParseArgs(argv):
    p = Parser(
        prog="tools/cycles-render",
        description="Render a glint scene file with Blender's Cycles (linear radiance).")
    p.add_argument("scene", help="glint scene file (JSON)")
    p.add_argument("--mode", default="mc", help="only 'mc': Cycles is a path tracer")
    p.add_argument("--walls", default="terminal", choices=["terminal", "diffuse"],
                   help="terminal: max diffuse bounces 0 (direct light at every wall); "
                        "diffuse: full global illumination (default: terminal)")
    p.add_argument("--size", default=None, help="N or WxH (default: the scene's resolution)")
    p.add_argument("--spp", type=int, default=64, help="samples per pixel (default 64)")
    p.add_argument("--seed", type=int, default=1, help="Cycles' seed (default 1)")
    p.add_argument("--threads", type=int, default=0, help="render threads (default: all)")
    p.add_argument("-o", "--output", required=True, help="OUT.pfm or OUT.exr")
    p.add_argument("--blend", default=None, help="also save the built scene as a .blend file")
    args = p.parse_args(argv)
    if args.mode != "mc":
        raise UsageError(f"--mode {args.mode}: expected mc (Cycles has no Whitted mode)")
    if args.spp < 1:
        raise UsageError(f"--spp {args.spp}: expected a whole number >= 1")
    ext = os.path.splitext(args.output)[1].lower()
    if ext not in (".pfm", ".exr"):
        raise UsageError(f"{args.output}: expected a file name ending in .pfm or .exr")
    folder = os.path.dirname(os.path.abspath(args.output))
    if not os.path.isdir(folder):
        raise UsageError(f"{args.output}: the folder '{folder}' does not exist")
    return args


def ParseSize(text, scene):
    if text is None:
        w, h = scene["camera"]["resolution"]
        return int(w), int(h)
    parts = text.lower().split("x")
    try:
        values = [int(v) for v in parts]
    except ValueError:
        raise UsageError(f"--size {text}: expected N or WxH")
    if len(values) == 1:
        values *= 2
    if len(values) != 2 or min(values) < 1 or max(values) > 65536:
        raise UsageError(f"--size {text}: expected N or WxH with whole numbers in [1, 65536]")
    return values[0], values[1]


# ---------------------------------------------------------------------------------------
# Blender


def SetProperty(owner, name, value):
    """owner.name = value, refusing a name that owner does not have."""
    props = owner.bl_rna.properties
    if name not in props.keys():
        raise RuntimeError(f"{owner.bl_rna.identifier} has no property '{name}'")
    setattr(owner, name, value)
    got = getattr(owner, name)
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        if abs(float(got) - float(value)) > 1e-6 * max(1.0, abs(float(value))):
            raise RuntimeError(f"{owner.bl_rna.identifier}.{name}: set {value}, reads {got}")
    elif isinstance(value, (str, bool)) and got != value:
        raise RuntimeError(f"{owner.bl_rna.identifier}.{name}: set {value!r}, reads {got!r}")


def SetProperties(owner, **values):
    for name, value in values.items():
        SetProperty(owner, name, value)


def SetInput(node, name, value):
    if name not in node.inputs.keys():
        raise RuntimeError(f"node {node.bl_idname} has no input '{name}'")
    node.inputs[name].default_value = value


def NewMaterial(bpy, name, build):
    """A node material whose surface is build(nodes) -> output socket."""
    mat = bpy.data.materials.new(name)
    SetProperty(mat, "use_nodes", True)
    nodes = mat.node_tree.nodes
    for n in list(nodes):
        nodes.remove(n)
    out = nodes.new("ShaderNodeOutputMaterial")
    SetProperty(out, "target", "CYCLES")
    mat.node_tree.links.new(build(mat.node_tree), out.inputs["Surface"])
    return mat


def Bsdf(bpy, name, node, properties, inputs):
    """A material of one BSDF node, its properties and inputs set through the helpers."""
    def build(tree):
        n = tree.nodes.new(node)
        for key, value in properties.items():
            SetProperty(n, key, value)
        for key, value in inputs.items():
            SetInput(n, key, value)
        return n.outputs["BSDF"]
    return NewMaterial(bpy, name, build)


def Diffuse(bpy, name, rho):
    # Roughness 0: Lambert (Oren-Nayar with sigma 0).
    return Bsdf(bpy, name, "ShaderNodeBsdfDiffuse", {}, {"Color": (*rho, 1.0), "Roughness": 0.0})


def Mirror(bpy, name, rho):
    return Bsdf(bpy, name, "ShaderNodeBsdfGlossy", {"distribution": "SHARP"},
                {"Color": (*rho, 1.0)})


def Glass(bpy, name, ior):
    return Bsdf(bpy, name, "ShaderNodeBsdfGlass", {"distribution": "SHARP"},
                {"Color": (1.0, 1.0, 1.0, 1.0), "IOR": ior})


def Emitter(bpy, name, radiance):
    """Radiance L_e on the front side (the side the face normal points to), nothing behind."""
    def build(tree):
        scale = max(radiance)
        emit = tree.nodes.new("ShaderNodeEmission")
        SetInput(emit, "Color", (*(c / scale for c in radiance), 1.0))
        SetInput(emit, "Strength", scale)
        black = tree.nodes.new("ShaderNodeEmission")
        SetInput(black, "Strength", 0.0)
        geometry = tree.nodes.new("ShaderNodeNewGeometry")
        mix = tree.nodes.new("ShaderNodeMixShader")
        tree.links.new(geometry.outputs["Backfacing"], mix.inputs["Fac"])
        tree.links.new(emit.outputs["Emission"], mix.inputs[1])
        tree.links.new(black.outputs["Emission"], mix.inputs[2])
        return mix.outputs["Shader"]
    return NewMaterial(bpy, name, build)


def CastsNoShadow(ob):
    """A wall of the convex room can stand between no point of the room and the light, so
    it casts no shadow, as in glint (Scene::Occluded tests the objects only). Cycles would
    otherwise let float-precision shadow rays that graze the ceiling toward the light's
    edge hit the ceiling around the hole: measured at 256x256, the top corners' walls came
    out 0.8% (7.7 sigma) darker than glint."""
    SetProperty(ob, "visible_shadow", False)


def AddMesh(bpy, name, vertices, faces, material):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([tuple(v) for v in vertices], [], faces)
    mesh.validate()
    mesh.update()
    mesh.materials.append(material)
    ob = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(ob)
    NoTerminatorOffset(ob)
    return ob


def NoTerminatorOffset(ob):
    # Cycles' shadow-terminator offsets move shading points of smooth low-poly meshes;
    # glint's geometry is exact, so they are off.
    for name in ("shadow_terminator_geometry_offset", "shadow_terminator_offset"):
        if name in ob.bl_rna.properties.keys():
            SetProperty(ob, name, 0.0)


def AddSphere(bpy, name, centre, radius, material, u=512, v=256):
    """A smooth-shaded UV sphere of 512 x 256 segments: its chord error, r (1 - cos(pi/512))
    = 1.9e-5 r, is far below a pixel. (Cycles' point-cloud spheres would be exact, but seen
    through Blender 3.4's point-cloud glass sphere the image disagreed with glint by up to
    119 sigma per block, where this mesh agrees within 2.2 sigma.) Built with numpy:
    bmesh's create_uvsphere took 19 s for it."""
    import numpy as np
    theta = np.pi * np.arange(1, v) / v  # the v - 1 rings between the poles
    phi = 2.0 * np.pi * np.arange(u) / u
    st, ct = np.sin(theta)[:, None], np.cos(theta)[:, None]
    rings = radius * np.stack([st * np.cos(phi), st * np.sin(phi), ct * np.ones_like(phi)], -1)
    vertices = np.vstack([[0.0, 0.0, radius], rings.reshape(-1, 3), [0.0, 0.0, -radius]])
    last = len(vertices) - 1
    j = np.arange(u)
    ring0 = 1 + j
    # Counter-clockwise seen from outside, so that every normal points out (glass needs it).
    faces = [[0, int(a), int(b)] for a, b in zip(ring0, 1 + (j + 1) % u)]
    for i in range(v - 2):
        a = 1 + i * u + j
        b = 1 + i * u + (j + 1) % u
        faces += np.stack([a, a + u, b + u, b], -1).tolist()
    lastRing = 1 + (v - 2) * u
    faces += [[last, int(lastRing + (k + 1) % u), int(lastRing + k)] for k in j]
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(vertices.tolist(), [], faces)
    mesh.polygons.foreach_set("use_smooth", [True] * len(mesh.polygons))
    mesh.update()
    normals = np.zeros(3 * len(mesh.polygons))
    centres = np.zeros(3 * len(mesh.polygons))
    mesh.polygons.foreach_get("normal", normals)
    mesh.polygons.foreach_get("center", centres)
    if np.min(np.sum(normals.reshape(-1, 3) * centres.reshape(-1, 3), axis=1)) <= 0.0:
        raise RuntimeError(f"sphere {name}: a face normal points inward")
    mesh.materials.append(material)
    ob = bpy.data.objects.new(name, mesh)
    ob.location = tuple(centre)
    bpy.context.scene.collection.objects.link(ob)
    NoTerminatorOffset(ob)
    return ob


def BuildRoom(bpy, scene):
    room = scene["room"]
    p = room["position"]
    s = room["size"]
    x0, y0, z0 = p
    x1, y1, z1 = x0 + s, y0 + s, z0 + s
    light = scene.get("area_light")
    # Faces listed counter-clockwise as seen from inside, so their normals point inward.
    sides = {
        "left": [(x0, y0, z1), (x0, y0, z0), (x0, y1, z0), (x0, y1, z1)],
        "right": [(x1, y0, z0), (x1, y0, z1), (x1, y1, z1), (x1, y1, z0)],
        "floor": [(x0, y0, z0), (x0, y0, z1), (x1, y0, z1), (x1, y0, z0)],
        "back": [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0)],
        "ceiling": [(x0, y1, z0), (x1, y1, z0), (x1, y1, z1), (x0, y1, z1)],
    }
    for i, wall in enumerate(room["walls"]):
        side = wall["side"]
        mat = Diffuse(bpy, f"wall-{side}", wall["reflectance"])
        if side == "ceiling" and light is not None:
            ob = BuildCeilingWithHole(bpy, (x0, x1, y1, z0, z1), light, mat)
        else:
            ob = AddMesh(bpy, wall.get("id", f"W{i + 1}"), sides[side], [[0, 1, 2, 3]], mat)
        CastsNoShadow(ob)
    if light is not None:
        lx0, lx1, lz0, lz1 = LightRect(light)
        ly = light["center"][1]
        # Counter-clockwise seen from below: the normal, and the emitting side, face down.
        AddMesh(bpy, "light", [(lx0, ly, lz0), (lx1, ly, lz0), (lx1, ly, lz1), (lx0, ly, lz1)],
                [[0, 1, 2, 3]], Emitter(bpy, "light", light["radiance"]))


def LightRect(light):
    cx, _, cz = light["center"]
    h = 0.5 * light["side"]
    return cx - h, cx + h, cz - h, cz + h


def BuildCeilingWithHole(bpy, box, light, mat):
    x0, x1, y, z0, z1 = box
    lx0, lx1, lz0, lz1 = LightRect(light)
    lx0, lx1 = max(lx0, x0), min(lx1, x1)
    lz0, lz1 = max(lz0, z0), min(lz1, z1)
    xs, zs = [x0, lx0, lx1, x1], [z0, lz0, lz1, z1]
    vertices = [(x, y, z) for z in zs for x in xs]
    faces = []
    for j in range(3):
        for i in range(3):
            if i == 1 and j == 1:
                continue  # the light's square
            a = j * 4 + i
            # Counter-clockwise seen from below (normal -y): (x, z), (x+, z), (x+, z+), (x, z+).
            face = [a, a + 1, a + 5, a + 4]
            if xs[i + 1] > xs[i] and zs[j + 1] > zs[j]:
                faces.append(face)
    return AddMesh(bpy, "W2", vertices, faces, mat)


def BuildObjects(bpy, scene):
    for i, o in enumerate(scene.get("objects", [])):
        name = o.get("id", f"O{i + 1}")
        kind = o["material"]
        if kind == "mirror":
            mat = Mirror(bpy, name, o["reflectance"])
        elif kind == "glass":
            mat = Glass(bpy, name, o["ior"])
        elif kind == "lambertian":
            mat = Diffuse(bpy, name, o["reflectance"])
        else:
            raise UsageError(
                f"/objects/{i}/material: expected mirror, glass or lambertian, found \"{kind}\" "
                "(glint's Phong lobe is zero where R.psi <= 0; no Cycles BSDF has it, not even "
                "at exponent 0)")
        if o["type"] == "sphere":
            AddSphere(bpy, name, o["center"], o["radius"], mat)
        elif o["type"] == "cube":
            (x0, y0, z0), s = o["position"], o["size"]
            x1, y1, z1 = x0 + s, y0 + s, z0 + s
            v = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
                 (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
            # Outward normals (counter-clockwise seen from outside).
            faces = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 4, 7, 3], [1, 2, 6, 5], [0, 1, 5, 4],
                     [3, 7, 6, 2]]
            AddMesh(bpy, name, v, faces, mat)
        else:
            raise UsageError(f"/objects/{i}/type: expected sphere or cube, found {o['type']}")


def BuildCamera(bpy, scene, width, height):
    room = scene["room"]
    eye = scene["camera"]["eye"]
    front = room["position"][2] + room["size"]
    # The scene's view plane distance, or the set-up rule's, which puts the view plane in
    # the front opening; the plane's height is the room's size either way.
    distance = scene["camera"].get("view_plane_distance", eye[2] - front)
    cam_data = bpy.data.cameras.new("camera")
    SetProperties(cam_data, type="PERSP", sensor_fit="VERTICAL", clip_start=1e-4,
                  clip_end=1e4)
    SetProperty(cam_data, "angle_y", 2.0 * math.atan(0.5 * room["size"] / distance))
    cam = bpy.data.objects.new("camera", cam_data)
    cam.location = tuple(eye)
    cam.rotation_euler = (0.0, 0.0, 0.0)  # Blender's camera looks down -z with +y up
    bpy.context.scene.collection.objects.link(cam)
    bpy.context.scene.camera = cam


def ConfigureRender(bpy, args, width, height):
    sc = bpy.context.scene
    r = sc.render
    SetProperty(r, "engine", "CYCLES")
    SetProperties(r, resolution_x=width, resolution_y=height, resolution_percentage=100,
                  pixel_aspect_x=1.0, pixel_aspect_y=1.0, use_border=False,
                  use_compositing=False, use_sequencer=False, film_transparent=False,
                  use_persistent_data=False)
    if args.threads > 0:
        SetProperties(r, threads_mode="FIXED", threads=args.threads)
    else:
        SetProperty(r, "threads_mode", "AUTO")
    c = sc.cycles
    SetProperties(c, device="CPU", samples=args.spp, seed=args.seed, use_animated_seed=False,
                  use_adaptive_sampling=False, use_denoising=False, time_limit=0.0,
                  pixel_filter_type="BOX", filter_width=1.0,
                  sample_clamp_direct=0.0, sample_clamp_indirect=0.0, blur_glossy=0.0,
                  caustics_reflective=True, caustics_refractive=True,
                  max_bounces=64, diffuse_bounces=0 if args.walls == "terminal" else 64,
                  glossy_bounces=64, transmission_bounces=64, transparent_max_bounces=64,
                  volume_bounces=0, min_light_bounces=0, light_sampling_threshold=0.0,
                  film_exposure=1.0, use_fast_gi=False)
    if "use_guiding" in c.bl_rna.properties.keys():
        SetProperty(c, "use_guiding", False)
    layer = sc.view_layers[0]
    if "use_denoising" in layer.cycles.bl_rna.properties.keys():
        SetProperty(layer.cycles, "use_denoising", False)
    SetProperties(sc.view_settings, view_transform="Standard", look="None", exposure=0.0,
                  gamma=1.0)
    world = bpy.data.worlds.new("black")
    SetProperty(world, "use_nodes", True)
    background = world.node_tree.nodes["Background"]
    SetInput(background, "Color", (0.0, 0.0, 0.0, 1.0))
    SetInput(background, "Strength", 0.0)
    sc.world = world
    settings = r.image_settings
    SetProperties(settings, file_format="OPEN_EXR", color_depth="32", color_mode="RGB",
                  exr_codec="ZIP")


def WritePfm(path, width, height, rgba):
    # rgba: Blender's pixels, bottom row first, as PFM stores them.
    rows = bytearray(b"PF\n%d %d\n-1.0\n" % (width, height))
    floats = [0.0] * (width * height * 3)
    floats[0::3] = rgba[0::4]
    floats[1::3] = rgba[1::4]
    floats[2::3] = rgba[2::4]
    rows += struct.pack("<%df" % len(floats), *floats)
    tmp = path + ".tmp-cycles"
    with open(tmp, "wb") as f:
        f.write(rows)
    os.replace(tmp, path)


def Main(argv):
    args = ParseArgs(argv)
    import bpy  # only inside Blender (--help works without it)

    try:
        with open(args.scene) as f:
            scene = json.load(f)
    except (OSError, ValueError) as e:
        raise UsageError(f"{args.scene}: {e}")
    width, height = ParseSize(args.size, scene)
    built = time.monotonic()
    bpy.ops.wm.read_factory_settings(use_empty=True)
    BuildRoom(bpy, scene)
    BuildObjects(bpy, scene)
    BuildCamera(bpy, scene, width, height)
    ConfigureRender(bpy, args, width, height)
    if args.blend:
        bpy.ops.wm.save_as_mainfile(filepath=os.path.abspath(args.blend))
    exr = os.path.abspath(args.output + ".tmp-cycles.exr")
    bpy.context.scene.render.filepath = exr
    start = time.monotonic()
    built = start - built
    bpy.ops.render.render(write_still=True)
    seconds = time.monotonic() - start
    if not os.path.exists(exr):
        raise RuntimeError("Cycles wrote no image")
    if args.output.lower().endswith(".exr"):
        os.replace(exr, args.output)
    else:
        image = bpy.data.images.load(exr)
        if tuple(image.size) != (width, height):
            raise RuntimeError(f"Cycles' image is {tuple(image.size)}, not {(width, height)}")
        rgba = [0.0] * (width * height * 4)
        image.pixels.foreach_get(rgba)
        WritePfm(args.output, width, height, rgba)
        os.remove(exr)
    threads = bpy.context.scene.render.threads
    print(f"{PREFIX} {os.path.basename(args.scene)} {width}x{height}, {args.spp} samples/pixel, "
          f"walls {args.walls}, seed {args.seed}, {threads} threads: {seconds:.2f} s render "
          f"(the scene built in {built:.2f} s, written in {time.monotonic() - start - seconds:.2f} s)"
          f" -> {args.output}", flush=True)


if __name__ == "__main__":
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else sys.argv[1:]
    try:
        Main(argv)
    except UsageError as e:
        Fail(str(e))
    except SystemExit:
        raise
    except Exception as e:  # a Blender property that does not exist, and the like
        print(f"{PREFIX} error: {type(e).__name__}: {e}", flush=True)
        sys.exit(3)
