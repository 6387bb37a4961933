"""10,000 reads of `.value` of a 5,000-point position (issue 12: < 10 ms in all)."""
import time

import numpy as np

import Sofa.Core


def main():
    root = Sofa.Core.Node("root")
    n = root.addChild("n")
    dofs = n.addObject("MechanicalObject", name="dofs", position=np.zeros((5000, 3)))
    data = dofs.position
    best = float("inf")
    for _ in range(5):
        t0 = time.perf_counter()
        for _ in range(10000):
            data.value
        best = min(best, time.perf_counter() - t0)
    lookup = float("inf")
    for _ in range(5):
        t0 = time.perf_counter()
        for _ in range(10000):
            dofs.position.value
        lookup = min(lookup, time.perf_counter() - t0)
    print("10,000 reads of a held Data:            %.2f ms" % (best * 1e3))
    print("10,000 reads through dofs.position:     %.2f ms" % (lookup * 1e3))


if __name__ == "__main__":
    main()
