"""SofaTypes: vector types (numpy based)."""
from Sofa.PyTypes import Vec3, RGBAColor  # noqa: F401

Vec3d = Vec3

__all__ = ["Vec3", "Vec3d", "RGBAColor"]
