"""Python components: Controller events, ForceField and DataEngine subclasses."""
import numpy as np
import pytest

import Sofa.Core
import Sofa.Simulation
import _sinew


class Recorder(Sofa.Core.Controller):
    def __init__(self, *args, **kwargs):
        Sofa.Core.Controller.__init__(self, *args, **kwargs)
        self.events = []
        self.inits = 0

    def init(self):
        self.inits += 1

    def onAnimateBeginEvent(self, event):
        self.events.append(("begin", event["dt"], event["isHandled"]))

    def onAnimateEndEvent(self, event):
        self.events.append(("end", event["dt"]))

    def onKeypressedEvent(self, event):
        self.events.append(("key", event["key"]))
        return True  # handled: not passed on below this node

    def onEvent(self, event):
        self.events.append(("other", event["type"]))


def test_controller_receives_events_in_order():
    root = Sofa.Core.Node("root")
    root.addObject("DefaultAnimationLoop")
    rec = root.addObject(Recorder(name="rec"))
    assert rec.getName() == "rec"
    assert rec.getClassName() == "Recorder"
    assert root.rec is rec  # the graph gives back the Python instance itself
    assert rec.listening.value is True
    Sofa.Simulation.init(root)
    assert rec.inits == 1
    Sofa.Simulation.animate(root, 0.01)
    Sofa.Simulation.animate(root, 0.02)
    _sinew.sendKey(root, "M")
    assert rec.events == [("other", "SimulationInitDoneEvent"), ("begin", 0.01, False), ("end", 0.01),
                          ("begin", 0.02, False), ("end", 0.02), ("key", "M")]


def test_controller_kwargs_and_script_events():
    class Ctl(Sofa.Core.Controller):
        def __init__(self, *args, **kwargs):
            Sofa.Core.Controller.__init__(self, *args, **kwargs)
            self.got = []

        def onPythonScriptEvent(self, event):
            self.got.append((event["event_name"], event["userData"], event["sender"]))

    root = Sofa.Core.Node("root")
    c = root.addObject(Ctl(name="ctl", printLog=True, other_value=3))
    assert c.printLog.value is True
    root.sendEvent({"a": 1}, "hello")
    assert c.got == [("hello", {"a": 1}, root)]


def test_controller_error_reports_traceback(tmp_path, capfd):
    class Broken(Sofa.Core.Controller):
        def onAnimateBeginEvent(self, event):
            raise RuntimeError("boom in the controller")

    root = Sofa.Core.Node("root")
    root.addObject("DefaultAnimationLoop")
    root.addObject(Broken(name="broken"))
    Sofa.Simulation.init(root)
    Sofa.Simulation.animate(root)
    err = capfd.readouterr().err
    assert "boom in the controller" in err
    assert "test_components.py" in err and "Traceback" in err


class RestShape(Sofa.Core.ForceFieldVec3d):
    """f = -k (x - x0), with its stiffness for implicit solvers."""

    def __init__(self, k, *args, **kwargs):
        Sofa.Core.ForceFieldVec3d.__init__(self, *args, **kwargs)
        self.addData("ks", type="double", value=k, help="stiffness")

    def init(self):
        self.x0 = self.getContext().getMechanicalState().rest_position.value.copy()

    def addForce(self, mparams, f, x, v):
        with f.writeableArray() as w:
            w[:] += (self.x0 - x.value) * self.ks.value

    def addDForce(self, mparams, df, dx):
        with df.writeableArray() as w:
            w[:] -= dx.value * self.ks.value * mparams["kFactor"]

    def addKToMatrix(self, mparams, nnodes, ndofs):
        # SofaPython3's dense form: an (n, n, 1) array (an (m, 3) array is (i, j, value) rows).
        return (-self.ks.value * np.eye(nnodes * ndofs))[:, :, None]


def particle_scene(ff):
    root = Sofa.Core.Node("root", dt=0.01, gravity=[0, 0, 0])
    root.addObject("DefaultAnimationLoop")
    n = root.addChild("p")
    n.addObject("EulerImplicitSolver", rayleighStiffness=0, rayleighMass=0)
    n.addObject("CGLinearSolver", iterations=100, tolerance=1e-20, threshold=1e-20)
    n.addObject("MechanicalObject", name="dofs", position=[0, 0, 0], rest_position=[0, 0, 0], velocity=[1, 0, 0])
    n.addObject("UniformMass", totalMass=2.0)
    ff(n)
    Sofa.Simulation.init(root)
    return root, n


def test_python_force_field_matches_builtin_spring():
    root_py, n_py = particle_scene(lambda n: n.addObject(RestShape(50.0, name="spring")))
    root_cpp, n_cpp = particle_scene(
        lambda n: n.addObject("RestShapeSpringsForceField", stiffness=50.0, points=[0]))
    for _ in range(20):
        Sofa.Simulation.animate(root_py)
        Sofa.Simulation.animate(root_cpp)
    a = n_py.dofs.position.value
    b = n_cpp.dofs.position.value
    assert a[0][0] != 0
    np.testing.assert_allclose(a, b, rtol=0, atol=1e-12)
    k = n_py.spring.assembleKMatrix().toarray()
    assert k.shape == (3, 3) and k[0, 0] == -50.0


def test_data_engine_updates_outputs_from_inputs():
    class Double(Sofa.Core.DataEngine):
        def __init__(self, *args, **kwargs):
            Sofa.Core.DataEngine.__init__(self, *args, **kwargs)
            self.addData("a", value=[1.0, 2.0], type="vector<double>")
            self.addData("b", value=[], type="vector<double>")
            self.addInput(self.a)
            self.addOutput(self.b)
            self.calls = 0

        def update(self):
            self.calls += 1
            self.b.value = 2 * np.asarray(self.a.value)

    root = Sofa.Core.Node("root")
    e = root.addObject(Double(name="double"))
    assert e.b.value.tolist() == [2.0, 4.0]
    assert e.b.value.tolist() == [2.0, 4.0]
    assert e.calls == 1  # outputs are recomputed only when an input changed
    e.a.value = [3.0]
    assert e.b.value.tolist() == [6.0]
    assert e.calls == 2


def test_factory_lists_components():
    names = [c.className for c in Sofa.Core.ObjectFactory.getComponentsList()]
    assert "MechanicalObject" in names and "TetrahedronFEMForceField" in names
    mo = Sofa.Core.ObjectFactory.getComponent("MechanicalObject")
    assert "Vec3d" in mo.templates and "Rigid3d" in mo.templates
    fields = {d["name"]: d for d in mo.data}
    assert fields["position"]["layout"] == "array"
    assert Sofa.Core.ObjectFactory.hasComponent("FixedConstraint")  # SOFA's old name still known
    assert not Sofa.Core.ObjectFactory.hasComponent("NoSuchThing")


def test_type_stubs_name_every_component_and_its_data(tmp_path):
    import ast
    from sinew import stubs
    assert stubs.main([str(tmp_path)]) == 0
    text = (tmp_path / "Sofa-stubs" / "Core.pyi").read_text()
    ast.parse(text)
    mo = [line for line in text.splitlines() if "Literal['MechanicalObject']" in line]
    assert len(mo) == 1 and "position: ArrayLike | str" in mo[0] and "showObject: bool | str" in mo[0]
    for c in Sofa.Core.ObjectFactory.getComponentsList():
        assert "Literal[%r]" % c.className in text


def test_python_force_fields_in_parallel_branches():
    """parallelODESolving integrates branches on worker threads: each Python call takes the GIL
    (animate releases it), so two Python force fields in two branches neither deadlock nor race."""
    root = Sofa.Core.Node("root", dt=0.01, gravity=[0, 0, 0])
    root.addObject("DefaultAnimationLoop", parallelODESolving=True)
    branches = []
    for i in range(2):
        n = root.addChild("b%d" % i)
        n.addObject("EulerImplicitSolver", rayleighStiffness=0, rayleighMass=0)
        n.addObject("CGLinearSolver", iterations=100, tolerance=1e-20, threshold=1e-20)
        n.addObject("MechanicalObject", name="dofs", position=[0, 0, 0], velocity=[1 + i, 0, 0])
        n.addObject("UniformMass", totalMass=2.0)
        n.addObject(RestShape(50.0, name="spring"))
        branches.append(n)
    Sofa.Simulation.init(root)
    for _ in range(50):
        Sofa.Simulation.animate(root)
    x0 = branches[0].dofs.position.value[0][0]
    x1 = branches[1].dofs.position.value[0][0]
    assert x0 != 0 and x1 == pytest.approx(2 * x0, rel=1e-9)  # linear: twice the initial velocity
