"""Sofa.Core: the scene graph (Node, objects, Data) and the bases of Python components."""
import _sinew

Base = _sinew.Base
Node = _sinew.Node
Object = _sinew.Object
BaseObject = _sinew.Object
BaseComponent = _sinew.Object
Data = _sinew.Data
DataContainer = _sinew.Data
Controller = _sinew.Controller
DataEngine = _sinew.DataEngine
ForceFieldVec1d = _sinew.ForceFieldVec1d
ForceFieldVec2d = _sinew.ForceFieldVec2d
ForceFieldVec3d = _sinew.ForceFieldVec3d
ForceFieldVec6d = _sinew.ForceFieldVec6d
ForceFieldRigid2d = _sinew.ForceFieldRigid2d
ForceFieldRigid3d = _sinew.ForceFieldRigid3d
TaskScheduler = _sinew.TaskScheduler
LinkPath = _sinew.LinkPath
BaseMass = _sinew.BaseMass

# SofaPython3's Mapping_<In>_<Out> and Mass<T> classes, as many as the module defines.
for _name in dir(_sinew):
    if _name.startswith("Mapping_") or (_name.startswith("Mass") and _name != "Mass"):
        globals()[_name] = getattr(_sinew, _name)
del _name


class ClassEntry:
    """One component class of the factory (SofaPython3's ObjectFactory entries)."""

    def __init__(self, info):
        self.className = info["className"]
        self.description = info["description"]
        self.category = info["category"]
        self.templates = list(info["templates"])
        self.defaultTemplate = info["defaultTemplate"]
        self.aliases = list(info["aliases"])

    @property
    def data(self):
        """The component's Data (name, type, default, help, group), for its default template."""
        return _sinew.component_fields(self.className, self.defaultTemplate)

    def __repr__(self):
        return "<ClassEntry " + self.className + ">"


class ObjectFactory:
    """The component factory: which classes exist (SofaPython3's Sofa.Core.ObjectFactory)."""

    @staticmethod
    def getComponentsList():
        return [ClassEntry(c) for c in _sinew.components()]

    @staticmethod
    def getComponent(name):
        for c in _sinew.components():
            if c["className"] == name or name in c["aliases"]:
                return ClassEntry(c)
        raise ValueError("no component named " + repr(name))

    @staticmethod
    def hasComponent(name):
        return _sinew.has_component(name)


ObjectFactory.components = property(lambda self: ObjectFactory.getComponentsList())
