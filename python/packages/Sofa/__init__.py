"""SofaPython3's ``Sofa`` package, on Sinew.

``import Sofa`` gives ``Sofa.Core``, ``Sofa.Simulation``, ``Sofa.Helper``,
``Sofa.Types``, ``Sofa.PyTypes`` and ``Sofa.constants``, as SofaPython3 does.
Every standard component is built in: ``RequiredPlugin`` and
``SofaRuntime.importPlugin`` only check the names.
"""
import numpy  # noqa: F401  (SofaPython3 requires numpy; fail early and clearly when it is missing)

from . import Core, Simulation, Helper, Types, PyTypes, constants  # noqa: F401
from .Helper import msg_info, msg_warning, msg_error, msg_deprecated, msg_fatal  # noqa: F401

__all__ = ["Core", "Simulation", "Helper", "Types", "PyTypes", "constants",
           "msg_info", "msg_warning", "msg_error", "msg_deprecated", "msg_fatal"]


def import_sofa_python_scene(path_to_scene):
    """Import a Python scene file as a module (its createScene builds the scene into any node).

    A relative path is looked up next to the calling script first, then in the current folder.
    """
    import importlib.util
    import os
    import sys

    path = path_to_scene
    if not os.path.isabs(path):
        caller = os.path.dirname(os.path.abspath(sys._getframe(1).f_code.co_filename))
        if os.path.exists(os.path.join(caller, path)):
            path = os.path.join(caller, path)
    spec = importlib.util.spec_from_file_location(os.path.splitext(os.path.basename(path))[0], path)
    if spec is None:
        raise ImportError("cannot import the scene " + repr(path_to_scene))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    if not hasattr(module, "createScene"):
        raise ImportError("the scene " + repr(path_to_scene) + " has no createScene function")
    return module
