"""Sofa.SofaLinearSystem: the assembled global system of a matrix linear system.

On every ``MatrixLinearSystem`` (and ``CompositeLinearSystem``, ...), whatever
its matrix template: ``A()`` / ``get_system_matrix()`` (scipy.sparse CSR, a
dense numpy array for ``FullMatrix``), ``b()`` / ``get_rhs_vector()`` and
``x()`` / ``get_solution_vector()`` (numpy), as assembled and solved in the
last time step.

SofaPython3 has one class per matrix template; Sinew has one for all, under
each of SofaPython3's names.
"""
import _sinew

MatrixLinearSystem = _sinew.MatrixLinearSystem
_TEMPLATES = ["FullMatrix", "SparseMatrix", "CompressedRowSparseMatrixd", "CompressedRowSparseMatrixMat2x2d",
              "CompressedRowSparseMatrixMat3x3d", "CompressedRowSparseMatrixMat4x4d",
              "CompressedRowSparseMatrixMat6x6d", "CompressedRowSparseMatrixMat8x8d", "DiagonalMatrix",
              "BlockDiagonalMatrixMat3x3d", "RotationMatrixd", "BTDMatrix6d"]
for _t in _TEMPLATES:
    globals()["TypedMatrixLinearSystem" + _t] = MatrixLinearSystem

__all__ = ["MatrixLinearSystem"] + ["TypedMatrixLinearSystem" + t for t in _TEMPLATES]
