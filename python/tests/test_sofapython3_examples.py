"""SofaPython3's own example scenes, unchanged, through `sinew run X.py -n 10` (issue 12's list)."""
import os
import subprocess
import sys

import pytest

# Scenes that need no GUI and no plugin outside SOFA.
SCENES = [
    "basic", "emptyController", "emptyDataEngine", "emptyForceField", "example-forcefield",
    "example-scriptcontroller", "liver", "liver-scriptcontroller", "loadXMLfromPython",
    "access_energy", "access_stiffness_matrix", "access_constraint_matrix",
    "pointSetTopologyModifier", "ReadTheDocs_Example", "MessageHandler", "keyEvents", "scene_check",
    "import_python_scene",
    "springForceField", "access_mass_matrix", "access_matrix", "access_compliance_matrix", "access_contact_forces",
    "example-mapping", "example-mapping_3_to_1", "taskScheduler",
]
# Listed by issue 12 and not running yet: what each one lacks. Strict: a scene that
# starts to run fails here until it moves to SCENES.
PENDING = {}


@pytest.mark.parametrize("name", SCENES + sorted(PENDING))
def test_example_runs_10_steps(name, sofa_data, run_sinew, request):
    if name in PENDING:
        request.applymarker(pytest.mark.xfail(reason="needs " + PENDING[name], strict=True))
    scene = sofa_data / "sofapython3" / (name + ".py")
    r = run_sinew(scene, 10)
    assert r.returncode == 0, r.stdout[-3000:] + r.stderr[-3000:]


def test_example_mapping_moves_the_mapped_points_with_the_object(sofa_data, capfd):
    """example-mapping.py: the Modelling subtree has two parents (root and Simulation), the
    solver in Simulation integrates it, and the Python IdentityMapping keeps the mapped points
    at their initial offset from the falling object."""
    import importlib.util
    import numpy as np
    import Sofa.Core
    import Sofa.Simulation
    spec = importlib.util.spec_from_file_location("example_mapping", sofa_data / "sofapython3" / "example-mapping.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    root = Sofa.Core.Node("root")
    module.createScene(root)
    Sofa.Simulation.initRoot(root)
    for _ in range(10):
        Sofa.Simulation.animate(root, root.dt.value)
    x = root.Modelling.Object.mechanical.position.value
    y = root.Modelling.Object.MappedDof.mapped_quantities.position.value
    assert x[0][1] < -0.05  # ten steps of free fall: y = -g dt² (1 + 2 + ... + 10)
    np.testing.assert_allclose(x[:, 1], -9.81 * 0.01 ** 2 * 55, rtol=1e-9)
    np.testing.assert_array_equal(y, x + [[0, 0.5, 0]] * 2)
    assert "PYTHON(🐍) APPLY" in capfd.readouterr().out


def test_sofacarving_python_example_runs(sofa_data, run_sinew):
    """SofaCarving's SimpleCarving.py (issue 12, once carving exists): gravity is zero, so nothing
    moves and nothing is carved until a user drives the instrument."""
    r = run_sinew(sofa_data / "plugins" / "SofaCarving" / "examples" / "SimpleCarving.py", 100)
    assert r.returncode == 0, r.stderr[-3000:]


def test_basic_runs_as_a_script(sofa_data, tmp_path):
    """`python3 basic.py`: the script's own main() builds, initialises and steps the scene."""
    env = dict(os.environ)
    r = subprocess.run([sys.executable, str(sofa_data / "sofapython3" / "basic.py")], capture_output=True,
                       text=True, cwd=tmp_path, env=env, timeout=300)
    assert r.returncode == 0, r.stderr[-3000:]
    assert "Simulation made 10 time steps. Done" in r.stdout


def test_python_errors_point_at_the_scene_line(tmp_path, run_sinew):
    scene = tmp_path / "broken.py"
    scene.write_text("def createScene(root):\n    root.addObject('DefaultAnimationLoop')\n"
                     "    root.addObject('MechanicalObject', positon=[0, 0, 0])\n")
    r = run_sinew(scene, 1)
    assert r.returncode != 0
    assert "broken.py:3" in r.stderr, r.stderr
    assert "position" in r.stderr  # the spelling suggestion
    scene.write_text("x = 1\n")
    r = run_sinew(scene, 1)
    assert r.returncode != 0 and "Missing createScene" in r.stderr


@pytest.mark.parametrize("locale", ["C", "C.UTF-8"])
def test_embedded_python_prints_unicode_under_any_locale(tmp_path, sinew_bin, locale):
    """`sinew run` embeds Python in UTF-8 mode, as python3 runs: example-mapping.py prints 🐍."""
    scene = tmp_path / "snake.py"
    scene.write_text("def createScene(root):\n    print('PYTHON(🐍)')\n    root.addObject('DefaultAnimationLoop')\n",
                     encoding="utf-8")
    env = dict(os.environ, LC_ALL=locale, LANG=locale)
    r = subprocess.run([sinew_bin, "run", str(scene), "-n", "1", "--hideProgressBar"], capture_output=True,
                       env=env, timeout=120)
    assert r.returncode == 0, r.stderr.decode("utf-8", "replace")
    assert "PYTHON(🐍)".encode("utf-8") in r.stdout
