"""SofaRuntime: the application runtime (plugins, module reloading)."""
import sys

import Sofa  # noqa: F401  (numpy check and the Sofa packages)
import _sinew

# Plugin names SOFA splits its components into. Sinew builds every component
# in, so importing one only checks the name.
_KNOWN_PREFIXES = ("Sofa.Component", "Sofa.GL", "Sofa.GUI", "Sofa.Gui", "SofaPython3", "SceneChecking",
                   "Sofa.Simulation", "Sofa.Core", "SofaCarving", "Sofa.LinearSystem", "Sofa.LinearSolver")

_imported_at_start = set(sys.modules)


def importPlugin(name):
    """Load a plugin: every standard component is built into Sinew, so this only checks the name."""
    if not any(name == p or name.startswith(p + ".") or name.startswith(p) for p in _KNOWN_PREFIXES):
        _sinew.msg_warning("SofaRuntime", "plugin '%s' is not part of Sinew; its components will be unknown" % name)
        return False
    return True


def unloadModules():
    """Forget the Python modules imported since start-up, so that edits are picked up by the next import."""
    for name in [n for n in sys.modules if n not in _imported_at_start]:
        del sys.modules[name]


def getPythonCallingPointAsString():
    f = sys._getframe(1)
    return "%s:%d" % (f.f_code.co_filename, f.f_lineno)


__all__ = ["importPlugin", "unloadModules"]
