"""The 10x10x40 tetrahedron beam of beam.scn, built from Python, with one empty Controller
(issue 12: within 5% of the XML scene's ms/step)."""
import Sofa.Core


class Empty(Sofa.Core.Controller):
    def __init__(self, *args, **kwargs):
        Sofa.Core.Controller.__init__(self, *args, **kwargs)

    def onAnimateBeginEvent(self, event):
        pass

    def onAnimateEndEvent(self, event):
        pass


def createScene(root):
    root.dt = 0.01
    root.gravity = [0, -9.81, 0]
    root.addObject("DefaultAnimationLoop")
    root.addObject(Empty(name="empty"))
    beam = root.addChild("beam")
    beam.addObject("EulerImplicitSolver", rayleighStiffness=0.1, rayleighMass=0.1)
    beam.addObject("CGLinearSolver", iterations=25, tolerance=1e-9, threshold=1e-9)
    beam.addObject("RegularGridTopology", name="grid", nx=10, ny=10, nz=40, xmin=0, xmax=1, ymin=0, ymax=1, zmin=0,
                   zmax=4)
    beam.addObject("MechanicalObject", name="dofs")
    beam.addObject("TetrahedronSetTopologyContainer", name="tetras")
    beam.addObject("TetrahedronSetTopologyModifier")
    beam.addObject("Hexa2TetraTopologicalMapping", input="@grid", output="@tetras")
    beam.addObject("UniformMass", totalMass=4)
    beam.addObject("TetrahedronFEMForceField", youngModulus=10000, poissonRatio=0.3, method="large",
                   topology="@tetras")
    beam.addObject("BoxROI", name="box", box=[-0.1, -0.1, -0.1, 1.1, 1.1, 0.01])
    beam.addObject("FixedProjectiveConstraint", indices="@box.indices")
