"""Stand-in for maya.cmds over a tiny in-memory scene (SCENE): nodes with a
type, attributes and parents; plug connections dest -> source; a current time
whose change calls SCENE.on_time (the test poses the joints there). Reading a
blendShape weight driven by a plug-in node runs that node's compute() through
maya.api.OpenMaya's fake data block, as Maya's graph would."""
import os
import runpy

from maya.api import OpenMaya


class Scene:
    def __init__(self):
        self.nodes = {}        # name -> {"type", "attrs": {}, "parent", "world": 16 values, "instance"}
        self.connections = {}  # destination plug -> source plug
        self.history = {}      # mesh -> deformer names
        self.aliases = {}      # blendShape -> [alias, "weight[i]", ...]
        self.keys = {}         # plug -> {frame: value}
        self.time = 0.0
        self.on_time = None
        self.up = "y"
        self.loaded = set()
        self.ui = []           # (command, name or label) of menu/shelf calls
        self.warnings = []
        self.cache = {}        # node -> outWeight values, until the graph changes (Maya's clean plugs)

    def add(self, name, node_type, parent=None, **attrs):
        self.nodes[name] = {"type": node_type, "attrs": dict(attrs), "parent": parent, "world": None}
        return name


SCENE = Scene()


def reset():
    global SCENE
    SCENE = Scene()
    return SCENE


def _node(plug):
    return plug.split(".", 1)[0]


def warning(text):
    SCENE.warnings.append(text)


def pluginInfo(name, query=False, loaded=False):
    return name in SCENE.loaded


def loadPlugin(filename, quiet=False):
    """Runs the plug-in file found on MAYA_PLUG_IN_PATH and its initializePlugin, as Maya does."""
    for folder in os.environ.get("MAYA_PLUG_IN_PATH", "").split(os.pathsep):
        path = os.path.join(folder, filename)
        if folder and os.path.isfile(path):
            module = runpy.run_path(path)
            assert callable(module["maya_useNewAPI"])
            module["initializePlugin"](object())
            SCENE.loaded.add(os.path.splitext(filename)[0])
            return [os.path.splitext(filename)[0]]
    raise RuntimeError("Plug-in, \"%s\", was not found on MAYA_PLUG_IN_PATH" % filename)


def ls(items=None, type=None, selection=False, long=False):
    if selection:
        items = list(getattr(SCENE, "selection", []))
    names = list(SCENE.nodes) if items is None else [i for i in items if i in SCENE.nodes]
    return [n for n in names if type is None or SCENE.nodes[n]["type"] == type]


def listHistory(node):
    return list(SCENE.history.get(node, []))


def listRelatives(node, parent=False, type=None):
    p = SCENE.nodes[node]["parent"]
    return [p] if parent and p and (type is None or SCENE.nodes[p]["type"] == type) else None


def aliasAttr(node, query=False):
    return list(SCENE.aliases.get(node, []))


def upAxis(query=False, axis=False):
    return SCENE.up


def connectionInfo(plug, sourceFromDestination=False):
    return SCENE.connections.get(plug, "")


def createNode(node_type, name=None):
    type_id, creator, attrs, _ = OpenMaya.MFnPlugin.registered[node_type]
    SCENE.add(name, node_type)
    SCENE.nodes[name]["instance"] = creator()
    SCENE.nodes[name]["attr_objects"] = attrs
    return name


def setAttr(plug, value, type=None):
    SCENE.cache.clear()
    SCENE.nodes[_node(plug)]["attrs"][plug.split(".", 1)[1]] = value


def connectAttr(source, destination, force=False):
    if destination in SCENE.connections and not force:
        raise RuntimeError("%s already has an incoming connection" % destination)
    SCENE.cache.clear()
    SCENE.connections[destination] = source


def listConnections(plug, source=True, destination=True, plugs=False):
    return sorted(d for d, s in SCENE.connections.items() if s.startswith(plug + "[") or s == plug)


def delete(node):
    SCENE.cache.clear()
    del SCENE.nodes[node]
    for d, s in list(SCENE.connections.items()):
        if _node(d) == node or _node(s) == node:
            del SCENE.connections[d]


def currentTime(frame=None, query=False, update=True):
    if query:
        return SCENE.time
    SCENE.time = frame
    SCENE.cache.clear()
    if SCENE.on_time:
        SCENE.on_time(frame)
    return frame


def setKeyframe(plug, time=None, value=None):
    SCENE.keys.setdefault(plug, {})[time] = value


def _evaluate(node):
    """Runs the plug-in node's compute() for its outWeight array (once per graph state)."""
    if node in SCENE.cache:
        return SCENE.cache[node]
    entry = SCENE.nodes[node]
    attrs = entry["attr_objects"]
    matrices = {}
    for d, s in SCENE.connections.items():
        if d.startswith(node + ".inMatrix["):
            assert s.endswith(".worldMatrix[0]"), s
            matrices[int(d[len(node) + 10:-1])] = SCENE.nodes[_node(s)]["world"]
    block = OpenMaya.MDataBlock({"layout": entry["attrs"].get("layout"), "inMatrix": matrices})
    entry["instance"].compute(OpenMaya.MPlug(attrs["outWeight"]), block)
    assert "outWeight" in block.clean
    SCENE.cache[node] = block.outputs.get("outWeight", {})
    return SCENE.cache[node]


def getAttr(plug, multiIndices=False):
    node, attr = plug.split(".", 1)
    if multiIndices:
        return sorted(int(d[len(plug) + 1:-1]) for d in SCENE.connections if d.startswith(plug + "["))
    source = SCENE.connections.get(plug)
    if source and SCENE.nodes[_node(source)].get("instance") is not None:
        return _evaluate(_node(source)).get(int(source.rsplit("[", 1)[1][:-1]), 0.0)
    if source:
        raise RuntimeError("fake getAttr: unsupported source %s" % source)
    return SCENE.nodes[node]["attrs"][attr]


def playbackOptions(query=False, minTime=False, maxTime=False):
    return SCENE.ui_range[0] if minTime else SCENE.ui_range[1]


def fileDialog2(**kwargs):
    SCENE.ui.append(("fileDialog2", kwargs.get("caption")))
    return getattr(SCENE, "dialog_answer", None)


def menu(name, exists=False, **kwargs):
    if exists:
        return any(c == "menu" and n == name for c, n in SCENE.ui)
    SCENE.ui.append(("menu", name))
    return name


def deleteUI(name):
    SCENE.ui = [(c, n) for c, n in SCENE.ui if n != name]


def menuItem(label=None, command=None, annotation=None):
    SCENE.ui.append(("menuItem", label))
    SCENE.commands = getattr(SCENE, "commands", {})
    SCENE.commands[label] = command


def shelfLayout(name, exists=False, parent=None):
    if exists:
        return any(c == "shelfLayout" and n == name for c, n in SCENE.ui)
    SCENE.ui.append(("shelfLayout", name))
    return name


def shelfButton(parent=None, label=None, command=None, **kwargs):
    SCENE.ui.append(("shelfButton", label))
    compile(command, "<shelf %s>" % label, "exec")  # the button's command must be valid Python
