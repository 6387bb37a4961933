"""Sofa.SofaDeformable: LinearSpring and SpringForceField's spring list edited from Python."""
import numpy as np
import pytest

import Sofa.Core
import Sofa.Simulation
from Sofa import SofaDeformable


def two_frames(length=3.0, stiffness=2.0):
    """Two Rigid3d frames 4 apart on x, mass 1 each, one spring; explicit Euler, no gravity."""
    root = Sofa.Core.Node("root")
    root.gravity = [0, 0, 0]
    root.dt = 0.01
    root.addObject("DefaultAnimationLoop")
    root.addObject("EulerExplicitSolver", symplectic=True)
    a = root.addChild("a")
    a.addObject("MechanicalObject", name="dofs", template="Rigid3d", position=[-2, 0, 0, 0, 0, 0, 1])
    a.addObject("UniformMass", totalMass=1)
    b = root.addChild("b")
    b.addObject("MechanicalObject", name="dofs", template="Rigid3d", position=[2, 0, 0, 0, 0, 0, 1])
    b.addObject("UniformMass", totalMass=1)
    springs = root.addObject("SpringForceField", object1=a.dofs.getLinkPath(), object2=b.dofs.getLinkPath(),
                             indices1=[0], indices2=[0], length=[length], stiffness=stiffness, damping=0)
    Sofa.Simulation.init(root)
    return root, a, b, springs


def test_rigid_spring_pulls_the_frame_centres():
    root, a, b, springs = two_frames()
    assert isinstance(springs, SofaDeformable.SpringForceField_Rigid3d)
    Sofa.Simulation.animate(root, root.dt.value)
    # |d| = 4, L0 = 3, ks = 2: a force of 2 along x on each centre, no torque; v = dt·F/m.
    np.testing.assert_allclose(a.dofs.velocity.value[0], [0.02, 0, 0, 0, 0, 0], atol=1e-15)
    np.testing.assert_allclose(b.dofs.velocity.value[0], [-0.02, 0, 0, 0, 0, 0], atol=1e-15)


def test_remove_spring_stops_the_force():
    root, a, b, springs = two_frames()
    assert len(springs.getSprings()) == 1
    springs.removeSpring(0)
    assert springs.getSprings() == []
    assert len(springs.indices1.value) == 0 and len(springs.length.value) == 0  # the Data follow
    Sofa.Simulation.animate(root, root.dt.value)
    np.testing.assert_array_equal(a.dofs.velocity.value[0], np.zeros(6))
    springs.removeSpring(0)  # nothing left: ignored (as SOFA), with a warning
    springs.addSpring(index1=0, index2=0, springStiffness=4, dampingFactor=0, restLength=3)
    Sofa.Simulation.animate(root, root.dt.value)
    # the new spring (ks = 4, stretched by 1) gives twice the first one's pull
    np.testing.assert_allclose(a.dofs.velocity.value[0][0], 0.04, rtol=1e-12)
    with pytest.raises(IndexError, match="out of range"):
        springs.addSpring(index1=1, index2=0, springStiffness=1, dampingFactor=0, restLength=1)
    assert len(springs.getSprings()) == 1


def planes():
    root = Sofa.Core.Node("root")
    for name, x in (("p1", -0.5), ("p2", 0.5)):
        n = root.addChild(name)
        n.addObject("RegularGridTopology", name="grid", min=[x, -1.5, -1.5], max=[x, 1.5, 1.5], n=[1, 3, 3])
        n.addObject("MechanicalObject", name="mo", template="Vec3d", position="@grid.position")
    root.addObject("StiffSpringForceField", name="ff", object1=root.p1.mo.getLinkPath(),
                   object2=root.p2.mo.getLinkPath(), indices1=list(range(9)), indices2=list(range(9)),
                   stiffness=1, damping=0, length=1.0)
    Sofa.Simulation.init(root)
    return root


def test_spring_list_edits():
    root = planes()
    ff = root.ff
    s = ff.getSprings()
    assert len(s) == 9 and all(x.index1 == x.index2 for x in s)
    assert (s[0].springStiffness, s[0].dampingFactor, s[0].restLength) == (1.0, 0.0, 1.0)
    ff.removeSprings([1, 2, 3])
    s = ff.getSprings()
    assert [(x.index1, x.index2) for x in s[:2]] == [(0, 0), (4, 4)] and len(s) == 6
    np.testing.assert_array_equal(ff.indices2.value, [0, 4, 5, 6, 7, 8])
    ff.clear()
    assert ff.getSprings() == []
    ff.addSprings([SofaDeformable.LinearSpring(index1=2, index2=2, springStiffness=1, dampingFactor=1,
                                               restLength=1, elongationOnly=True, enabled=False),
                   SofaDeformable.LinearSpring(3, 3, 2, 2, 2)])
    s1, s2 = ff.getSprings()
    assert (s1.index1, s1.elongationOnly, s1.enabled) == (2, True, False)
    assert (s2.index1, s2.springStiffness, s2.restLength, s2.enabled) == (3, 2.0, 2.0, True)
    np.testing.assert_array_equal(ff.stiffness.value, [1, 2])
    assert "index1: 2" in str(s1)


def test_linear_spring_fields():
    sp = SofaDeformable.LinearSpring(index1=0, index2=1, restLength=5)
    assert (sp.springStiffness, sp.dampingFactor, sp.elongationOnly, sp.enabled) == (100, 5, False, True)
    sp.restLength = 10
    sp.index2 = 0
    assert (sp.restLength, sp.index2) == (10, 0)


def test_spring_methods_only_on_spring_force_fields():
    root = Sofa.Core.Node("root")
    mo = root.addObject("MechanicalObject")
    assert not hasattr(mo, "removeSpring")
