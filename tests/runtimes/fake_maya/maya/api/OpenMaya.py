"""Stand-in for maya.api.OpenMaya: the attribute classes the node creates, the
plug-in registration and a data block that feeds compute() from the fake scene."""


class MTypeId:
    def __init__(self, value):
        self.value = value


class MGlobal:
    errors = []

    @staticmethod
    def displayError(text):
        MGlobal.errors.append(text)


class MFnData:
    kString = "string"


class MFnNumericData:
    kDouble = "double"


class Attribute:
    def __init__(self, long_name, short_name, kind):
        self.name, self.short, self.kind = long_name, short_name, kind
        self.array = False
        self.usesArrayDataBuilder = False
        self.writable = self.storable = True


class _AttrFn:
    def __init__(self):
        self._attr = None

    def _make(self, long_name, short_name, kind):
        self._attr = Attribute(long_name, short_name, kind)
        return self._attr

    def __setattr__(self, key, value):  # MFnAttribute properties apply to the last created attribute
        if key != "_attr" and self._attr is not None:
            setattr(self._attr, key, value)
        else:
            object.__setattr__(self, key, value)


class MFnTypedAttribute(_AttrFn):
    def create(self, long_name, short_name, kind):
        return self._make(long_name, short_name, kind)


class MFnMatrixAttribute(_AttrFn):
    kDouble = "matrix"

    def create(self, long_name, short_name, kind=kDouble):
        return self._make(long_name, short_name, kind)


class MFnNumericAttribute(_AttrFn):
    def create(self, long_name, short_name, kind, default):
        return self._make(long_name, short_name, kind)


class MPxNode:
    attributes = []
    affects = []

    def __init__(self):
        pass

    @staticmethod
    def addAttribute(attr):
        MPxNode.attributes.append(attr)

    @staticmethod
    def attributeAffects(source, dest):
        MPxNode.affects.append((source.name, dest.name))


class MFnPlugin:
    registered = {}

    def __init__(self, obj, vendor=None, version=None, api=None):
        self.obj = obj

    def registerNode(self, name, type_id, creator, initialize):
        MPxNode.attributes, MPxNode.affects = [], []
        initialize()
        MFnPlugin.registered[name] = (type_id, creator, {a.name: a for a in MPxNode.attributes},
                                      list(MPxNode.affects))

    def deregisterNode(self, type_id):
        for name in [n for n, v in MFnPlugin.registered.items() if v[0] is type_id]:
            del MFnPlugin.registered[name]


# ---------------------------------------------------------------- data block

class MPlug:
    def __init__(self, attr, index=None):
        self.attr, self.index = attr, index
        self.isElement = index is not None

    def array(self):
        return self.attr

    def __eq__(self, other):
        return not self.isElement and other is self.attr

    def __ne__(self, other):
        return not self.__eq__(other)


class _Value:
    def __init__(self, value):
        self.value = value

    def asString(self):
        return self.value or ""

    def asMatrix(self):
        return list(self.value)  # MMatrix: 16 values, indexable m[i], row-vector layout


class _InputArray:
    def __init__(self, elements):
        self.elements = sorted(elements.items())  # physical order: logical indices ascending
        self.position = 0

    def __len__(self):
        return len(self.elements)

    def jumpToPhysicalElement(self, i):
        self.position = i

    def elementLogicalIndex(self):
        return self.elements[self.position][0]

    def inputValue(self):
        return _Value(self.elements[self.position][1])


class _Element:
    def __init__(self, store, index):
        self.store, self.index = store, index

    def setDouble(self, value):
        self.store[self.index] = value


class _Builder:
    def __init__(self):
        self.values = {}

    def addElement(self, index):
        return _Element(self.values, index)


class _OutputArray:
    def __init__(self, block, name):
        self.block, self.name = block, name

    def builder(self):
        return _Builder()

    def set(self, builder):
        self.block.outputs[self.name] = dict(builder.values)

    def setAllClean(self):
        self.block.clean.add(self.name)


class MDataBlock:
    """inputs: attribute name -> value (arrays: {logical index: value})."""

    def __init__(self, inputs):
        self.inputs, self.outputs, self.clean = inputs, {}, set()

    def inputValue(self, attr):
        return _Value(self.inputs.get(attr.name))

    def inputArrayValue(self, attr):
        return _InputArray(self.inputs.get(attr.name) or {})

    def outputArrayValue(self, attr):
        return _OutputArray(self, attr.name)

    def setClean(self, plug):
        self.clean.add(plug.attr.name)
