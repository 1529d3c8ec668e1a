"""SMPL correctives: drive the pose-corrective shape keys of assets written by
smpl-export from the bone rotations, so Blender reproduces the body model's
own output (docs/file-contract.md, "The robust runtime formula"). The math lives in
core.py (numpy only, shared with the Maya package), its Blender glue in
correctives.py, importable without the UI; this file is the panel and the
operators (3D View > Sidebar > SMPL; File > Import > SMPL asset).

Packaging: bl_info serves Blender 3.x-4.1 add-on installs;
blender_manifest.toml beside it serves Blender 4.2+ extensions. The version in
both is checked against the repository's VERSION file by
scripts/check-version.py.
"""
import os

import bpy
from bpy.props import BoolProperty, StringProperty
from bpy_extras.io_utils import ImportHelper
from mathutils import Matrix

from . import correctives

bl_info = {
    "name": "SMPL Correctives",
    "author": "smpl-export",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "3D View > Sidebar > SMPL, File > Import > SMPL asset",
    "description": "Drive SMPL pose-corrective shape keys from the armature pose",
    "category": "Animation",
}


def _pairs(context):
    """(armature, mesh) pairs selected by the user: an armature drives all its
    skinned meshes; a mesh is driven by the armature of its modifier."""
    pairs = []
    selected = getattr(context, "selected_objects", None) or []
    active = getattr(context, "active_object", None)
    for obj in selected or ([active] if active else []):
        if obj.type == "ARMATURE":
            pairs += [(obj, m) for m in correctives.skinned_meshes(obj)
                      if m.data is not None and m.data.shape_keys]
        elif obj.type == "MESH" and obj.data is not None and obj.data.shape_keys:
            arm = correctives.armature_of(obj)
            if arm is not None:
                pairs.append((arm, obj))
    return list(dict.fromkeys(pairs))


class SMPL_OT_enable(bpy.types.Operator):
    """Drive the selected body's corrective shape keys every frame"""
    bl_idname = "smpl.enable_correctives"
    bl_label = "Enable"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        return bool(_pairs(context))

    def execute(self, context):
        pairs = _pairs(context)
        if not pairs:
            self.report({"ERROR"}, "Select an armature or a skinned mesh with shape keys")
            return {"CANCELLED"}
        for arm, mesh in pairs:
            correctives.enable(arm, mesh)
        self.report({"INFO"}, "SMPL correctives enabled on %d mesh(es)" % len(pairs))
        return {"FINISHED"}


class SMPL_OT_disable(bpy.types.Operator):
    """Stop driving the selected body's corrective shape keys"""
    bl_idname = "smpl.disable_correctives"
    bl_label = "Disable"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        return any(correctives.is_enabled(a, m) for a, m in _pairs(context))

    def execute(self, context):
        for arm, mesh in _pairs(context):
            correctives.disable(arm, mesh)
        return {"FINISHED"}


PROP_GROUND_OFFSET = "smpl_ground_offset_m"  # on the armature: the lift feet on ground applied


def _clip_fps(filepath):
    """The first baked clip's fps from the file's metadata (animations[0].fps), or None."""
    meta = correctives.metadata_from_file(filepath) or {}
    clips = meta.get("animations")
    if isinstance(clips, list) and clips and isinstance(clips[0], dict):
        fps = clips[0].get("fps")
        if isinstance(fps, (int, float)) and fps > 0:
            return float(fps)
    return None


def _set_scene_fps(scene, fps):
    """scene.render.fps / fps_base = fps (integer fps, fps_base for rates such as 29.97)."""
    scene.render.fps = max(1, int(round(fps)))
    scene.render.fps_base = scene.render.fps / fps


def _action_range(objects):
    """(first, last) integer frame covering the active actions of the objects
    and of their shape keys, or None if none is animated."""
    import math
    ranges = []
    for obj in objects:
        for owner in (obj, getattr(getattr(obj, "data", None), "shape_keys", None)):
            ad = getattr(owner, "animation_data", None)
            if ad is not None and ad.action is not None:
                ranges.append(tuple(ad.action.frame_range))
    if not ranges:
        return None
    return int(math.floor(min(r[0] for r in ranges))), int(math.ceil(max(r[1] for r in ranges)))


def _lowest_z(meshes, depsgraph):
    """Lowest world z (metres, Blender's Z up) of the evaluated meshes."""
    lowest = float("inf")
    for mesh_obj in meshes:
        ev = mesh_obj.evaluated_get(depsgraph)
        me = ev.to_mesh()
        if len(me.vertices):
            import numpy as np
            co = np.empty(len(me.vertices) * 3, dtype=np.float64)
            me.vertices.foreach_get("co", co)
            m = np.array(ev.matrix_world)
            z = co.reshape(-1, 3) @ m[2, :3] + m[2, 3]
            lowest = min(lowest, float(z.min()))
        ev.to_mesh_clear()
    return lowest


def put_on_ground(scene, objects, frames=None):
    """Lift the imported objects (their top-level ones, as one rigid move
    along world Z) so that the lowest vertex of their meshes is at z = 0:
    over every frame of `frames` (first, last) if given (the clip, posed with
    its correctives), else in the current pose. Bones and shape keys are not
    touched, so the correctives are unaffected. Returns the lift in metres
    (also stored as the armature property smpl_ground_offset_m), or None if
    there is no mesh."""
    meshes = [o for o in objects if o.type == "MESH"]
    if not meshes:
        return None
    depsgraph = bpy.context.evaluated_depsgraph_get()
    if frames is None:
        lowest = _lowest_z(meshes, depsgraph)
    else:
        current = scene.frame_current
        lowest = float("inf")
        for frame in range(frames[0], frames[1] + 1):
            scene.frame_set(frame)
            lowest = min(lowest, _lowest_z(meshes, bpy.context.evaluated_depsgraph_get()))
        scene.frame_set(current)
    if lowest == float("inf"):
        return None
    inside = set(objects)
    for obj in objects:
        if obj.parent not in inside:
            obj.matrix_world = Matrix.Translation((0.0, 0.0, -lowest)) @ obj.matrix_world
    for obj in objects:
        if obj.type == "ARMATURE":
            obj[PROP_GROUND_OFFSET] = -lowest
    bpy.context.view_layer.update()
    return -lowest


def import_asset(filepath, feet_on_ground=False, set_timeline=True):
    """Import a .glb/.gltf/.fbx written by smpl-export, bind and enable its
    correctives. Returns the list of (armature, mesh) pairs bound.

    set_timeline: for a file with a baked clip, the scene rate is set to the
    clip's fps (metadata animations[0].fps) before a glTF import (the glTF
    importer keys at t x scene fps; the FBX importer sets it from the file),
    and the scene's frame range to the imported actions' range.
    feet_on_ground: lift the body so its lowest vertex is at z = 0 over the
    whole clip (or in the rest pose without one); see put_on_ground."""
    ext = os.path.splitext(filepath)[1].lower()
    scene = bpy.context.scene
    before = set(bpy.data.objects)
    if ext in (".glb", ".gltf"):
        import numpy as np
        if not hasattr(np, "bool"):  # Debian numpy vs Blender 3.4's glTF importer
            np.bool = bool
        fps = _clip_fps(filepath) if set_timeline else None
        if fps is not None:
            _set_scene_fps(scene, fps)
        bpy.ops.import_scene.gltf(filepath=filepath)
    elif ext == ".fbx":
        bpy.ops.import_scene.fbx(filepath=filepath)
    else:
        raise ValueError("%s: not a .glb, .gltf or .fbx file" % filepath)
    new = [o for o in bpy.data.objects if o not in before]
    pairs = [(a, m) for a in new if a.type == "ARMATURE"
             for m in correctives.skinned_meshes(a) if m.data.shape_keys]
    for arm, mesh in pairs:
        correctives.bind(arm, mesh, source_path=filepath)
        correctives.enable(arm, mesh)
    frames = _action_range(new)
    if set_timeline and frames is not None:
        scene.frame_start, scene.frame_end = frames
        scene.frame_set(frames[0])
    if feet_on_ground:
        put_on_ground(scene, new, frames)
    return pairs


class SMPL_OT_import(bpy.types.Operator, ImportHelper):
    """Import an SMPL asset (glTF/GLB/FBX) and drive its correctives"""
    bl_idname = "smpl.import_asset"
    bl_label = "Import SMPL asset"
    bl_options = {"REGISTER", "UNDO"}

    @classmethod
    def poll(cls, context):
        return context.mode == "OBJECT"

    filter_glob: StringProperty(default="*.glb;*.gltf;*.fbx", options={"HIDDEN"})
    feet_on_ground: BoolProperty(
        name="Feet on ground", default=True,
        description="Lift the body so its lowest point (over the whole clip, or in the rest pose) is at Z = 0")
    set_timeline: BoolProperty(
        name="Set timeline to clip", default=True,
        description="Set the scene's frame rate and frame range to the imported clip's")

    def execute(self, context):
        try:
            pairs = import_asset(self.filepath, feet_on_ground=self.feet_on_ground,
                                 set_timeline=self.set_timeline)
        except (ValueError, RuntimeError) as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        if not pairs:
            self.report({"WARNING"}, "%s: no skinned mesh with shape keys found" % self.filepath)
        return {"FINISHED"}


class SMPL_PT_panel(bpy.types.Panel):
    bl_label = "SMPL Correctives"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "SMPL"

    def draw(self, context):
        col = self.layout.column(align=True)
        col.operator(SMPL_OT_import.bl_idname, icon="IMPORT")
        row = col.row(align=True)
        row.operator(SMPL_OT_enable.bl_idname, icon="PLAY")
        row.operator(SMPL_OT_disable.bl_idname, icon="PAUSE")
        for arm, mesh in _pairs(context):
            state = "driven" if correctives.is_enabled(arm, mesh) else "off"
            col.label(text="%s: %s" % (mesh.name, state))


_classes = (SMPL_OT_enable, SMPL_OT_disable, SMPL_OT_import, SMPL_PT_panel)


def _menu_import(self, context):
    """File > Import > SMPL asset (smpl-export .glb/.gltf/.fbx)."""
    self.layout.operator(SMPL_OT_import.bl_idname, text="SMPL asset (smpl-export .glb/.fbx)")


def register():
    for cls in _classes:
        bpy.utils.register_class(cls)
    bpy.types.TOPBAR_MT_file_import.append(_menu_import)
    correctives.register_load_handler(True)


def unregister():
    correctives.register_load_handler(False)
    bpy.types.TOPBAR_MT_file_import.remove(_menu_import)
    for cls in reversed(_classes):
        bpy.utils.unregister_class(cls)
