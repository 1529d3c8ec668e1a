"""Menu and shelf entries: SMPL > Bind correctives / Bake correctives.

    import smpl_maya.menu; smpl_maya.menu.install()        # e.g. from userSetup.py
"""
from maya import cmds

from . import bind as smpl_bind

MENU = "smplExportMenu"
SHELF = "SMPL"


def bind_selected(*_args):
    """Bind every selected skinned mesh; asks for the sidecar <file>.smpl.json."""
    meshes = cmds.ls(selection=True, long=True) or []
    if not meshes:
        cmds.warning("smpl_maya: select the imported body mesh first")
        return []
    picked = cmds.fileDialog2(fileFilter="smpl-export metadata (*.smpl.json)", fileMode=1,
                              caption="Sidecar metadata (cancel: bind by names only)")
    nodes = []
    for mesh in meshes:
        try:
            nodes.append(smpl_bind.bind(mesh, picked[0] if picked else None))
        except RuntimeError as e:
            cmds.warning(str(e))
    return nodes


def bake_selected(*_args):
    """Bake the correctives of the selected smplCorrectives nodes (or of all)
    over the playback range."""
    nodes = cmds.ls(selection=True, type="smplCorrectives") or cmds.ls(type="smplCorrectives") or []
    start = cmds.playbackOptions(query=True, minTime=True)
    end = cmds.playbackOptions(query=True, maxTime=True)
    for node in nodes:
        smpl_bind.bake(node, start, end)
    return nodes


def install():
    """Create the SMPL menu in the main window and the SMPL shelf (idempotent)."""
    if cmds.menu(MENU, exists=True):
        cmds.deleteUI(MENU)
    cmds.menu(MENU, label="SMPL", parent="MayaWindow", tearOff=True)
    cmds.menuItem(label="Bind correctives", command=bind_selected,
                  annotation="Drive the selected body's pose-corrective blend shapes from its joints")
    cmds.menuItem(label="Bake correctives", command=bake_selected,
                  annotation="Key the corrective weights over the playback range")
    if not cmds.shelfLayout(SHELF, exists=True):
        cmds.shelfLayout(SHELF, parent="ShelfLayout")
    for label, fn in (("Bind", "bind_selected"), ("Bake", "bake_selected")):
        cmds.shelfButton(parent=SHELF, label=label, imageOverlayLabel=label, image="pythonFamily.png",
                         sourceType="python", command="import smpl_maya.menu as m; m.%s()" % fn)
