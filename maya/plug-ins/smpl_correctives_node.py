"""Maya plug-in file for the smplCorrectives dependency node (smpl_maya.node).
Load with cmds.loadPlugin("smpl_correctives_node.py") (the module file
smpl_maya.mod puts this folder on MAYA_PLUG_IN_PATH)."""
from smpl_maya.node import initializePlugin, maya_useNewAPI, uninitializePlugin  # noqa: F401

__all__ = ["initializePlugin", "maya_useNewAPI", "uninitializePlugin"]  # what Maya looks up
