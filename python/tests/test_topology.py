"""Topology modifiers from Python: SofaPython3's pointSetTopologyModifier example driven by key events."""
import runpy

import numpy as np

import Sofa.Core
import Sofa.Simulation
import _sinew


def test_point_modifier_example_adds_and_removes_points(sofa_data):
    scene = runpy.run_path(str(sofa_data / "sofapython3" / "pointSetTopologyModifier.py"))
    root = Sofa.Core.Node("root")
    scene["createScene"](root)
    Sofa.Simulation.init(root)
    state = root.getMechanicalState()
    assert len(state.position) == 2
    _sinew.sendKey(root, "A")  # the example's controller adds 10 points
    Sofa.Simulation.animate(root)
    assert len(state.position) == 12
    assert root.PointSetTopologyContainer.nbPoints.value == 12
    with state.position.writeableArray() as p:
        p[:] = np.arange(36).reshape(12, 3)
    _sinew.sendKey(root, "D")  # removes point 0: the last one takes its place
    assert len(state.position) == 11
    assert state.position.value[0].tolist() == [33, 34, 35]


def test_remove_items_on_a_triangle_modifier():
    root = Sofa.Core.Node("root")
    root.addObject("DefaultAnimationLoop")
    n = root.addChild("n")
    n.addObject("TriangleSetTopologyContainer", name="c", position=[0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0],
                triangles=[0, 1, 2, 1, 3, 2])
    m = n.addObject("TriangleSetTopologyModifier")
    n.addObject("MechanicalObject")
    Sofa.Simulation.init(root)
    m.removeItems([0])
    # Point 0 was left isolated and went too: the last point (3) took its index.
    assert n.c.triangles.value.tolist() == [[1, 0, 2]]
    assert len(n.MechanicalObject.position) == 3
