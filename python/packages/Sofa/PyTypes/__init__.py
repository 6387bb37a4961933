"""Sofa.PyTypes: numpy arrays with the accessors of SOFA's small types."""
import math

import numpy


class Vec3(numpy.ndarray):
    """A 3-vector: Vec3(), Vec3(s), Vec3(x, y, z), Vec3([x, y, z]) or Vec3(data)."""

    def __new__(cls, *args):
        if len(args) == 0:
            values = [0.0, 0.0, 0.0]
        elif len(args) == 1 and numpy.isscalar(args[0]):
            values = [float(args[0])] * 3
        elif len(args) == 1:
            a = args[0]
            values = a.value if hasattr(a, "value") else a
        elif len(args) == 3:
            values = args
        else:
            raise ValueError("Vec3 takes 0, 1 or 3 arguments")
        arr = numpy.array(values, dtype=float).reshape(3)
        return arr.view(cls)

    def getNorm(self):
        return float(numpy.linalg.norm(self))

    def normalize(self):
        n = self.getNorm()
        if n > 0:
            self /= n
        return self

    def translate(self, v):
        self += numpy.asarray(v, dtype=float)
        return self

    def scale(self, s):
        self *= s
        return self

    def rotateFromQuat(self, q):
        x, y, z, w = (float(c) for c in q)
        v = numpy.array(self, dtype=float)
        u = numpy.array([x, y, z])
        r = v + 2.0 * numpy.cross(u, numpy.cross(u, v) + w * v)
        self[:] = r
        return self

    def rotateFromAxisAngle(self, axis, angle):
        a = numpy.asarray(axis, dtype=float)
        a = a / numpy.linalg.norm(a)
        s = math.sin(angle / 2.0)
        return self.rotateFromQuat([a[0] * s, a[1] * s, a[2] * s, math.cos(angle / 2.0)])

    def rotateFromEuler(self, euler):
        """Rotation about x, then y, then z (radians)."""
        for axis, angle in zip(([1, 0, 0], [0, 1, 0], [0, 0, 1]), euler):
            if angle:
                self.rotateFromAxisAngle(axis, angle)
        return self

    def toString(self):
        return " ".join(repr(float(c)) for c in self)

    @staticmethod
    def dot(v1, v2):
        return float(numpy.dot(v1, v2))

    @staticmethod
    def cross(v1, v2):
        return Vec3(numpy.cross(v1, v2))


class RGBAColor(numpy.ndarray):
    """A colour of 4 components in [0, 1]: RGBAColor(), RGBAColor([r, g, b, a]) or RGBAColor(data)."""

    def __new__(cls, values=None):
        if values is None:
            values = [0.0, 0.0, 0.0, 0.0]
        elif hasattr(values, "value"):
            values = values.value
        arr = numpy.array(values, dtype=float)
        if arr.shape != (4,):
            raise ValueError("an RGBA colour has 4 components, got shape %s" % (arr.shape,))
        return arr.view(cls)

    def r(self):
        return float(self[0])

    def g(self):
        return float(self[1])

    def b(self):
        return float(self[2])

    def a(self):
        return float(self[3])


__all__ = ["Vec3", "RGBAColor"]
