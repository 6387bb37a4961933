"""Sofa.SofaConstraintSolver (W, lambda_force, dfree), the constraint events, and a
state's `constraint` (Jacobian rows) and `lambda` (Jᵀλ) Data."""
import numpy as np
import pytest

import Sofa.Core
import Sofa.Simulation
from Sofa import SofaConstraintSolver

scipy_sparse = pytest.importorskip("scipy.sparse")

POINTS = 20  # StringMeshCreator resolution 20: 20 points, 19 edges, one constraint row per edge


class Recorder(Sofa.Core.Controller):
    def __init__(self, *args, **kwargs):
        Sofa.Core.Controller.__init__(self, *args, **kwargs)
        self.solver = kwargs.get("solver")
        self.mo = kwargs.get("mo")
        self.log = []

    def onBuildConstraintSystemEndEvent(self, event):
        self.log.append(("build", self.solver.W(), self.solver.dfree(), self.mo.constraint.value))

    def onSolveConstraintSystemEndEvent(self, event):
        self.log.append(("solve", self.solver.lambda_force()))


def string_scene():
    root = Sofa.Core.Node("root")
    root.addObject("FreeMotionAnimationLoop", solveVelocityConstraintFirst=True)
    solver = root.addObject("BlockGaussSeidelConstraintSolver", tolerance=1e-9, maxIterations=1000)
    root.addObject("StringMeshCreator", name="loader", resolution="20")
    root.addObject("EulerImplicitSolver")
    root.addObject("EigenSimplicialLLT", template="CompressedRowSparseMatrixMat3x3d")
    root.addObject("GenericConstraintCorrection")
    root.addObject("EdgeSetTopologyContainer", name="topo", position="@loader.position", edges="@loader.edges")
    mo = root.addObject("MechanicalObject", name="defoDOF", template="Vec3d")
    root.addObject("FixedProjectiveConstraint", indices=[0])
    root.addObject("DiagonalMass", name="mass", totalMass="1e-3")
    ext = root.addChild("extensionsNode")
    ext.addObject("MechanicalObject", template="Vec1d", name="extensionsDOF")
    ext.addObject("DistanceMapping", name="distanceMapping", topology="@topo")
    ext.addObject("UniformLagrangianConstraint", template="Vec1d", iterative=True)
    rec = root.addObject(Recorder(name="rec", solver=solver, mo=mo))
    Sofa.Simulation.init(root)
    return root, solver, mo, rec


def test_compliance_and_forces_of_a_string():
    root, solver, mo, rec = string_scene()
    assert isinstance(solver, SofaConstraintSolver.ConstraintSolver)
    for _ in range(3):
        Sofa.Simulation.animate(root, root.dt.value)
    # one build and one solve per step (solveVelocityConstraintFirst: a single solve), in that order
    assert [e[0] for e in rec.log] == ["build", "solve"] * 3
    _, W, dfree, J = rec.log[-2]
    (_, lam), n = rec.log[-1], POINTS - 1
    assert W.shape == (n, n) and W.dtype == np.float64 and dfree.shape == (n,) and lam.shape == (n,)
    np.testing.assert_allclose(W, W.T, rtol=0, atol=1e-12 * abs(W).max())
    assert np.all(np.diag(W) > 0)
    assert np.all(np.linalg.eigvalsh(W) > 0)
    # the solver's own copies after the step
    np.testing.assert_array_equal(solver.W(), W)
    np.testing.assert_array_equal(solver.lambda_force(), lam)
    # the Jacobian on the string: one row per edge, on the edge's two points
    assert scipy_sparse.issparse(J) and J.shape == (n, 3 * POINTS)
    for i in range(n):
        cols = J[i].nonzero()[1]
        assert len(cols) > 0 and set(cols) <= set(range(3 * i, 3 * i + 6))
    assert J.nnz == 3 * (2 * n - 1)  # point 0 is fixed: its block is left out of row 0 (SOFA erases it)
    # lambda: Jᵀλ on every state; on the Vec1d extensions (J = I) it is λ itself
    np.testing.assert_allclose(root.extensionsNode.extensionsDOF.getData("lambda").value[:, 0], lam,
                               rtol=1e-14, atol=0)
    L = mo.getData("lambda").value
    assert L.shape == (POINTS, 3)
    np.testing.assert_allclose(L.ravel(), J.T @ lam, rtol=1e-12, atol=1e-15 * abs(lam).max())


def test_only_constraint_solvers_have_W():
    root = Sofa.Core.Node("root")
    mo = root.addObject("MechanicalObject")
    assert not hasattr(mo, "W") and not hasattr(mo, "lambda_force")
    assert mo.constraint.value.shape == (0, 0)  # no constraint solved yet


def test_visual_vector_field_has_sofas_data_and_follows_lambda():
    root, solver, mo, rec = string_scene()
    v = root.addObject("VisualVectorField", name="arrows", position="@defoDOF.position", vector="@defoDOF.lambda",
                       vectorScale=100, color="orange", drawMode="Arrow")
    names = {d.getName() for d in v.getDataFields()}
    assert {"enable", "position", "vector", "vectorScale", "drawMode", "color"} <= names
    Sofa.Simulation.animate(root, root.dt.value)
    np.testing.assert_array_equal(v.vector.value, mo.getData("lambda").value)
    assert v.position.value.shape == (POINTS, 3) and v.vectorScale.value == 100 and v.drawMode.value == "Arrow"
    v.vectorScale.value = 0.5
    assert v.vectorScale.value == 0.5
