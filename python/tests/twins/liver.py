"""Python twin of examples/Demos/liver.scn."""


def createScene(root):
    root.name = "lroot"
    root.gravity = [0, -9.81, 0]
    root.dt = 0.02
    root.addObject("CollisionPipeline", name="CollisionPipeline", verbose=False)
    root.addObject("DefaultAnimationLoop")
    root.addObject("BruteForceBroadPhase")
    root.addObject("BVHNarrowPhase")
    root.addObject("CollisionResponse", name="collision response", response="PenalityContactForceField")
    root.addObject("DiscreteIntersection")
    root.addObject("MeshOBJLoader", name="LiverSurface", filename="mesh/liver-smooth.obj")

    liver = root.addChild("Liver", gravity=[0, -9.81, 0])
    liver.addObject("EulerImplicitSolver", name="cg_odesolver", rayleighStiffness=0.1, rayleighMass=0.1)
    liver.addObject("CGLinearSolver", name="linear solver", iterations=25, tolerance=1e-09, threshold=1e-09)
    liver.addObject("MeshGmshLoader", name="meshLoader", filename="mesh/liver.msh")
    liver.addObject("TetrahedronSetTopologyContainer", name="topo", src="@meshLoader")
    liver.addObject("MechanicalObject", name="dofs", src="@meshLoader")
    liver.addObject("TetrahedronSetGeometryAlgorithms", template="Vec3", name="GeomAlgo")
    liver.addObject("DiagonalMass", name="computed using mass density", massDensity=1)
    liver.addObject("TetrahedralCorotationalFEMForceField", template="Vec3", name="FEM", method="large",
                    poissonRatio=0.3, youngModulus=3000, computeGlobalMatrix=False)
    liver.addObject("FixedProjectiveConstraint", name="FixedProjectiveConstraint", indices=[3, 39, 64])

    visu = liver.addChild("Visu", tags="Visual", gravity=[0, -9.81, 0])
    visu.addObject("OglModel", name="VisualModel", src="@../../LiverSurface")
    visu.addObject("BarycentricMapping", name="visual mapping", input="@../dofs", output="@VisualModel")

    surf = liver.addChild("Surf", gravity=[0, -9.81, 0])
    surf.addObject("SphereLoader", filename="mesh/liver.sph")
    surf.addObject("MechanicalObject", name="spheres", position="@[-1].position")
    surf.addObject("SphereCollisionModel", name="CollisionModel", listRadius="@[-2].listRadius")
    surf.addObject("BarycentricMapping", name="sphere mapping", input="@../dofs", output="@spheres")
