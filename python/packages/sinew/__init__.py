"""Sinew's Python API: the scene graph, its Data and the simulation loop.

The same objects appear under SofaPython3's names in the packages ``Sofa``
(``Sofa.Core``, ``Sofa.Simulation``, ``Sofa.Helper``), ``SofaRuntime`` and
``SofaTypes``, so that SofaPython3 scenes run unchanged.

    import sinew
    root = sinew.Node("root")
    root.addObject("MechanicalObject", position=[0, 0, 0])
    sinew.init(root)
    sinew.animate(root)
"""
from _sinew import *  # noqa: F401,F403  (the native module: Node, Object, Data, init, animate, ...)
from _sinew import Node, Object, Data, Controller, DataEngine  # noqa: F401

__all__ = [name for name in dir() if not name.startswith("_")]
