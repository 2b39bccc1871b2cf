# Blender's own glTF importer (io_scene_gltf2, run headless) imports hullcook's plain .glb of the
# sample sprites: one object per asset, named after it, whose mesh holds the finest level's hull
# vertices that `hullcook inspect --json` prints, and as many triangles as the hulls' fans.
#
# Usage: blender -b --factory-startup --python blender_import.py -- FILE.glb INSPECT.json
# Prints "blender: ..." lines; exits 1 on any mismatch, 0 when all match.
import json
import sys

import bpy
import numpy

# Debian 12's Blender 3.4.1 importer still writes numpy.bool, which Debian's numpy 1.24 removed
# (the alias had meant the builtin bool since numpy 1.20); restore the alias so the unmodified
# importer runs. This is Blender's own bug, not hullcook's.
if not hasattr(numpy, "bool") or numpy.bool is not bool:
    numpy.bool = bool

glb, inspect_json = sys.argv[sys.argv.index("--") + 1:][:2]
with open(inspect_json) as f:
    assets = json.load(f)["assets"]

failures = []


def fail(message):
    if len(failures) < 20:
        print("blender:   FAIL " + message)
    failures.append(message)


bpy.ops.wm.read_factory_settings(use_empty=True)
result = bpy.ops.import_scene.gltf(filepath=glb)
if result != {"FINISHED"}:
    print("blender: the import did not finish: %s" % result)
    sys.exit(1)

objects = {o.name: o for o in bpy.data.objects}
if len(objects) != len(assets):
    fail("%d objects for %d assets" % (len(objects), len(assets)))

checked = 0
for asset in assets:
    hulls = asset["levels"][0]["hulls"] if asset["levels"] else []
    points = [p for hull in hulls for p in hull]
    # Blender truncates object names at 63 bytes.
    obj = objects.get(asset["name"][:63])
    if obj is None:
        fail("no object named %s" % asset["name"])
        continue
    if not points:
        if obj.type == "MESH" and len(obj.data.vertices):
            fail("%s: vertices for an asset without hulls" % asset["name"])
        continue
    if obj.type != "MESH":
        fail("%s: a %s, not a mesh" % (asset["name"], obj.type))
        continue
    mesh = obj.data
    # glTF is Y-up, Blender Z-up: the importer maps glTF (x, y, z) to Blender (x, -z, y).
    read = []
    for v in mesh.vertices:
        w = obj.matrix_world @ v.co
        read.append((w.x, w.z, -w.y))
    if len(read) != len(points):
        fail("%s: %d vertices, expected %d" % (asset["name"], len(read), len(points)))
    for i, ((x, y), (bx, by, bz)) in enumerate(zip(points, read)):
        # The plain .glb stores float32: compare against the float32 of what inspect prints.
        fx, fy = numpy.float32(x), numpy.float32(y)
        if (abs(bx - fx) > 1e-6 * max(1.0, abs(fx)) or abs(by - fy) > 1e-6 * max(1.0, abs(fy))
                or abs(bz) > 1e-12):
            fail("%s vertex %d: (%r, %r, %r) for (%r, %r)" % (asset["name"], i, bx, by, bz, x, y))
            break
    triangles = sum(max(0, len(hull) - 2) for hull in hulls)
    if len(mesh.polygons) != triangles:
        fail("%s: %d faces, expected %d triangles" % (asset["name"], len(mesh.polygons), triangles))
    checked += len(points)

print("blender: %s, %d objects, %d finest-level vertices checked" % (glb, len(objects), checked))
if checked == 0:
    fail("no vertex checked")
if failures:
    print("blender: %d failures" % len(failures))
    sys.exit(1)
print("blender: Blender imports every asset with the hulls inspect prints")
sys.exit(0)
