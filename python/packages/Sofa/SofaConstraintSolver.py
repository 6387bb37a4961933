"""Sofa.SofaConstraintSolver: the constraint problem of a Lagrangian constraint solver.

On every constraint solver (BlockGaussSeidelConstraintSolver, NNCGConstraintSolver,
UnbuiltGaussSeidelConstraintSolver, ImprovedJacobiConstraintSolver, ...):
``W()`` (compliance in constraint space, numpy n×n), ``lambda_force()`` (λ, numpy n)
and ``dfree()`` (numpy n), of the last solve. Controllers get
``onBuildConstraintSystemEndEvent`` once W is built and
``onSolveConstraintSystemEndEvent`` once λ is found.
"""
import _sinew

ConstraintSolver = _sinew.ConstraintSolver
ConstraintSolverImpl = ConstraintSolver

__all__ = ["ConstraintSolver", "ConstraintSolverImpl"]
