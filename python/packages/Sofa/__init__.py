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
