"""Sofa.Gui (SofaPython3's GUIManager) on Sinew's viewer: SofaPython3's GUI examples run as
scripts with Debian's python3 and show their scene in a window (under Xvfb here)."""
import os
import subprocess
import sys
import textwrap

import pytest

import Sofa
import Sofa.Gui


def run_script(path, display, tmp_path, frames=5, extra_env=None):
    env = dict(os.environ, DISPLAY=display, SINEW_VIEW_QUIT_AFTER=str(frames), SINEW_VIEW_PLAY="1",
               SINEW_VIEW_SCREENSHOT=str(tmp_path / "gui.png"), **(extra_env or {}))
    return subprocess.run([sys.executable, str(path)], env=env, capture_output=True, text=True, timeout=300,
                          cwd=tmp_path)


def test_gui_names_and_init():
    assert Sofa.Gui.GUIManager.ListSupportedGUI(",") == "imgui,glfw,qglviewer,qt,batch"
    assert Sofa.Gui.GUIManager.ListSupportedGUI() == ["imgui", "glfw", "qglviewer", "qt", "batch"]
    assert Sofa.Gui.GUIManager.Init("test", "imgui") == 0
    assert Sofa.Gui.GUIManager.GetGUIName() == "imgui"
    assert Sofa.Gui.GUIManager.Init("test", "nosuchgui") == 1
    assert Sofa.Gui.GUIManager.GetGUIName() == "imgui"  # unchanged


def test_batch_gui_steps_without_a_window():
    root = Sofa.Core.Node("root")
    root.dt = 0.01
    root.addObject("DefaultAnimationLoop")
    Sofa.Simulation.initRoot(root)
    assert Sofa.Gui.GUIManager.Init("test", "batch") == 0
    Sofa.Gui.GUIManager.createGUI(root)
    assert Sofa.Gui.GUIManager.MainLoop(root) == 0
    assert root.time.value == pytest.approx(10.0)  # SOFA's batch GUI: 1000 steps
    Sofa.Gui.GUIManager.Init("test", "imgui")


@pytest.mark.parametrize("name", ["basic-addGUI.py", "basic-useQtGUI.py", "example-forcefield.py"])
def test_sofapython3_gui_examples_open_the_viewer(name, sofa_data, display, tmp_path):
    r = run_script(sofa_data / "sofapython3" / name, display, tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "screenshot written" in r.stdout
    assert (tmp_path / "gui.png").stat().st_size > 100


def test_controller_saves_a_screenshot_and_the_scene_moves(display, tmp_path):
    script = tmp_path / "falling.py"
    script.write_text(textwrap.dedent("""
        import Sofa, Sofa.Gui

        class Shot(Sofa.Core.Controller):
            def __init__(self, *a, **k):
                Sofa.Core.Controller.__init__(self, *a, **k)
                self.steps = 0
            def onAnimateEndEvent(self, event):
                self.steps += 1
                if self.steps == 3:
                    Sofa.Gui.GUIManager.SaveScreenshot("step3.png")

        root = Sofa.Core.Node("root")
        root.gravity = [0, -9.81, 0]
        root.dt = 0.01
        root.addObject("DefaultAnimationLoop")
        body = root.addChild("body")
        body.addObject("EulerImplicitSolver")
        body.addObject("CGLinearSolver", iterations=25, tolerance=1e-9, threshold=1e-9)
        dofs = body.addObject("MechanicalObject", position=[[0, 0, 0]], showObject=True)
        body.addObject("UniformMass", totalMass=1)
        root.addObject(Shot(name="shot"))
        Sofa.Simulation.initRoot(root)
        Sofa.Gui.GUIManager.Init("falling", "imgui")
        Sofa.Gui.GUIManager.createGUI(root, __file__)
        Sofa.Gui.GUIManager.SetDimension(320, 240)
        code = Sofa.Gui.GUIManager.MainLoop(root)
        Sofa.Gui.GUIManager.closeGUI()
        print("exit", code, "time", round(root.time.value, 6), "y", dofs.position.value[0][1])
    """))
    r = run_script(script, display, tmp_path, frames=10)
    assert r.returncode == 0, r.stdout + r.stderr
    assert (tmp_path / "step3.png").exists()
    # Ten frames, one step each: t = 0.1, and the point fell (backward Euler: y = -g dt^2 n(n+1)/2).
    assert "exit 0 time 0.1 " in r.stdout
    y = float(r.stdout.split(" y ")[-1])
    assert y == pytest.approx(-9.81 * 0.01 ** 2 * 55, rel=1e-9)
