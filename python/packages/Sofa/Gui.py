"""Sofa.Gui: SofaPython3's GUIManager, shown in Sinew's viewer (``sinew view``).

A script that builds its scene and calls ``Sofa.Gui.GUIManager.MainLoop(root)`` gets the
viewer's window on that graph: play, step, reset, the scene graph and its fields, display
flags, the shift-drag grab (docs/viewer.md). Every GUI name SOFA knows stands for Sinew's
viewer except ``batch``, which steps the scene without a window (1000 steps, as SOFA's batch
GUI). Scripted runs take ``SINEW_VIEW_QUIT_AFTER``, ``SINEW_VIEW_SCREENSHOT``,
``SINEW_VIEW_SCRIPT`` and ``SINEW_VIEW_PLAY`` from the environment (as ``sinew view``'s
``--quit-after``, ``--screenshot``, ``--script``, ``--play``).
"""
import os

import _sinew

__all__ = ["GUIManager", "BaseGUI"]

_GUIS = ["imgui", "glfw", "qglviewer", "qt", "batch"]
_BATCH_STEPS = 1000  # SOFA's BatchGUI default number of iterations


class BaseGUI:
    """The GUI made by createGUI (SofaPython3's Sofa.Gui.BaseGUI)."""

    def setBackgroundImage(self, filename):
        GUIManager._background_image = filename

    @staticmethod
    def SetConfigDirectoryPath(path, createIfNecessary=False):
        if createIfNecessary:
            os.makedirs(path, exist_ok=True)


class GUIManager:
    """SofaPython3's static GUIManager."""

    _name = ""
    _program = "python"
    _root = None
    _filename = ""
    _size = (0, 0)
    _gui = None
    _background_image = ""

    @staticmethod
    def ListSupportedGUI(separator=None):
        """The GUI names, as a list, or one string joined by `separator`."""
        return list(_GUIS) if separator is None else separator.join(_GUIS)

    @staticmethod
    def Init(program_name="python", gui_name=""):
        """Chooses the GUI; 0 when it is known, 1 otherwise (as SOFA)."""
        name = gui_name or "imgui"
        if name not in _GUIS:
            from . import Helper
            Helper.msg_error("GUIManager", "unknown GUI '%s'; supported: %s" % (name, ", ".join(_GUIS)))
            return 1
        GUIManager._name, GUIManager._program = name, program_name
        return 0

    @staticmethod
    def GetGUIName():
        return GUIManager._name or "imgui"

    @staticmethod
    def createGUI(node, filename=""):
        GUIManager._root, GUIManager._filename = node, filename
        GUIManager._gui = BaseGUI()
        return 0

    @staticmethod
    def GetGUI():
        return GUIManager._gui

    @staticmethod
    def SetScene(root, filename=None, temporaryFile=False):
        GUIManager._root, GUIManager._filename = root, filename or GUIManager._filename

    @staticmethod
    def SetDimension(width, height):
        GUIManager._size = (int(width), int(height))

    @staticmethod
    def CenterWindow():
        """The window manager places the window."""

    @staticmethod
    def SetFullScreen():
        """Not supported: the window keeps its size."""

    @staticmethod
    def SaveScreenshot(filename):
        """A picture of the 3D view after the viewer's next frame (while MainLoop runs)."""
        if not _sinew.gui_save_screenshot(str(filename)):
            from . import Helper
            Helper.msg_warning("GUIManager", "SaveScreenshot: no viewer is running")

    @staticmethod
    def MainLoop(node=None, filename=""):
        """Shows `node` (else the scene given to createGUI) until the window closes; 0 when fine."""
        root = node if node is not None else GUIManager._root
        if root is None:
            raise RuntimeError("Sofa.Gui.GUIManager.MainLoop: no scene (call createGUI(root) or pass the root)")
        from . import Simulation
        if GUIManager.GetGUIName() == "batch":
            for _ in range(_BATCH_STEPS):
                Simulation.animate(root, root.dt.value)
            return 0
        if not root.isInitialized():  # as SOFA's GUIs do when given a graph not initialised yet
            Simulation.init(root)
        name = filename or GUIManager._filename or GUIManager._program
        width, height = GUIManager._size
        return _sinew.gui_main_loop(root, name, width, height)

    @staticmethod
    def closeGUI():
        GUIManager._gui = None
