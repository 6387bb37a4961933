"""Python twin of examples/Component/LinearSolver/Iterative/FEMBAR_CGLinearSolver.scn (with FEMBAR-common.xml)."""


def createScene(root):
    root.name = "root"
    root.dt = 0.02
    root.gravity = [0, -10, 0]
    plugins = root.addChild("plugins")
    plugins.addObject("RequiredPlugin", pluginName=["Sofa.Component.Constraint.Projective",
                                                    "Sofa.Component.Mass", "Sofa.Component.ODESolver.Backward",
                                                    "Sofa.Component.SolidMechanics.FEM.Elastic",
                                                    "Sofa.Component.StateContainer",
                                                    "Sofa.Component.Topology.Container.Grid",
                                                    "Sofa.Component.Engine.Select",
                                                    "Sofa.Component.LinearSolver.Iterative"])
    root.addObject("VisualStyle", displayFlags="showBehaviorModels showForceFields")
    root.addObject("DefaultAnimationLoop", name="animationLoop")
    root.addObject("DefaultVisualManagerLoop", name="visualLoop")
    root.addObject("EulerImplicitSolver", name="odesolver", rayleighStiffness=0.1, rayleighMass=0.1)
    root.addObject("MechanicalObject", name="DoFs")
    root.addObject("UniformMass", name="mass", totalMass=320)
    root.addObject("RegularGridTopology", name="grid", nx=4, ny=4, nz=20, xmin=-9, xmax=-6, ymin=0, ymax=3,
                   zmin=0, zmax=19)
    root.addObject("BoxROI", name="box", box=[-10, -1, -0.0001, -5, 4, 0.0001])
    root.addObject("FixedProjectiveConstraint", indices="@box.indices")
    root.addObject("CGLinearSolver", template="GraphScattered", iterations=1000, threshold=1e-9, tolerance=1e-9)
    root.addObject("HexahedronFEMForceField", name="FEM", youngModulus=4000, poissonRatio=0.45, method="large")
