"""Sofa.Types: small value types."""
from Sofa.PyTypes import RGBAColor  # noqa: F401  (SofaPython3 has it here too)


class BoundingBox:
    """An axis-aligned box given by its minimum and maximum corners."""

    def __init__(self, min_corner=(0.0, 0.0, 0.0), max_corner=(0.0, 0.0, 0.0)):
        self._min = [float(v) for v in min_corner]
        self._max = [float(v) for v in max_corner]

    def getMin(self):
        return list(self._min)

    def getMax(self):
        return list(self._max)

    def setMin(self, v):
        self._min = [float(x) for x in v]

    def setMax(self, v):
        self._max = [float(x) for x in v]

    def getCenter(self):
        return [(a + b) / 2 for a, b in zip(self._min, self._max)]
