"""Python twin of examples/Component/Collision/Response/FrictionContact.scn (Lagrangian friction contact)."""


def rigid_body(parent, name, mo, mass, visual_mesh, collision_mesh, scale, color):
    body = parent.addChild(name)
    body.addObject("MechanicalObject", template="Rigid3", **mo)
    body.addObject("UniformMass", totalMass=mass)
    body.addObject("UncoupledConstraintCorrection")
    visu = body.addChild("Visu")
    visu.addObject("MeshOBJLoader", name=visual_mesh[0], filename=visual_mesh[1], scale=scale, handleSeams=True)
    visu.addObject("OglModel", name="Visual", src="@" + visual_mesh[0], color=color)
    visu.addObject("RigidMapping", input="@..", output="@Visual")
    surf = body.addChild("Surf2")
    surf.addObject("MeshOBJLoader", name="loader", filename=collision_mesh, triangulate=True)
    surf.addObject("MeshTopology", src="@loader")
    surf.addObject("MechanicalObject", src="@loader", scale=scale)
    surf.addObject("TriangleCollisionModel")
    surf.addObject("LineCollisionModel")
    surf.addObject("PointCollisionModel")
    surf.addObject("RigidMapping")


def createScene(root):
    root.dt = 0.03
    root.gravity = [0, -9.810, 0]
    root.addObject("VisualStyle", displayFlags="showVisual showBehaviorModels")
    root.addObject("LCPConstraintSolver", maxIt=1000, tolerance=1e-6, initial_guess=False, build_lcp=True,
                   multi_grid=False, printLog=False, mu=0.000000000000000001)
    root.addObject("FreeMotionAnimationLoop")
    root.addObject("CollisionPipeline", depth=15, verbose=False, draw=False)
    root.addObject("BruteForceBroadPhase")
    root.addObject("BVHNarrowPhase")
    root.addObject("LocalMinDistance", name="Proximity", alarmDistance=0.3, contactDistance=0.1, useLMDFilters=False)
    root.addObject("CollisionResponse", name="Response", response="FrictionContactConstraint")
    scene = root.addChild("Node")
    scene.addObject("EulerImplicitSolver", name="cg_odesolver", printLog=False, rayleighStiffness=0.1, rayleighMass=0.1)
    scene.addObject("CGLinearSolver", iterations=25, name="linear solver", tolerance=1.0e-9, threshold=1.0e-9)
    rigid_body(scene, "TORUS", dict(scale=1.0, dx=0.0, dy=0.0, dz=0.0), 40.0, ("meshLoader_2", "mesh/torus.obj"),
               "mesh/torus_for_collision.obj", 1.0, [1.0, 0.5, 0.25, 1.0])
    rigid_body(scene, "CUBE", dict(scale=0.3, dx=-2.0, dy=-3.5, dz=-0.5, rx=10), 100.0,
               ("meshLoader_1", "mesh/smCube27.obj"), "mesh/smCube27.obj", 0.3, [0.0, 0.5, 0.5, 1.0])
    box = scene.addChild("BOX")
    box.addObject("MeshOBJLoader", name="loader", filename="mesh/box_inside.obj", triangulate=True)
    box.addObject("MeshTopology", src="@loader")
    box.addObject("MechanicalObject", src="@loader")
    box.addObject("TriangleCollisionModel", simulated=False, moving=False)
    box.addObject("LineCollisionModel", simulated=False, moving=False)
    box.addObject("PointCollisionModel", simulated=False, moving=False)
    box.addObject("MeshOBJLoader", name="meshLoader_0", filename="mesh/box_outside.obj", handleSeams=True)
    box.addObject("OglModel", name="Visual", src="@meshLoader_0", color=[1, 0, 0, 0.3])
