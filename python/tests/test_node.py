"""Sofa.Core.Node: building a graph from Python, traversal, paths, removal."""
import pytest

import Sofa
import Sofa.Core
import Sofa.Simulation


def make_beam(root):
    root.dt = 0.01
    root.gravity = [0, -10, 0]
    root.addObject("DefaultAnimationLoop")
    beam = root.addChild("beam")
    beam.addObject("EulerImplicitSolver", rayleighStiffness=0.1, rayleighMass=0.1)
    beam.addObject("CGLinearSolver", iterations=25, tolerance=1e-9, threshold=1e-9)
    beam.addObject("RegularGridTopology", name="grid", nx=2, ny=2, nz=4, xmin=0, xmax=1, ymin=0, ymax=1, zmin=0, zmax=3)
    beam.addObject("MechanicalObject", name="dofs")
    beam.addObject("UniformMass", totalMass=1.0)
    beam.addObject("HexahedronFEMForceField", youngModulus=1000, poissonRatio=0.3)
    beam.addObject("FixedProjectiveConstraint", indices=[0, 1, 2, 3])
    return beam


def test_node_construction_and_names():
    root = Sofa.Core.Node("root")
    assert root.name.value == "root"
    assert Sofa.Core.Node().name.value == "unnamed"
    beam = make_beam(root)
    assert beam.getPathName() == "/beam"
    assert beam.getLinkPath() == "@/beam"
    assert root.beam is beam  # one handle per object
    assert root.getChild("beam") is beam
    assert root.getChild("nope") is None
    assert beam.dofs.getPathName() == "/beam/dofs"
    assert beam.dofs.getLinkPath() == "@/beam/dofs"
    # SofaPython3 names unnamed objects after their class, without a number.
    assert beam.getObject("UniformMass") is not None
    assert beam.UniformMass.getClassName() == "UniformMass"
    assert [c.getName() for c in root.children] == ["beam"]
    assert [o.getName() for o in beam.objects][:2] == ["EulerImplicitSolver", "CGLinearSolver"]
    assert beam.parents[0] is root
    assert root["beam.dofs"] is beam.dofs
    assert root["beam.dofs.position"].getName() == "position"
    assert beam.getRoot() is root
    assert beam.getMechanicalState() is beam.dofs
    assert beam.hasODESolver()


def test_unknown_names_raise_with_suggestions():
    root = Sofa.Core.Node("root")
    beam = make_beam(root)
    with pytest.raises(AttributeError, match="dofs"):
        beam.dofz
    with pytest.raises(ValueError, match="MechanicalObject"):
        beam.addObject("MechanicalObjekt")
    with pytest.raises(TypeError, match="youngModulus"):
        beam.addObject("TetrahedronFEMForceField", youngModulu=3)


def test_simulate_and_reset():
    root = Sofa.Core.Node("root")
    beam = make_beam(root)
    Sofa.Simulation.init(root)
    x0 = beam.dofs.position.value.copy()
    for _ in range(5):
        Sofa.Simulation.animate(root, root.dt.value)
    assert root.time.value == pytest.approx(0.05)
    x5 = beam.dofs.position.value
    assert x5[-1][1] < x0[-1][1]  # the free end falls
    assert (x5[:4] == x0[:4]).all()  # the fixed end stays
    Sofa.Simulation.reset(root)
    assert root.time.value == 0
    assert (beam.dofs.position.value == x0).all()


def test_add_and_remove_during_simulation():
    root = Sofa.Core.Node("root")
    beam = make_beam(root)
    Sofa.Simulation.init(root)
    Sofa.Simulation.animate(root)
    extra = root.addChild("extra")
    extra.addObject("EulerImplicitSolver")
    extra.addObject("CGLinearSolver", iterations=10, tolerance=1e-9, threshold=1e-9)
    extra.addObject("MechanicalObject", name="p", position=[0, 0, 0])
    extra.addObject("UniformMass", totalMass=2.0)
    Sofa.Simulation.animate(root)  # the new subtree is initialised by the step
    assert extra.p.position.value[0][1] < 0
    root.removeChild(extra)
    assert root.getChild("extra") is None
    # The removed node now belongs to Python: it can be inspected and added again.
    assert extra.p.position.value.shape == (1, 3)
    root.addChild(extra)
    Sofa.Simulation.animate(root)
    removed = beam.getObject("HexahedronFEMForceField")
    beam.removeObject(removed)
    Sofa.Simulation.animate(root)
    assert beam.getObject("HexahedronFEMForceField") is None


def test_destroyed_objects_raise_instead_of_crashing():
    root = Sofa.Core.Node("root")
    beam = make_beam(root)
    dofs = beam.dofs
    pos = dofs.position
    Sofa.Simulation.unload(root)
    with pytest.raises(ReferenceError):
        dofs.getName()
    with pytest.raises(ReferenceError):
        pos.value


def test_context_manager_and_kwargs_on_nodes():
    root = Sofa.Core.Node("root", dt=0.005, gravity=[0, 0, -9.81])
    assert root.dt.value == 0.005
    assert list(root.gravity.value) == [0, 0, -9.81]
    with root.addChild("child", activated=False) as child:
        assert child.activated.value is False
    with pytest.raises(TypeError, match="gravity"):
        root.addChild("c2", gravty=[0, 0, 0])


def test_task_scheduler_sets_the_worker_threads():
    ts = Sofa.Core.TaskScheduler
    assert ts.GetHardwareThreadsCount() >= 1
    ts.init(1)
    assert ts.getThreadCount() == 1
    root = Sofa.Core.Node("root")
    make_beam(root)
    Sofa.Simulation.init(root)
    Sofa.Simulation.animate(root)
    ts.stop()
    assert ts.getThreadCount() == ts.GetHardwareThreadsCount()
