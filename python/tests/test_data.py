"""Data: values as Python scalars, strings and numpy views of every shape; writes; links."""
import numpy as np
import pytest

import Sofa.Core
import Sofa.Simulation


@pytest.fixture
def scene():
    root = Sofa.Core.Node("root")
    root.addObject("DefaultAnimationLoop")
    n = root.addChild("n")
    n.addObject("MeshTopology", name="topo", position=[0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1],
                triangles=[0, 1, 2, 0, 2, 3], tetrahedra=[0, 1, 2, 3])
    n.addObject("MechanicalObject", name="dofs", position="@topo.position")
    r = root.addChild("r")
    r.addObject("MechanicalObject", name="rigid", template="Rigid3d", position=[1, 2, 3, 0, 0, 0, 1])
    return root


def test_scalars_and_strings(scene):
    assert isinstance(scene.dt.value, float) and scene.dt.value == 0.01
    assert scene.n.dofs.name.value == "dofs"
    assert isinstance(scene.n.dofs.name.value, str)
    assert scene.activated.value is True
    assert isinstance(scene.n.dofs.drawMode.value, int)
    scene.dt.value = 0.02
    assert scene.dt.value == 0.02
    scene.dt = 0.03  # direct assignment on the node (SofaPython3)
    assert scene.dt.value == 0.03
    scene.n.dofs.name = "renamed"
    assert scene.n.getObject("renamed") is not None
    assert scene.n.renamed.tags.value == []
    scene.n.renamed.tags = ["a", "b"]
    assert scene.n.renamed.tags.value == ["a", "b"]
    with pytest.raises(ValueError):
        scene.dt.value = "not a number"


def test_numpy_views_of_every_shape(scene):
    Sofa.Simulation.init(scene)
    pos = scene.n.dofs.position.value
    assert pos.shape == (4, 3) and pos.dtype == np.float64
    assert (pos[1] == [1, 0, 0]).all()
    tri = scene.n.topo.triangles.value
    assert tri.shape == (2, 3) and tri.dtype == np.uint32 and tri.tolist() == [[0, 1, 2], [0, 2, 3]]
    assert scene.n.topo.tetrahedra.value.shape == (1, 4)
    g = scene.gravity.value
    assert g.shape == (3,) and g[1] == -9.81
    rig = scene.r.rigid.position.value
    assert rig.shape == (1, 7) and rig.tolist() == [[1, 2, 3, 0, 0, 0, 1]]
    assert scene.r.rigid.velocity.value.shape == (1, 6)
    # read-only views: edits must go through writeableArray()
    with pytest.raises(ValueError):
        pos[0, 0] = 5.0
    # a view, not a copy: it sees later writes
    with scene.n.dofs.position.writeableArray() as w:
        w[0] = [0.5, 0.25, 0.125]
    assert pos[0].tolist() == [0.5, 0.25, 0.125]
    assert len(scene.n.dofs.position) == 4
    assert scene.n.dofs.position[1].tolist() == [1, 0, 0]
    assert np.asarray(scene.n.dofs.position).shape == (4, 3)


def test_matrix_and_lists():
    root = Sofa.Core.Node("root")
    n = root.addChild("n")
    n.addObject("MechanicalObject", position=[0, 0, 0, 1, 0, 0])
    c = n.addObject("AffineMovementProjectiveConstraint", meshIndices=[0], indices=[0],
                    rotation="[0 -1 0,1 0 0,0 0 1]", translation=[1, 2, 3], beginConstraintTime=0, endConstraintTime=1)
    m = c.rotation.value
    assert m.shape == (3, 3)
    assert m.tolist() == [[0, -1, 0], [1, 0, 0], [0, 0, 1]]  # rows as written, though stored by columns
    c.rotation.value = np.array([[1, 0, 0], [0, 0, -1], [0, 1, 0]])
    assert c.rotation.getValueString() == "[1 0 0,0 0 -1,0 1 0]"
    idx = c.indices.value
    assert idx.dtype == np.uint32 and idx.tolist() == [0]
    c.indices.value = [0, 1]  # another length: resized
    assert c.indices.value.tolist() == [0, 1]


def test_writes_resize_and_convert(scene):
    d = scene.n.dofs
    d.position.value = [[0, 0, 0], [2, 0, 0]]
    assert d.position.value.shape == (2, 3)
    d.position.value = np.array([[1.5, 2.5, 3.5], [4, 5, 6]])
    assert d.position.value.tolist() == [[1.5, 2.5, 3.5], [4, 5, 6]]
    d.position.value = "7 8 9"
    assert d.position.value.tolist() == [[7, 8, 9]]
    with scene.gravity.writeableArray() as g:
        g[2] = 1.0
    assert scene.gravity.value.tolist() == [0, -9.81, 1.0]
    with scene.dt.writeableArray() as a:  # a single number: a one-element array
        a[0] = 0.25
    assert scene.dt.value == 0.25


def test_links(scene):
    d = scene.n.dofs
    assert str(d.position.linkpath) == "@/n/dofs.position"
    assert d.position.getLinkPath() == "@/n/dofs.position"
    assert str(d.linkpath) == "@/n/dofs"
    assert d.position.hasParent()  # position="@topo.position"
    assert d.position.getParent().getOwner() is scene.n.topo
    other = scene.n.addObject("MechanicalObject", name="copy", position=d.position.linkpath)
    assert other.position.value.shape == (4, 3)
    third = scene.n.addObject("MechanicalObject", name="third")
    third.position.setParent(d.position)
    assert third.position.value.tolist() == d.position.value.tolist()
    # an object given for a link is its path; object links resolve at init at the latest
    m = scene.n.addObject("UniformMass", totalMass=1, mstate=third)
    Sofa.Simulation.init(scene)
    assert m.mstate is third


def test_data_fields_and_dynamic_data(scene):
    d = scene.n.dofs
    names = [f.getName() for f in d.getDataFields()]
    assert "position" in names and "velocity" in names
    assert d.getData("velocity").getName() == "velocity"
    assert d.findData("nothing") is None
    x = scene.addData("custom", value=[1.0, 2.0], help="a list", group="Test")
    assert x.value.tolist() == [1.0, 2.0]
    assert scene.custom.getHelp() == "a list"
    s = scene.addData("label", value="hello", type="string")
    assert s.value == "hello"
    with pytest.raises(ValueError):
        scene.addData("label", value="twice")
    with pytest.raises(TypeError):
        scene.addData("bad", value=1, type="NoSuchType")
