"""Sofa.SofaLinearSystem / Sofa.SofaLinearSolver: the global system A·x = b of the last solve."""
import numpy as np
import pytest

import Sofa.Core
import Sofa.Simulation
from Sofa import SofaLinearSolver, SofaLinearSystem

scipy_sparse = pytest.importorskip("scipy.sparse")

N = 2 * 2 * 5  # grid points


def beam(node, matrix_template, solver, mass="UniformMass", **system_kw):
    node.addObject("EulerImplicitSolver", rayleighStiffness=0.1, rayleighMass=0.1)
    system = node.addObject("MatrixLinearSystem", template=matrix_template, name="system", **system_kw)
    node.addObject("MechanicalObject", name="dofs")
    node.addObject(mass, name="mass", totalMass=320)
    node.addObject("RegularGridTopology", name="grid", nx=2, ny=2, nz=5, xmin=0, xmax=1, ymin=0, ymax=1,
                   zmin=0, zmax=4)
    node.addObject("FixedProjectiveConstraint", indices=[0, 1, 2, 3])  # the z = 0 face
    node.addObject("HexahedronFEMForceField", youngModulus=4000, poissonRatio=0.3, method="large")
    node.addObject(solver, name="solver", template=matrix_template)
    return system


def run(make, steps=1):
    root = Sofa.Core.Node("root")
    root.gravity = [0, -9.81, 0]
    root.dt = 0.01
    root.addObject("DefaultAnimationLoop")
    out = make(root)
    Sofa.Simulation.init(root)
    for _ in range(steps):
        Sofa.Simulation.animate(root, root.dt.value)
    return root, out


def test_sparse_system_matrix_rhs_and_solution():
    root, system = run(lambda r: beam(r, "CompressedRowSparseMatrixMat3x3d", "SparseLDLSolver"), steps=2)
    assert isinstance(system, SofaLinearSystem.TypedMatrixLinearSystemCompressedRowSparseMatrixMat3x3d)
    A = system.get_system_matrix()
    b = system.get_rhs_vector()
    x = system.get_solution_vector()
    assert scipy_sparse.issparse(A) and A.format == "csr" and A.dtype == np.float64
    assert A.shape == (3 * N, 3 * N) and b.shape == (3 * N,) and x.shape == (3 * N,)
    D = A.toarray()
    np.testing.assert_allclose(D, D.T, rtol=0, atol=1e-12 * abs(D).max())
    # fixed points: row and column cleared, 1 on the diagonal; their right-hand side projected to 0
    np.testing.assert_array_equal(D[:12], np.eye(3 * N)[:12])
    np.testing.assert_array_equal(D[:, :12], np.eye(3 * N)[:, :12])
    np.testing.assert_array_equal(b[:12], 0)
    assert abs(b[12:]).max() > 0
    # x solves the system the solver was given (a direct solver: to round-off)
    np.testing.assert_allclose(A @ x, b, rtol=0, atol=1e-9 * abs(b).max())
    assert np.all(np.linalg.eigvalsh(D) > 0)
    # the solver's binding gives the same arrays
    solver = root.solver
    assert isinstance(solver, SofaLinearSolver.MatrixLinearSolver)
    assert (solver.A() != A).nnz == 0
    np.testing.assert_array_equal(solver.b(), b)
    np.testing.assert_array_equal(solver.x(), x)


def test_full_matrix_is_dense_and_equal_to_the_sparse_one():
    root1, sparse = run(lambda r: beam(r, "CompressedRowSparseMatrixMat3x3d", "SparseLDLSolver"))
    root2, full = run(lambda r: beam(r, "FullMatrix", "CGLinearSolver"))  # the graphs live while used
    F = full.get_system_matrix()
    assert isinstance(F, np.ndarray) and F.shape == (3 * N, 3 * N)
    np.testing.assert_allclose(F, sparse.A().toarray(), rtol=0, atol=1e-12 * abs(F).max())


def test_mass_only_system_holds_the_mass_matrix():
    def make(root):
        root.addObject("EulerImplicitSolver", rayleighStiffness=0, rayleighMass=0)
        m = root.addChild("matrices")
        m.addObject("MatrixLinearSystem", template="CompressedRowSparseMatrixMat3x3d", name="system")
        M = m.addObject("MatrixLinearSystem", template="CompressedRowSparseMatrixMat3x3d", name="M",
                        assembleStiffness=False, assembleDamping=False, assembleGeometricStiffness=False,
                        applyProjectiveConstraints=False)
        root.addObject("CompositeLinearSystem", template="CompressedRowSparseMatrixMat3x3d", name="composite",
                       linearSystems="@matrices/system @matrices/M", solverLinearSystem="@matrices/system")
        root.addObject("SparseLDLSolver", template="CompressedRowSparseMatrixMat3x3d", linearSystem="@composite")
        masses = []
        for i, total in enumerate((320, 80)):
            b = root.addChild("beam%d" % i)
            b.addObject("MechanicalObject", name="dofs")
            masses.append(b.addObject("MeshMatrixMass", name="mass", totalMass=total))
            b.addObject("RegularGridTopology", nx=2, ny=2, nz=5, xmin=0, xmax=1, ymin=0, ymax=1, zmin=0, zmax=4)
            b.addObject("FixedProjectiveConstraint", indices=[0, 1, 2, 3])
            b.addObject("HexahedronFEMForceField", youngModulus=4000, poissonRatio=0.3)
        return M, masses

    _, (M_system, masses) = run(make)
    M = M_system.A()
    assert M.shape == (6 * N, 6 * N)
    # no projection in this system: the two beams' mass matrices, one after the other
    blocks = scipy_sparse.block_diag([m.assembleMMatrix() for m in masses]).toarray()
    np.testing.assert_allclose(M.toarray(), blocks, rtol=1e-14, atol=0)
    # each direction carries the total mass
    for c in range(3):
        assert M.toarray()[c::3, c::3].sum() == pytest.approx(400, rel=1e-12)


def test_only_systems_and_solvers_have_the_accessors():
    root = Sofa.Core.Node("root")
    mo = root.addObject("MechanicalObject")
    assert not hasattr(mo, "get_system_matrix") and not hasattr(mo, "A")
