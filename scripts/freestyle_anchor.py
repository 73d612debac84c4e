# The anchor a line style is held up against: Blender's Freestyle lines over a flat paper-coloured
# surface, from the orbit view `inkwire-render --view 35,15,1.3 --size 400x320` uses (45 degree
# vertical field of view). Optional, for comparing looks (docs/benchmarks-journal.md, looks);
# Blender is not one of the project's packages (`apt-get install blender`, 3.4 in Debian 12):
#   blender -b --factory-startup -P scripts/freestyle_anchor.py -- MODEL.obj|MODEL.dae OUT.png
import math
import sys

import bpy
import mathutils

PAPER = (0.96, 0.94, 0.9)
AZIMUTH, ELEVATION, DISTANCE_DIAGONALS = 35.0, 15.0, 1.3


def load_as_one_mesh(path):
    """Imports the model (Blender turns its up axis into +Z) and joins its meshes into one object."""
    if path.endswith('.dae'):
        bpy.ops.wm.collada_import(filepath=path)
    else:
        bpy.ops.wm.obj_import(filepath=path)
    for other in [o for o in bpy.context.scene.objects if o.type != 'MESH']:
        bpy.data.objects.remove(other)
    meshes = list(bpy.context.scene.objects)
    if not meshes:
        sys.exit(f'freestyle_anchor: {path} holds no mesh')
    bpy.ops.object.select_all(action='DESELECT')
    for m in meshes:
        m.select_set(True)
    bpy.context.view_layer.objects.active = meshes[0]
    if len(meshes) > 1:
        bpy.ops.object.join()
    return bpy.context.view_layer.objects.active


def orbit_camera(obj):
    """inkwire's orbit camera: azimuth about the up axis from the front, distance in bounding-box
    diagonals. Its (x, y, z) with y up is Blender's (x, -z, y)."""
    corners = [obj.matrix_world @ mathutils.Vector(c) for c in obj.bound_box]
    lo = mathutils.Vector([min(c[i] for c in corners) for i in range(3)])
    hi = mathutils.Vector([max(c[i] for c in corners) for i in range(3)])
    centre, diagonal = (lo + hi) / 2, (hi - lo).length
    az, el = math.radians(AZIMUTH), math.radians(ELEVATION)
    toward_eye = mathutils.Vector((math.sin(az) * math.cos(el), -math.cos(az) * math.cos(el), math.sin(el)))
    lens = bpy.data.cameras.new('camera')
    lens.sensor_fit = 'VERTICAL'
    lens.angle_y = math.radians(45)
    camera = bpy.data.objects.new('camera', lens)
    bpy.context.scene.collection.objects.link(camera)
    camera.location = centre + toward_eye * DISTANCE_DIAGONALS * diagonal
    camera.rotation_euler = (centre - camera.location).to_track_quat('-Z', 'Y').to_euler()
    return camera


def main():
    model, out = sys.argv[sys.argv.index('--') + 1:][:2]
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.camera = orbit_camera(load_as_one_mesh(model))
    # A flat surface the colour of the paper, so only the lines show.
    scene.world = bpy.data.worlds.new('paper')
    scene.world.color = PAPER
    scene.render.engine = 'BLENDER_WORKBENCH'
    shading = scene.display.shading
    shading.light, shading.color_type, shading.single_color, shading.background_type = 'FLAT', 'SINGLE', PAPER, 'WORLD'
    scene.view_settings.view_transform = 'Standard'  # colours as given, not tone-mapped
    scene.render.resolution_x, scene.render.resolution_y, scene.render.resolution_percentage = 400, 320, 100
    # Silhouettes, borders and creases as Freestyle's defaults draw them, in dark ink.
    scene.render.use_freestyle = True
    scene.render.line_thickness_mode = 'ABSOLUTE'
    settings = bpy.context.view_layer.freestyle_settings
    lines = settings.linesets[0] if settings.linesets else settings.linesets.new('lines')
    if lines.linestyle is None:
        lines.linestyle = bpy.data.linestyles.new('ink')
    lines.linestyle.color, lines.linestyle.thickness = (0.1, 0.1, 0.1), 1.2
    lines.select_silhouette = lines.select_border = lines.select_crease = True
    scene.render.filepath = out
    bpy.ops.render.render(write_still=True)


main()
