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
from bpy.props import StringProperty
from bpy_extras.io_utils import ImportHelper

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


def import_asset(filepath):
    """Import a .glb/.gltf/.fbx written by smpl-export, bind and enable its
    correctives. Returns the list of (armature, mesh) pairs bound."""
    ext = os.path.splitext(filepath)[1].lower()
    before = set(bpy.data.objects)
    if ext in (".glb", ".gltf"):
        import numpy as np
        if not hasattr(np, "bool"):  # Debian numpy vs Blender 3.4's glTF importer
            np.bool = bool
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

    def execute(self, context):
        try:
            pairs = import_asset(self.filepath)
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
