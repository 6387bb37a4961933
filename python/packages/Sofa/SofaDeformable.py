"""Sofa.SofaDeformable: linear springs (SofaPython3's module of the same name).

``LinearSpring(index1, index2, springStiffness=100, dampingFactor=5, restLength,
elongationOnly=False, enabled=True)``, and on every SpringForceField
(``node.addObject("SpringForceField", ...)``): ``getSprings()``, ``addSpring``,
``addSprings``, ``removeSpring``, ``removeSprings``, ``clear``.

Sinew has one SpringForceField class for every template: the per-template
names SofaPython3 gives (``SpringForceField_Vec3d``, ...) are that class.
"""
import _sinew

LinearSpring = _sinew.LinearSpring
SpringForceField = _sinew.SpringForceField
SpringForceField_Vec1d = SpringForceField
SpringForceField_Vec2d = SpringForceField
SpringForceField_Vec3d = SpringForceField
SpringForceField_Vec6d = SpringForceField
SpringForceField_Rigid3d = SpringForceField

__all__ = ["LinearSpring", "SpringForceField", "SpringForceField_Vec1d", "SpringForceField_Vec2d",
           "SpringForceField_Vec3d", "SpringForceField_Vec6d", "SpringForceField_Rigid3d"]
