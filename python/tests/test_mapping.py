"""Mappings written in Python (Mapping_<In>_<Out>), nodes with several parents,
LinkPath and the mass classes."""
import numpy as np
import pytest

import Sofa.Core
import Sofa.Simulation


class Offset(Sofa.Core.Mapping_Vec3d_Vec3d):
    """out = in + delta, J = identity: what SofaPython3's example-mapping.py computes,
    with a Jᵀ that carries the forces back (the example's prints nothing)."""

    def __init__(self, *args, **kwargs):
        Sofa.Core.Mapping_Vec3d_Vec3d.__init__(self, *args, **kwargs)
        self.delta = kwargs["output"].target().position.value - kwargs["input"].target().position.value
        self.calls = {"apply": 0, "applyJ": 0, "applyJT": 0}

    def apply(self, m, outCoord, inCoord):
        self.calls["apply"] += 1
        with outCoord.writeableArray() as wa:
            wa[:] = inCoord.value + self.delta

    def applyJ(self, m, outDeriv, inDeriv):
        self.calls["applyJ"] += 1
        with outDeriv.writeableArray() as wa:
            wa[:] = inDeriv.value

    def applyJT(self, m, outDeriv, inDeriv):
        self.calls["applyJT"] += 1
        with outDeriv.writeableArray() as wa:
            wa[:] += inDeriv.value


def two_points(root, python_mapping):
    """SofaPython3's example-mapping.py graph, with a force on the mapped points."""
    root.addObject("DefaultAnimationLoop")
    modelling = root.addChild("Modelling")
    o = modelling.addChild("Object")
    c = o.addObject("MechanicalObject", name="mechanical", position=[0, 0, 0, 1, 0, 0])
    o.addObject("UniformMass", name="mass", totalMass=1.0)
    m = o.addChild("MappedDof")
    sm = m.addObject("MechanicalObject", name="mapped", position=[0, 0.5, 0, 1, 0.5, 0])
    m.addObject("ConstantForceField", forces=[1, 0, 0, 0, 0, 2])
    if python_mapping:
        m.addObject(Offset(name="map", input=c.linkpath, output=sm.linkpath))
    else:
        m.addObject("IdentityMapping", name="map", input=c.linkpath, output=sm.linkpath)
    sim = root.addChild("Simulation")
    sim.addObject("EulerImplicitSolver", rayleighStiffness=0, rayleighMass=0)
    sim.addObject("CGLinearSolver", tolerance=1e-12, threshold=1e-12, iterations=25)
    sim.addChild(modelling)
    return c, sm


def test_multi_parent_node_is_integrated_by_the_solver_of_its_second_parent():
    root = Sofa.Core.Node("root", dt=0.01)
    c, sm = two_points(root, python_mapping=False)
    modelling = root.Modelling
    assert [p.getName() for p in modelling.parents] == ["root", "Simulation"]
    assert root.Simulation.children[0] is modelling
    assert modelling.getPathName() == "/Modelling"
    Sofa.Simulation.init(root)
    Sofa.Simulation.animate(root, 0.01)
    # Backward Euler, m = 0.5 per point: v = dt (g + f / m), x = dt v
    v = c.velocity.value
    np.testing.assert_allclose(v[0], [0.01 * 2, -0.0981, 0], rtol=1e-9, atol=1e-14)
    np.testing.assert_allclose(v[1], [0, -0.0981, 0.01 * 4], rtol=1e-9, atol=1e-14)
    np.testing.assert_allclose(c.position.value, 0.01 * v + [[0, 0, 0], [1, 0, 0]], rtol=1e-9, atol=1e-14)


def test_python_mapping_gives_the_builtin_identity_mapping_result_bit_for_bit():
    roots = []
    for python_mapping in (True, False):
        root = Sofa.Core.Node("root", dt=0.01)
        c, sm = two_points(root, python_mapping)
        Sofa.Simulation.init(root)
        for _ in range(10):
            Sofa.Simulation.animate(root, 0.01)
        roots.append((root, c, sm))
    (_, c_py, sm_py), (_, c_cpp, sm_cpp) = roots
    assert c_py.position.value[0][1] < 0
    assert np.array_equal(c_py.position.value, c_cpp.position.value)
    assert np.array_equal(c_py.velocity.value, c_cpp.velocity.value)
    # IdentityMapping copies; Offset adds the initial delta.
    np.testing.assert_array_equal(sm_py.position.value, c_py.position.value + [[0, 0.5, 0]] * 2)
    calls = roots[0][0].Modelling.Object.MappedDof.map.calls
    assert calls["apply"] > 10 and calls["applyJ"] > 10 and calls["applyJT"] > 10


def test_mapping_vec3d_vec1d_and_its_class_names():
    class Loss(Sofa.Core.Mapping_Vec3d_Vec1d):
        def apply(self, m, outCoord, inCoord):
            with outCoord.writeableArray() as wa:
                wa[:] = np.sum(inCoord.value ** 2)

        def applyJ(self, m, outDeriv, inDeriv):
            pass

        def applyJT(self, m, outDeriv, inDeriv):
            pass

    root = Sofa.Core.Node("root", gravity=[0, 0, 0])
    root.addObject("DefaultAnimationLoop")
    c = root.addObject("MechanicalObject", name="x", position=[1, 2, 3, 0, 0, 1])
    child = root.addChild("loss")
    out = child.addObject("MechanicalObject", name="l", template="Vec1d", position=[0.0])
    child.addObject(Loss(name="loss", input=c.linkpath, output=out.linkpath))
    Sofa.Simulation.init(root)
    assert out.position.value.shape == (1, 1)
    assert out.position.value[0][0] == 15.0
    for name in ("Mapping_Vec1d_Vec1d", "Mapping_Vec3d_Vec1d", "Mapping_Rigid3d_Vec3d", "Mapping_Vec3d_Rigid3d",
                 "Mapping_Rigid2d_Rigid2d", "Mapping_Vec6d_Vec1d"):
        assert hasattr(Sofa.Core, name), name


def test_mapping_without_its_methods_is_an_error(capfd):
    class Empty(Sofa.Core.Mapping_Vec3d_Vec3d):
        pass

    root = Sofa.Core.Node("root")
    root.addObject("DefaultAnimationLoop")
    c = root.addObject("MechanicalObject", name="x", position=[1, 2, 3])
    child = root.addChild("c")
    out = child.addObject("MechanicalObject", name="y", position=[0, 0, 0])
    child.addObject(Empty(name="empty", input=c.linkpath, output=out.linkpath))
    Sofa.Simulation.init(root)
    assert "defines no apply()" in capfd.readouterr().err


def test_linkpath_names_objects_and_data():
    root = Sofa.Core.Node("root")
    n = root.addChild("n")
    d = n.addObject("MechanicalObject", name="dofs", position=[1, 2, 3])
    lp = d.linkpath
    assert isinstance(lp, Sofa.Core.LinkPath)
    assert str(lp) == "@/n/dofs" and repr(lp) == 'LinkPath("@/n/dofs")'
    assert lp.target() is d
    assert str(d.position.linkpath) == "@/n/dofs.position"
    assert d.position.linkpath.target().getName() == "position"
    copy = root.addChild("c").addObject("MechanicalObject", name="copy", position=d.position.linkpath)
    assert copy.position.getParent().getOwner() is d
    mass = n.addObject("UniformMass", name="mass")
    mass.mstate = d.linkpath
    with pytest.raises(TypeError, match="a link points to an object"):
        mass.mstate = d.position.linkpath


def test_adding_a_node_to_a_second_parent_and_removing_it():
    root = Sofa.Core.Node("root")
    a = root.addChild("a")
    b = root.addChild("b")
    b.addChild(a)
    assert len(a.parents) == 2
    below = b.addChild("below")
    a.addChild(below)  # any node of the graph that is not above it
    assert [p.getName() for p in below.parents] == ["b", "a"]
    with pytest.raises(ValueError):
        a.addChild(root)  # a cycle
    b.removeChild(a)
    assert [p.getName() for p in a.parents] == ["root"]
    b.addChild(a)
    root.removeChild(a)  # the owner lets go: b owns it now
    assert [p.getName() for p in a.parents] == ["b"]
    assert a.getPathName() == "/b/a"


def test_masses_have_sofapython3_classes():
    root = Sofa.Core.Node("root")
    root.addObject("MechanicalObject", name="dofs", position=[0, 0, 0])
    m = root.addObject("UniformMass", name="mass", totalMass=2.0)
    assert isinstance(m, Sofa.Core.MassVec3d) and isinstance(m, Sofa.Core.BaseMass)
    r = root.addChild("r")
    r.addObject("MechanicalObject", template="Rigid3d", name="dofs", position=[0, 0, 0, 0, 0, 0, 1])
    assert isinstance(r.addObject("UniformMass", name="mass", totalMass=1.0), Sofa.Core.MassRigid3d)
    Sofa.Simulation.init(root)
    assert root.mass.mstate is not None
    assert root.mass.assembleMMatrix().toarray()[0, 0] == 2.0
