"""Blender's own exporters on our content, for smpl-bench --compare.

Run: blender -b --factory-startup --python blender_export_time.py -- IN.glb OUTDIR
Imports IN.glb (the asset smpl-export wrote: skinned mesh, armature, shape
keys), then times Blender's glTF (GLB) and FBX exporters writing the same
scene, each once, and prints one machine-readable line per exporter:
  BLENDER_EXPORT gltf <wall seconds> <CPU seconds> <bytes>
  BLENDER_EXPORT fbx <wall seconds> <CPU seconds> <bytes>
The import itself is not timed.
"""
import os
import sys
import time

import numpy as np

if not hasattr(np, "bool"):
    np.bool = bool  # Blender 3.4's glTF importer with Debian's numpy >= 1.24

import bpy  # noqa: E402


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(argv) != 2:
        raise SystemExit("usage: blender -b --python blender_export_time.py -- IN.glb OUTDIR")
    src, outdir = argv
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=src)
    meshes = [o for o in bpy.data.objects if o.type == "MESH"]
    keys = sum(len(o.data.shape_keys.key_blocks) if o.data.shape_keys else 0 for o in meshes)
    print("BLENDER_SCENE meshes %d vertices %d shape_keys %d" %
          (len(meshes), sum(len(o.data.vertices) for o in meshes), keys))
    runs = [("gltf", os.path.join(outdir, "blender_export.glb"),
             lambda p: bpy.ops.export_scene.gltf(filepath=p, export_format="GLB", export_morph=True,
                                                 export_skins=True, export_animations=False)),
            ("fbx", os.path.join(outdir, "blender_export.fbx"),
             lambda p: bpy.ops.export_scene.fbx(filepath=p, add_leaf_bones=False, bake_anim=False))]
    for name, path, export in runs:
        start, cpu = time.perf_counter(), time.process_time()
        result = export(path)
        seconds, cpu = time.perf_counter() - start, time.process_time() - cpu
        if "FINISHED" not in result:
            raise SystemExit("Blender's %s exporter failed: %s" % (name, result))
        print("BLENDER_EXPORT %s %.4f %.4f %d" % (name, seconds, cpu, os.path.getsize(path)))


main()
