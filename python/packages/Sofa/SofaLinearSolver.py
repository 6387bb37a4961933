"""Sofa.SofaLinearSolver: the system a matrix linear solver solved.

On every linear solver working on an assembled system (SparseLDLSolver,
EigenSimplicialLLT, CGLinearSolver with a matrix template, ...): ``A()``
(scipy.sparse CSR; dense numpy for FullMatrix), ``b()`` and ``x()`` (numpy),
those of its linear system in the last time step.
"""
import _sinew

MatrixLinearSolver = _sinew.MatrixLinearSolver
MatrixLinearSolverCompressedRowSparseMatrixd = MatrixLinearSolver
MatrixLinearSolverCompressedRowSparseMatrixMat3x3d = MatrixLinearSolver

__all__ = ["MatrixLinearSolver", "MatrixLinearSolverCompressedRowSparseMatrixd",
           "MatrixLinearSolverCompressedRowSparseMatrixMat3x3d"]
