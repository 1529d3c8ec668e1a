"""Blender side of scripts/render-picture.sh: import a GLB with Blender's own
glTF importer and render it (Workbench, studio light, 480 x 640).

    blender -b --factory-startup --python picture_blender.py -- BODY.glb OUT.png
"""
import sys

import bpy
import numpy as np
from mathutils import Vector

np.bool = bool  # Blender 3.4's glTF importer still uses the removed alias

glb, png = sys.argv[sys.argv.index("--") + 1:][:2]
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=glb)
scene = bpy.context.scene
scene.frame_set(0)
depsgraph = bpy.context.evaluated_depsgraph_get()
corners = []
for obj in scene.objects:
    if obj.type == "MESH":
        mesh = obj.evaluated_get(depsgraph).to_mesh()
        corners += [obj.matrix_world @ v.co for v in mesh.vertices]
lo = Vector([min(c[i] for c in corners) for i in range(3)])
hi = Vector([max(c[i] for c in corners) for i in range(3)])
center, height = (lo + hi) / 2, hi.z - lo.z

camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
scene.collection.objects.link(camera)
camera.data.lens = 85
distance = 2.7 * height
camera.location = center + Vector((0.45 * distance, -distance, 0.12 * height))
camera.rotation_euler = (center - camera.location).to_track_quat("-Z", "Y").to_euler()
scene.camera = camera

scene.render.engine = "BLENDER_WORKBENCH"
shading = scene.display.shading
shading.light = "STUDIO"
shading.color_type = "SINGLE"
shading.single_color = (0.80, 0.62, 0.50)
shading.show_cavity = True
shading.show_shadows = True
scene.render.film_transparent = True
scene.render.resolution_x, scene.render.resolution_y = 480, 640
scene.render.image_settings.file_format = "PNG"
scene.render.image_settings.color_mode = "RGBA"
scene.render.filepath = png
bpy.ops.render.render(write_still=True)
