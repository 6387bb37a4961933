"""Sofa.Simulation: initialise, step, reset and load scenes."""
import _sinew

init = _sinew.init
initRoot = _sinew.initRoot
animate = _sinew.animate
animateNSteps = _sinew.animateNSteps
reset = _sinew.reset
unload = _sinew.unload
load = _sinew.load
print = _sinew.print  # noqa: A001  (SofaPython3's name)


def initVisual(node):
    """Visual models are initialised with the graph; nothing more to do without a viewer."""


def updateVisual(node):
    """Visual models follow the simulation at each step; nothing more to do without a viewer."""


class SceneCheck:
    def __init__(self, name, desc):
        self._name, self._desc = name, desc

    def getName(self):
        return self._name

    def getDesc(self):
        return self._desc


class SceneCheckMainRegistry:
    """The checks made on every scene when it is loaded and initialised."""

    _checks = [
        SceneCheck("UnknownComponents", "Components and attributes Sinew does not know, with spelling suggestions"),
        SceneCheck("Links", "Data and object links that cannot be resolved, and link cycles"),
        SceneCheck("Resources", "Mesh and data files that cannot be found in the scene folder or the data paths"),
        SceneCheck("Values", "Attribute values that cannot be read, or with a wrong number of entries"),
        SceneCheck("TimeStep", "A time step that is not a positive number"),
        SceneCheck("AnimationLoop", "A root without an animation loop (a DefaultAnimationLoop is added)"),
    ]

    @staticmethod
    def getRegisteredSceneChecks():
        return list(SceneCheckMainRegistry._checks)
