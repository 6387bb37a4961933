"""The skin-suture trainer (issue 16), Python version of skin_suture.scn: the same
graph built with SofaPython3's API (`sinew run skin_suture.py`, or `runSofa`
with SofaPython3 and Sinew's SutureSpringForceField replaced).

A skin pad 30 x 20 x 5 (tetrahedra from skin_pad.msh), a suture needle (front
sphere pierces, back sphere draws the thread) and a scalpel, each driven by a
scripted haptic device (needle.csv, scalpel.csv). See docs/haptics.md.
"""
import os

HERE = os.path.dirname(os.path.abspath(__file__))

PLUGINS = [
    "Geomagic", "SofaCarving", "Sofa.Component.AnimationLoop", "Sofa.Component.Collision.Detection.Algorithm",
    "Sofa.Component.Collision.Detection.Intersection", "Sofa.Component.Collision.Geometry",
    "Sofa.Component.Collision.Response.Contact", "Sofa.Component.Constraint.Lagrangian.Correction",
    "Sofa.Component.Constraint.Lagrangian.Solver", "Sofa.Component.Constraint.Projective",
    "Sofa.Component.Engine.Select", "Sofa.Component.Haptics", "Sofa.Component.IO.Mesh",
    "Sofa.Component.LinearSolver.Iterative", "Sofa.Component.Mapping.NonLinear", "Sofa.Component.Mass",
    "Sofa.Component.ODESolver.Backward", "Sofa.Component.SolidMechanics.FEM.Elastic",
    "Sofa.Component.SolidMechanics.Spring", "Sofa.Component.StateContainer",
    "Sofa.Component.Topology.Container.Dynamic", "Sofa.Component.Topology.Mapping",
]


def add_instrument(root, name, device, tag, start, points):
    """A rigid instrument held to its device's pose by stiff springs (virtual coupling).
    `points`: (child name, local position, sphere radius or None, carving tool?)."""
    proxy = root.addChild(name + "Proxy")
    proxy.addObject("MechanicalObject", name="pose", template="Rigid3d", position="@../%s.positionDevice" % device)
    tool = root.addChild(name)
    tool.addObject("EulerImplicitSolver", rayleighStiffness=0, rayleighMass=0)
    tool.addObject("CGLinearSolver", iterations=25, tolerance=1e-12, threshold=1e-12)
    tool.addObject("MechanicalObject", name="frame", template="Rigid3d", position=start)
    tool.addObject("UniformMass", totalMass=0.01)
    tool.addObject("RestShapeSpringsForceField", stiffness=100, angularStiffness=100,
                   external_rest_shape="@../%sProxy/pose" % name, points=0, external_points=0)
    tool.addObject("LCPForceFeedback", name="haptics", tags=tag, activate=True, forceCoef=0.1)
    tool.addObject("UncoupledConstraintCorrection")
    for child, position, radius, carving in points:
        n = tool.addChild(child)
        n.addObject("MechanicalObject", name="points" if radius is None else "MechanicalObject", template="Vec3d",
                    position=position)
        if radius is not None:
            n.addObject("SphereCollisionModel", name="sphere", radius=radius,
                        **({"tags": "CarvingTool"} if carving else {}))
        n.addObject("RigidMapping")
    return tool


def createScene(root):
    root.dt = 0.01
    root.gravity = [0, 0, -9.81]
    for p in PLUGINS:
        root.addObject("RequiredPlugin", pluginName=p)
    root.addObject("FreeMotionAnimationLoop")
    root.addObject("LCPConstraintSolver", name="lcp", tolerance=0.001, maxIt=1000, mu=0.3)
    root.addObject("CollisionPipeline", name="pipeline", depth=6)
    root.addObject("BruteForceBroadPhase")
    root.addObject("BVHNarrowPhase", name="narrowPhase")
    root.addObject("LocalMinDistance", name="proximity", alarmDistance=0.3, contactDistance=0.1, angleCone=0.0)
    root.addObject("CollisionResponse", name="response", response="FrictionContactConstraint",
                   responseParams="mu=0.3")
    root.addObject("GeomagicDriver", name="needleDevice", tags="needle",
                   trajectory=os.path.join(HERE, "needle.csv"), positionBase=[0, 0, 0], scale=1)
    root.addObject("GeomagicDriver", name="scalpelDevice", tags="scalpel",
                   trajectory=os.path.join(HERE, "scalpel.csv"), positionBase=[0, 0, 0], scale=1)
    root.addObject("CarvingManager", name="needleCarving", active=True, carvingDistance=0.05,
                   toolModel="@Needle/Front/sphere", narrowPhaseDetection="@narrowPhase")
    root.addObject("CarvingManager", name="scalpelCarving", active=True, carvingDistance=0.05,
                   toolModel="@Scalpel/Tip/sphere", narrowPhaseDetection="@narrowPhase")

    skin = root.addChild("Skin")
    skin.addObject("EulerImplicitSolver", rayleighStiffness=0.1, rayleighMass=0.1)
    skin.addObject("CGLinearSolver", iterations=25, tolerance=1e-9, threshold=1e-9)
    skin.addObject("MeshGmshLoader", name="loader", filename=os.path.join(HERE, "skin_pad.msh"))
    skin.addObject("TetrahedronSetTopologyContainer", name="volume", src="@loader")
    # No point removal: the indices of the base, border and thread springs stay valid.
    skin.addObject("TetrahedronSetTopologyModifier", removeIsolated=False)
    skin.addObject("TetrahedronSetGeometryAlgorithms", template="Vec3d")
    skin.addObject("MechanicalObject", name="skin", template="Vec3d", src="@loader")
    skin.addObject("DiagonalMass", totalMass=0.3)
    skin.addObject("TetrahedronFEMForceField", name="fem", youngModulus=300, poissonRatio=0.49, method="large")
    skin.addObject("BoxROI", name="base", box=[-1, -1, -0.1, 31, 21, 0.1])
    skin.addObject("FixedProjectiveConstraint", indices="@base.indices")
    skin.addObject("BoxROI", name="border", box=[-1, -1, 0.1, 0.1, 21, 6, 29.9, -1, 0.1, 31, 21, 6,
                                                 -1, -1, 0.1, 31, 0.1, 6, -1, 19.9, 0.1, 31, 21, 6])
    skin.addObject("RestShapeSpringsForceField", name="borderSprings", points="@border.indices", stiffness=50)
    skin.addObject("SutureSpringForceField", name="suture", needle="@../Needle/Points/points", frontIndex=0,
                   backIndex=1, captureDistance=1.5, stiffness=5)
    skin.addObject("UncoupledConstraintCorrection", compliance=0.001)
    surface = skin.addChild("Surface")
    surface.addObject("TriangleSetTopologyContainer", name="surface")
    surface.addObject("TriangleSetTopologyModifier")
    surface.addObject("TriangleSetGeometryAlgorithms", template="Vec3d")
    surface.addObject("Tetra2TriangleTopologicalMapping", input="@../volume", output="@surface")
    surface.addObject("TriangleCollisionModel", name="triangles", tags="CarvingSurface")
    surface.addObject("PointCollisionModel", name="points", tags="CarvingSurface")

    add_instrument(root, "Needle", "needleDevice", "needle",
                   [8.844952, 10, 7.664699, 0, 0.64278761, 0, 0.76604444],
                   [("Points", [0, 0, 0, -3, 0, 0], None, False), ("Front", [0, 0, 0], 0.3, True),
                    ("Back", [-3, 0, 0], 0.2, False)])
    add_instrument(root, "Scalpel", "scalpelDevice", "scalpel", [5, 4, 7, 0, 0, 0, 1],
                   [("Tip", [0, 0, 0], 0.3, True)])
    return root
