// Force-field battery: every registered force field (masses included: they
// are force fields carrying gravity) is checked on a small scene of its own,
// one line in kCases below, against the properties every force field must
// have (spec/mechanics.md §0, framework.md §6.3). What applies to a component
// is said by the flags of its line:
//
// * add_force = −∇E by central differences of potential_energy() (kEnergy);
// * add_dforce = ∂f/∂x by central differences of add_force along random
//   directions, and linear in kfactor (every case); where SOFA's tangent is
//   exact only at the rest shape, tightly there (kExactAtRest) and within the
//   case's tolerance elsewhere;
// * build_stiffness through MatrixSink = add_dforce on every unit vector
//   (kStiffness, or kStiffnessAtRest);
// * internal forces have no net force (kNetForce) nor net torque (kMomentum),
//   and a rigid motion of the rest shape gives no force (kRigidRest);
// * build_damping = ∂f/∂v by central differences (kDamping).
//
// Each check runs at a deformed state: the rest positions (moved rigidly as
// well for kRigidRest fields, so that corotational frames turn), plus seeded
// random displacements of 5% of the scene size (rotations of 0.05 rad).
// Velocities are zero, so damping forces never enter the position
// derivatives. A new force field joins with one line;
// EveryRegisteredForceFieldHasACase fails until it does.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "components/register_all.h"
#include "conformance.h"
#include "core/registry.h"
#include "test_scene.h"

using namespace sinew;
using namespace sinew::conformance;

namespace {

enum Check : unsigned {
  kEnergy = 1u << 0,       // potential_energy() is provided and add_force = −∇E
  kStiffness = 1u << 1,    // build_stiffness = add_dforce
  kNetForce = 1u << 2,     // Σ f = 0 (internal forces)
  kMomentum = 1u << 3,     // Σ f = 0 and Σ x × f = 0 (internal, rotation-invariant forces)
  kRigidRest = 1u << 4,    // f = 0 at rest and at a rigid motion of the rest shape
  kExactAtRest = 1u << 5,  // add_dforce exact at the rest shape (moved rigidly with kRigidRest); tol elsewhere
  kDamping = 1u << 6,      // build_damping = ∂f/∂v
  kStiffnessAtRest = 1u << 7,  // build_stiffness = add_dforce at the (unmoved) rest shape only
  kFirstStateOnly = 1u << 8,   // derivatives with respect to the first state only (the others held)
};
// Elastic internal forces that do not depend on the orientation (springs, hyperelasticity).
constexpr unsigned kInternal = kStiffness | kMomentum | kRigidRest;
// SOFA's corotational elements: rotation invariant, but their frames (from edges, or the polar part
// of the edge matrix) are not the rotation of the deformation gradient, so the net torque of a
// deformed element is not zero; the tangent freezes the frames (exact at the rest shape only).
constexpr unsigned kCorotational = kStiffness | kNetForce | kRigidRest | kExactAtRest;

struct ForceFieldCase {
  const char* name;   // test name: the class, then the variant
  std::string scene;  // the force field under test is named "ff"
  unsigned checks;
  // Relative tolerance of the finite-difference checks at the deformed state.
  // 1e-6 keeps four orders of magnitude above the finite-difference error
  // (h = 1e-6 × scene size) while any wrong term, factor or sign is ≥ 1e-3.
  // Larger only where SOFA's formula is itself an approximation (said on the line).
  double tol = 1e-6;
  // Size of the random displacements of the deformed state, relative to the scene size
  // (rotations in radians).
  double deform = 0.05;
};
void PrintTo(const ForceFieldCase& c, std::ostream* os) { *os << c.name; }

// ---------------------------------------------------------------- scenes
std::string node(const std::string& body, const char* gravity = "0 0 0") {
  return std::string("<Node name='root' gravity='") + gravity + "'>" + body + "</Node>";
}
// The component under test: <cls name='ff' attrs/>.
std::string ff(const std::string& cls, const std::string& attrs = "") {
  return "<" + cls + " name='ff' " + attrs + "/>";
}
const std::string kElastic = "youngModulus='1000' poissonRatio='0.3' ";
const std::string kSoft = "youngModulus='60' poissonRatio='0.3' ";
const char* kGravity = "1 -9.81 0.5";

// Two tetrahedra sharing the face (1, 2, 3).
std::string tetras(const std::string& body, const char* gravity = "0 0 0") {
  return node("<MeshTopology name='topo' position='0 0 0  1 0 0  0 1 0  0 0 1  0.9 1.1 1.2'"
              " tetrahedra='0 1 2 3  1 2 3 4'/><MechanicalObject name='dofs'/>" + body, gravity);
}
// Two hexahedra (a 3×2×2 regular grid).
std::string hexas(const std::string& body, const char* gravity = "0 0 0") {
  return node("<RegularGridTopology name='grid' n='3 2 2' min='0 0 0' max='2 1 1'/>"
              "<MechanicalObject name='dofs'/>" + body, gravity);
}
// Two hexahedra of a sparse grid over a closed 2×1×1 box, condensed from one virtual finer level.
std::string sparse_hexas(const std::string& body) {
  return node("<SparseGridTopology name='grid' n='3 2 2' nbVirtualFinerLevels='1'"
              " position='0 0 0  2 0 0  2 1 0  0 1 0  0 0 1  2 0 1  2 1 1  0 1 1'"
              " triangles='0 2 1  0 3 2  4 5 6  4 6 7  0 1 5  0 5 4  1 2 6  1 6 5  2 3 7  2 7 6  3 0 4  3 4 7'/>"
              "<MechanicalObject name='dofs'/>" + body);
}
// The same box on a ramified sparse grid (the composite homogenization follows ramifications).
std::string ramified_hexas(const std::string& body) {
  return node("<SparseGridRamificationTopology name='grid' n='3 2 2' nbVirtualFinerLevels='1'"
              " position='0 0 0  2 0 0  2 1 0  0 1 0  0 0 1  2 0 1  2 1 1  0 1 1'"
              " triangles='0 2 1  0 3 2  4 5 6  4 6 7  0 1 5  0 5 4  1 2 6  1 6 5  2 3 7  2 7 6  3 0 4  3 4 7'/>"
              "<MechanicalObject name='dofs'/>" + body);
}
// Two prisms sharing the quad (1, 2, 5, 4), and two pyramids on either side of the square base.
std::string prisms(const std::string& body) {
  return node("<MeshTopology name='topo' position='0 0 0  1 0 0  0 1 0  0 0 1  1 0 1.1  0 1 1  1.2 1.1 0  1.1 1 1'"
              " prisms='0 1 2 3 4 5  1 6 2 4 7 5'/><MechanicalObject name='dofs'/>" + body);
}
std::string pyramids(const std::string& body) {
  return node("<MeshTopology name='topo' position='0 0 0  1 0 0  1 1 0  0 1 0  0.5 0.5 1  0.4 0.6 -1'"
              " pyramids='0 1 2 3 4  3 2 1 0 5'/><MechanicalObject name='dofs'/>" + body);
}
// Two triangles sharing the edge (1, 2) in the z = 0 plane.
std::string triangles(const std::string& body) {
  return node("<MeshTopology name='topo' position='0 0 0  1 0 0  0 1 0  1.1 0.9 0' triangles='0 1 2  1 3 2'/>"
              "<MechanicalObject name='dofs'/>" + body);
}
// Two quads sharing the edge (1, 4) in the z = 0 plane.
std::string quads(const std::string& body) {
  return node("<MeshTopology name='topo' position='0 0 0  1 0 0  2 0 0  0 1 0  1 1 0  2 1 0'"
              " quads='0 1 4 3  1 2 5 4'/><MechanicalObject name='dofs'/>" + body);
}
// Points of type `tmpl` with SpringForceField springs "i j ks kd L0 ...".
std::string springs(const std::string& tmpl, const std::string& position, const std::string& list) {
  return node("<MechanicalObject name='dofs' template='" + tmpl + "' position='" + position + "'/>" +
              ff("SpringForceField", "spring='" + list + "'"));
}
const char* kRoot2 = "1.4142135623730951";
// A unit tetrahedron's corner and edges, every spring at its rest length.
const std::string kUnitSprings =
    std::string("0 1 50 2 1  0 2 30 2 1  0 3 20 2 1  1 2 40 2 ") + kRoot2 + "  2 3 10 2 " + kRoot2;
// The same springs between two states (object1, object2) initialised before the force field.
const std::string kTwoStates =
    node(std::string("<Node name='a'><MechanicalObject name='a' position='0 0 0  1 0 0'/></Node>"
                     "<Node name='b'><MechanicalObject name='b' position='0 1 0  0 0 1'/></Node>"
                     "<Node name='springs'>") +
         ff("SpringForceField", std::string("object1='@../a/a' object2='@../b/b' spring='0 0 50 2 1  1 1 30 2 ") +
                                    kRoot2 + "  0 1 20 2 1  1 0 40 2 " + kRoot2 + "'") +
         "</Node>");
// A frame carrying an ellipsoid (radii 1, 0.8, 0.6, turned 45° about z); three points 1% inside, one outside.
const std::string kEllipsoid = node(
    "<Node name='R'><MechanicalObject name='frame' template='Rigid3d'"
    "   position='0.1 0.2 0.3  0 0 0.38268343236508978 0.92387953251128674'/></Node>"
    "<Node name='P'><MechanicalObject name='pts' position='0.800036 0.900036 0.3  -0.460029 0.760029 0.3"
    "   0.827498 0.280833 0.642946  1.16066 1.26066 0.3'/>" +
    ff("InteractionEllipsoidForceField", "template='Vec3d,Rigid3d' object1='@pts' object2='@../R/frame' "
                                         "stiffness='100' damping='0' center='0 0 0' vradius='1 0.8 0.6' "
                                         "object2_forces='false'") +
    "</Node>");
// A beam of three Rigid3d frames along x.
std::string beam(const std::string& body) {
  return node("<MeshTopology name='lines' edges='0 1  1 2'/><MechanicalObject name='dofs' template='Rigid3d'"
              " position='0 0 0 0 0 0 1  1 0 0 0 0 0 1  2 0 0 0 0 0 1'/>" + body);
}
std::string hyper(const std::string& material, const std::string& parameters) {
  return tetras(ff("TetrahedronHyperelasticityFEMForceField",
                   "materialName='" + material + "' ParameterSet='" + parameters + "'"));
}
std::string standard(const std::string& material, const std::string& parameters) {
  return tetras(ff("StandardTetrahedralFEMForceField",
                   "materialName='" + material + "' ParameterSet='" + parameters + "'"));
}

// ---------------------------------------------------------------- cases: one line per component (variant)
const std::vector<ForceFieldCase> kCases = {
    // Springs
    {"SpringForceField", springs("Vec3d", "0 0 0  1 0 0  0 1 0  0 0 1", kUnitSprings), kEnergy | kInternal},
    {"SpringForceField_Vec2d",
     springs("Vec2d", "0 0  1 0  0 1  1.2 1.3", "0 1 50 2 1  0 2 30 2 1.2  1 2 40 2 1.4  2 3 10 2 1.1"),
     kEnergy | kStiffness | kMomentum},
    {"SpringForceField_Vec1d", springs("Vec1d", "0  1  2.5", "0 1 50 2 0.8  1 2 30 2 1.7"),
     kEnergy | kStiffness | kNetForce},
    {"SpringForceField_TwoStates", kTwoStates, kEnergy | kInternal},
    // Rest *vectors*: not rotation invariant (no momentum or rigid-rest checks); no damping matrix, as SOFA.
    {"VectorSpringForceField", tetras(ff("VectorSpringForceField", "useTopology='1' stiffness='30' viscosity='2'")),
     kEnergy | kStiffness | kNetForce},
    {"MeshSpringForceField", tetras(ff("MeshSpringForceField", "stiffness='300' damping='2'")), kEnergy | kInternal},
    {"RegularGridSpringForceField", hexas(ff("RegularGridSpringForceField", "stiffness='300' damping='2'")),
     kEnergy | kInternal},
    {"QuadBendingSprings", quads(ff("QuadBendingSprings", "stiffness='300' damping='2'")), kEnergy | kInternal},
    {"QuadularBendingSprings", quads(ff("QuadularBendingSprings", "stiffness='300' damping='2'")), kInternal},
    {"TriangularBendingSprings", triangles(ff("TriangularBendingSprings", "stiffness='300' damping='2'")),
     kEnergy | kInternal},
    {"TriangleBendingSprings", triangles(ff("TriangleBendingSprings", "stiffness='300' damping='2'")),
     kEnergy | kInternal},
    {"TriangleBendingSprings_Quads", quads(ff("TriangleBendingSprings", "stiffness='300' damping='2'")),
     kEnergy | kInternal},
    {"TriangularBiquadraticSpringsForceField",
     triangles(ff("TriangularBiquadraticSpringsForceField", kSoft + "compressible='0'")), kEnergy | kInternal},
    // The compression term's tangent is SOFA's regularised blend (exact only as J → 1): compressed
    // triangles of the deformed state are off by a few percent of that term. (useAngularSprings='0'
    // has no line: SOFA's tangent then lacks the edge-direction term, see the unit test.)
    {"TriangularBiquadraticSpringsForceField_Compressible",
     triangles(ff("TriangularBiquadraticSpringsForceField", kSoft)), kEnergy | kInternal, 0.1},
    {"TriangularQuadraticSpringsForceField",
     triangles(ff("TriangularQuadraticSpringsForceField", kSoft + "useAngularSprings='0'")), kEnergy | kInternal},
    // With angular springs SOFA's tangent takes (c − s·l₀)/l³ for the edge-direction coefficient where
    // the derivative has (c − s·l)/l³: exact at the rest shape, off by the strain elsewhere.
    {"TriangularQuadraticSpringsForceField_Angular",
     triangles(ff("TriangularQuadraticSpringsForceField", kSoft)), kEnergy | kInternal | kExactAtRest, 0.2},
    // Linear in the displacement from the rest shape (not rotation invariant), symmetric tangent.
    {"TriangularTensorMassForceField", triangles(ff("TriangularTensorMassForceField", kSoft)),
     kEnergy | kStiffness | kNetForce},
    {"TetrahedralTensorMassForceField", tetras(ff("TetrahedralTensorMassForceField", kSoft)),
     kEnergy | kStiffness | kNetForce},
    // Given rest lengths shorter than every spring: all stretched, where SOFA's tangent is exact
    // (compressed springs keep the stretched tangent, see polynomial_springs_test.cpp).
    {"PolynomialSpringsForceField",
     node("<MechanicalObject name='dofs' position='0 0 0  1 0 0  0 1 0  0 0 1'/>" +
          ff("PolynomialSpringsForceField", "firstObjectPoints='0 1' secondObjectPoints='2 3' polynomialDegree='2 1' "
                                            "polynomialStiffness='20 50 30' computeZeroLength='0' zeroLength='0.5'")),
     kStiffness | kMomentum},
    // A Vec1 field diffusing on two tetrahedra whose geometry is the tagged Vec3d state above it.
    {"TetrahedronDiffusionFEMForceField",
     node("<MeshTopology name='topo' position='0 0 0  1 0 0  0 1 0  0 0 1  0.9 1.1 1.2' tetrahedra='0 1 2 3  1 2 3 4'/>"
          "<MechanicalObject name='geo' tags='meca'/><Node name='heat'>"
          "<MechanicalObject name='dofs' template='Vec1d' position='0.1 0.7 0.3 0.9 0.4'/>" +
          ff("TetrahedronDiffusionFEMForceField", "template='Vec1d' topology='@../topo' constantDiffusionCoefficient='5'") +
          "</Node>"),
     kStiffness | kNetForce},
    {"FastTriangularBendingSprings", triangles(ff("FastTriangularBendingSprings", "bendingStiffness='10'")),
     kEnergy | kInternal},
    // Threads to a needle's back point (0.5 0.5 2), held: two stretched, one slack (no force, no stiffness).
    {"SutureSpringForceField",
     node("<MechanicalObject name='dofs' position='0 0 0  1 0 0  0 1 0  0 0 1'/>"
          "<Node name='n'><MechanicalObject name='needle' position='5 5 5  0.5 0.5 2'/></Node>" +
          ff("SutureSpringForceField", "needle='@n/needle' stiffness='40' springs='0 0.5  2 1  3 3'")),
     kEnergy | kStiffness},
    {"RestShapeSpringsForceField", tetras(ff("RestShapeSpringsForceField", "stiffness='100 200 300 400 500'")),
     kEnergy | kStiffness},
    {"RestShapeSpringsForceField_Vec2d",
     node("<MechanicalObject name='dofs' template='Vec2d' position='0 0  1 0  0 1'/>" +
          ff("RestShapeSpringsForceField", "points='0 2' stiffness='70' activeDirections='1 0'")),
     kEnergy | kStiffness},
    // Three frames, a clamped joint (0-1) and one with two free rotations (1-2, general case);
    // REST_T: rest offsets from the initial positions. SOFA's tangent is the per-axis stiffness
    // of the last force (no frame-rotation or rotation-vector Jacobian terms): exact at rest,
    // first order in the deformation elsewhere. The rest offset is a world vector (no kRigidRest)
    // and the centres carry no lever arm (no kMomentum); SOFA reports no energy (no kEnergy).
    {"JointSpringForceField",
     node("<MechanicalObject name='dofs' template='Rigid3d'"
          " position='0 0 0 0 0 0 1  1 0.2 0 0 0 0 1  1.8 0.9 0.3 0 0 0 1'/>" +
          ff("JointSpringForceField", "template='Rigid3d' spring='"
             "BEGIN_SPRING 0 1 FREE_AXIS 0 0 0 0 0 0 KS_T 0 900 KS_R 0 300 REST_T 0 0 0 END_SPRING "
             "BEGIN_SPRING 1 2 FREE_AXIS 0 1 0 1 0 1 KS_T 40 700 KS_R 60 500 REST_T 0 0 0 END_SPRING'")),
     kStiffness | kNetForce | kExactAtRest, 0.05, 1e-3},
    // Loads
    {"ConstantForceField", tetras(ff("ConstantForceField", "indices='1 3 4' forces='1 2 3  -4 0 1  0.5 0.5 -2'")),
     kEnergy | kStiffness},
    {"PlaneForceField", tetras(ff("PlaneForceField", "normal='0 0.6 0.8' d='0.45' stiffness='700' damping='3'")),
     kEnergy | kStiffness},
    {"PlaneForceField_Rigid3d", beam(ff("PlaneForceField", "template='Rigid3d' normal='0 0.6 0.8' d='0.45' stiffness='700'")),
     kEnergy | kStiffness},
    {"SphereForceField", tetras(ff("SphereForceField", "center='0.5 0.5 0.5' radius='1.2' stiffness='700' damping='3'")),
     kEnergy | kStiffness},
    {"SphereForceField_Bilateral",
     tetras(ff("SphereForceField", "center='0.5 0.5 0.5' radius='0.6' stiffness='700' bilateral='1'")),
     kEnergy | kStiffness},
    // SOFA's tangent misses a term proportional to the penetration (ellipsoid_penalty.h): points
    // 1% inside the ellipsoid, deformed by 0.1% only (as InteractionEllipsoidForceField).
    {"EllipsoidForceField",
     node("<MechanicalObject name='dofs' position='0.99 0 0  0 0.792 0  0 0 0.594  0.61845 0.61845 0'/>" +
          ff("EllipsoidForceField", "center='0 0 0' vradius='1 0.8 0.6' stiffness='100' damping='0'")),
     kStiffness, 0.05, 1e-3},
    // Points 1% beyond the cone's base sphere: SOFA's tangent −k·n·nᵀ drops the curvature term
    // k·d/ρ·(I − n·nᵀ), of the order of the penetration.
    {"ConicalForceField",
     node("<MechanicalObject name='dofs' position='0 0 1.01  0.1 0 1.005  0 0.2 0.9898  -0.15 0.1 0.9938'/>" +
          ff("ConicalForceField", "coneCenter='0 0 0' coneHeight='0 0 1' coneAngle='40' stiffness='300' damping='0'")),
     kStiffness, 0.05, 1e-3},
    {"LinearForceField",
     tetras(ff("LinearForceField", "points='1 3' times='0 2' forces='1 2 3  3 2 1' force='2'")), kEnergy | kStiffness},
    {"LinearForceField_Rigid3d", beam(ff("LinearForceField", "template='Rigid3d' points='0 2' times='0 1' "
                                                             "forces='1 0 0 0 0 1  0 2 0 1 0 0'")),
     kStiffness},
    {"DiagonalVelocityDampingForceField",
     tetras(ff("DiagonalVelocityDampingForceField", "dampingCoefficient='0.5 0.2 0.1  1 2 3'")),
     kEnergy | kStiffness | kDamping},
    {"DiagonalVelocityDampingForceField_Rigid3d",
     beam(ff("DiagonalVelocityDampingForceField", "template='Rigid3d' dampingCoefficient='1 2 3 4 5 6'")),
     kEnergy | kStiffness | kDamping},
    {"QuadPressureForceField", quads(ff("QuadPressureForceField", "quadList='0 1' pressure='0.3 0 -6'")), kStiffness},
    {"SurfacePressureForceField", triangles(ff("SurfacePressureForceField", "pressure='40'")), kStiffness},
    // Pressure mode only: the binormal/p_intensity modes follow the edge directions with no
    // tangent in SOFA (addDForce adds nothing), so they would fail the tangent check by design
    // (tests/forcefield/edge_pressure_force_field_test.cpp covers them).
    {"EdgePressureForceField",
     node("<MeshTopology name='topo' position='0 0 0  2 0 0  2 1 0' edges='0 1  1 2'/><MechanicalObject name='dofs'/>" +
          ff("EdgePressureForceField", "edges='0 1  1 2' pressure='0 0 1'")),
     kStiffness},
    // A closed tetrahedral surface: no pressure at rest (internal), then a constant p0 on top.
    {"TaitSurfacePressureForceField",
     node("<MechanicalObject position='0 0 0  1 0 0  0 1 0  0 0 1'/>"
          "<MeshTopology triangles='0 2 1  0 1 3  0 3 2  1 2 3'/>" +
          ff("TaitSurfacePressureForceField", "B='10' gamma='5'")),
     kInternal},
    {"TaitSurfacePressureForceField_p0",
     node("<MechanicalObject position='0 0 0  1 0 0  0 1 0  0 0 1'/>"
          "<MeshTopology triangles='0 2 1  0 1 3  0 3 2  1 2 3'/>" +
          ff("TaitSurfacePressureForceField", "p0='2' B='10' gamma='1'")),
     kStiffness | kMomentum},
    {"TrianglePressureForceField",
     triangles(ff("TrianglePressureForceField", "triangleList='0 1' pressure='0.3 0 -6'")), kStiffness},
    // SOFA's tangent ignores the frame (object2) and misses a term proportional to the penetration
    // (spring_force_fields_test.cpp): points 1% inside the ellipsoid, deformed by 0.1% only.
    {"InteractionEllipsoidForceField", kEllipsoid, kStiffness | kFirstStateOnly, 0.05, 1e-3},
    {"UniformVelocityDampingForceField",
     tetras(ff("UniformVelocityDampingForceField", "dampingCoefficient='0.7' implicit='true'")), kStiffness | kDamping},
    // Linear elasticity: not rotation invariant, only the net force vanishes.
    {"TetrahedronFEMForceField_small", tetras(ff("TetrahedronFEMForceField", kElastic + "method='small'")),
     kEnergy | kStiffness | kNetForce},
    {"TetrahedralCorotationalFEMForceField_small",
     tetras(ff("TetrahedralCorotationalFEMForceField", kElastic + "method='small'")), kStiffness | kNetForce},
    {"HexahedronFEMForceField_small", hexas(ff("HexahedronFEMForceField", kElastic + "method='small'")),
     kEnergy | kStiffness | kNetForce},
    {"LinearSmallStrainFEMForceField_Tetrahedron", tetras(ff("LinearSmallStrainFEMForceField", kElastic)),
     kEnergy | kStiffness | kNetForce},
    {"LinearSmallStrainFEMForceField_Hexahedron",
     hexas(ff("LinearSmallStrainFEMForceField", kElastic + "template='Vec3d,Hexahedron'")),
     kEnergy | kStiffness | kNetForce},
    {"LinearSmallStrainFEMForceField_Prism", prisms(ff("LinearSmallStrainFEMForceField", kElastic + "template='Vec3d,Prism'")),
     kEnergy | kStiffness | kNetForce},
    {"LinearSmallStrainFEMForceField_Pyramid",
     pyramids(ff("LinearSmallStrainFEMForceField", kElastic + "template='Vec3d,Pyramid'")),
     kEnergy | kStiffness | kNetForce},
    // Small displacements with K sized from the current shape, as SOFA: exact tangent at rest only.
    {"TriangularFEMForceField_small", triangles(ff("TriangularFEMForceField", kSoft + "method='small'")),
     kStiffness | kNetForce | kExactAtRest, 0.2},
    {"TriangleFEMForceField_small", triangles(ff("TriangleFEMForceField", kSoft + "method='small'")),
     kStiffness | kNetForce | kExactAtRest, 0.2},
    {"QuadBendingFEMForceField",
     quads(ff("QuadBendingFEMForceField", "youngModulus='2000' poissonRatio='0.3' thickness='0.1'")),
     kStiffness | kNetForce | kExactAtRest, 0.3},
    // Corotational elasticity (tolerance: SOFA's frozen frames, first order in the 5% deformation).
    {"TetrahedronFEMForceField_large", tetras(ff("TetrahedronFEMForceField", kElastic + "method='large'")),
     kCorotational, 0.2},
    {"TetrahedronFEMForceField_polar", tetras(ff("TetrahedronFEMForceField", kElastic + "method='polar'")),
     kCorotational, 0.2},
    {"TetrahedronFEMForceField_svd", tetras(ff("TetrahedronFEMForceField", kElastic + "method='svd'")),
     kCorotational, 0.2},
    {"TetrahedralCorotationalFEMForceField_large",
     tetras(ff("TetrahedralCorotationalFEMForceField", kElastic + "method='large'")), kCorotational, 0.2},
    {"TetrahedralCorotationalFEMForceField_polar",
     tetras(ff("TetrahedralCorotationalFEMForceField", kElastic + "method='polar'")), kCorotational, 0.2},
    {"FastTetrahedralCorotationalForceField_linear",
     tetras(ff("FastTetrahedralCorotationalForceField", kElastic + "method='linear'")), kStiffness | kNetForce},
    {"FastTetrahedralCorotationalForceField_qr",
     tetras(ff("FastTetrahedralCorotationalForceField", kElastic + "method='qr'")), kCorotational, 0.2},
    {"FastTetrahedralCorotationalForceField_polar",
     tetras(ff("FastTetrahedralCorotationalForceField", kElastic + "method='polar'")), kCorotational, 0.2},
    {"FastTetrahedralCorotationalForceField_polar2",
     tetras(ff("FastTetrahedralCorotationalForceField", kElastic + "method='polar2'")), kCorotational, 0.2},
    {"CorotationalFEMForceField_Tetrahedron", tetras(ff("CorotationalFEMForceField", kElastic)), kCorotational, 0.2},
    {"CorotationalFEMForceField_Hexahedron",
     hexas(ff("CorotationalFEMForceField", kElastic + "template='Vec3d,Hexahedron'")), kCorotational, 0.2},
    {"CorotationalFEMForceField_Hexahedron_stable_polar",
     hexas(ff("CorotationalFEMForceField", kElastic + "template='Vec3d,Hexahedron' rotationMethod='stable_polar'")),
     kCorotational, 0.2},
    {"CorotationalFEMForceField_Prism", prisms(ff("CorotationalFEMForceField", kElastic + "template='Vec3d,Prism'")),
     kCorotational, 0.2},
    {"CorotationalFEMForceField_Pyramid",
     pyramids(ff("CorotationalFEMForceField", kElastic + "template='Vec3d,Pyramid'")), kCorotational, 0.2},
    {"HexahedronFEMForceField_large", hexas(ff("HexahedronFEMForceField", kElastic + "method='large'")),
     kEnergy | kCorotational, 0.2},
    {"HexahedronFEMForceField_polar", hexas(ff("HexahedronFEMForceField", kElastic + "method='polar'")),
     kEnergy | kCorotational, 0.2},
    {"ParallelHexahedronFEMForceField", hexas(ff("ParallelHexahedronFEMForceField", kElastic + "method='large'")),
     kEnergy | kCorotational, 0.2},
    {"HexahedronFEMForceFieldAndMass", hexas(ff("HexahedronFEMForceFieldAndMass", kElastic + "density='2'")),
     kCorotational, 0.2},
    {"NonUniformHexahedronFEMForceFieldAndMass",
     sparse_hexas(ff("NonUniformHexahedronFEMForceFieldAndMass", kElastic + "density='2' nbVirtualFinerLevels='1'")),
     kCorotational, 0.2},
    {"HexahedronCompositeFEMForceFieldAndMass",
     ramified_hexas(ff("HexahedronCompositeFEMForceFieldAndMass", kElastic + "density='2' nbVirtualFinerLevels='1'")),
     kCorotational, 0.2},
    // SOFA assembles R·K·Rᵀ with frames other than add_dforce's once they turn (hexahedral_fem_test.cpp).
    {"HexahedralFEMForceField_large", hexas(ff("HexahedralFEMForceField", kElastic + "method='large'")),
     (kCorotational & ~kStiffness) | kStiffnessAtRest, 0.2},
    {"HexahedralFEMForceFieldAndMass",
     hexas(ff("HexahedralFEMForceFieldAndMass", kElastic + "method='large' density='2'")),
     (kCorotational & ~kStiffness) | kStiffnessAtRest, 0.2},
    {"HexahedralFEMForceField_polar", hexas(ff("HexahedralFEMForceField", kElastic + "method='polar'")),
     (kCorotational & ~kStiffness) | kStiffnessAtRest, 0.2},
    // J rebuilt from the current shape, not differentiated (as SOFA).
    {"TriangularFEMForceField_large", triangles(ff("TriangularFEMForceField", kSoft + "method='large'")),
     kCorotational, 0.3},
    {"TriangleFEMForceField_large", triangles(ff("TriangleFEMForceField", kSoft + "method='large'")),
     kCorotational, 0.3},
    {"TriangleFEMForceField_planeStrain",
     triangles(ff("TriangleFEMForceField", kSoft + "thickness='0.2' planeStrain='true'")), kCorotational, 0.3},
    {"TriangularFEMForceFieldOptim", triangles(ff("TriangularFEMForceFieldOptim", kSoft)), kCorotational, 0.2},
    {"BeamFEMForceField", beam(ff("BeamFEMForceField", "youngModulus='20000' poissonRatio='0.3' radius='0.1'")),
     kCorotational, 0.2},
    // Hyperelasticity: exact tangents, energy Σ V0·W.
    {"TetrahedronHyperelasticityFEMForceField_ArrudaBoyce", hyper("ArrudaBoyce", "3448 31034"), kEnergy | kInternal},
    {"TetrahedronHyperelasticityFEMForceField_StVenantKirchhoff", hyper("StVenantKirchhoff", "3448 31034"),
     kEnergy | kInternal},
    {"TetrahedronHyperelasticityFEMForceField_NeoHookean", hyper("NeoHookean", "3448 31034"), kEnergy | kInternal},
    {"TetrahedronHyperelasticityFEMForceField_MooneyRivlin", hyper("MooneyRivlin", "5000 7000 10"),
     kEnergy | kInternal},
    {"TetrahedronHyperelasticityFEMForceField_Ogden", hyper("Ogden", "1500 5 5000"), kEnergy | kInternal},
    {"TetrahedronHyperelasticityFEMForceField_VerondaWestman", hyper("VerondaWestman", "1000 5 20000"),
     kEnergy | kInternal},
    // k0 = 1: SOFA's Costa tangent omits k0 (hyperelastic_test.cpp, CostaTangentMissesK0AsSofa).
    {"TetrahedronHyperelasticityFEMForceField_Costa", hyper("Costa", "1000 1 10 5 8 4 3 6"), kEnergy | kInternal},
    {"TetrahedronHyperelasticityFEMForceField_StableNeoHookean", hyper("StableNeoHookean", "3448 31034"),
     kEnergy | kInternal},
    // The same elements through the strain-displacement matrices and the 6×6 elasticity tensor.
    {"StandardTetrahedralFEMForceField_ArrudaBoyce", standard("ArrudaBoyce", "3448 31034"), kEnergy | kInternal},
    {"StandardTetrahedralFEMForceField_StVenantKirchhoff", standard("StVenantKirchhoff", "3448 31034"),
     kEnergy | kInternal},
    {"StandardTetrahedralFEMForceField_NeoHookean", standard("NeoHookean", "3448 31034"), kEnergy | kInternal},
    {"StandardTetrahedralFEMForceField_MooneyRivlin", standard("MooneyRivlin", "5000 7000 10"), kEnergy | kInternal},
    {"StandardTetrahedralFEMForceField_Ogden", standard("Ogden", "1500 5 5000"), kEnergy | kInternal},
    // Masses: gravity as a force, E = −Σ m g·x where SOFA defines it.
    {"UniformMass", tetras(ff("UniformMass", "totalMass='2.5'"), kGravity), kEnergy | kStiffness},
    {"UniformMass_Rigid3d",
     node("<MechanicalObject name='dofs' template='Rigid3d' position='0 0 0 0 0 0 1  1 2 0 0 0 0.6 0.8'/>" +
          ff("UniformMass", "vertexMass='2 1 1 0 0 0 2 0 0 0 3'"), kGravity),
     kEnergy | kStiffness},
    {"DiagonalMass", tetras(ff("DiagonalMass", "massDensity='3'"), kGravity), kEnergy | kStiffness},
    {"DiagonalMass_Rigid3d",
     node("<MechanicalObject name='dofs' template='Rigid3d' position='0 0 0 0 0 0 1  1 2 0 0 0 0.6 0.8'/>" +
          ff("DiagonalMass", "template='Rigid3d,Rigid3d' vertexMass='2 1 [1 0.1 0,0.1 2 0,0 0 3] 0.5 1 1 0 0 0 1 0 0 0 4'"),
          kGravity),
     kEnergy | kStiffness},
    {"MeshMatrixMass", tetras(ff("MeshMatrixMass", "massDensity='3'"), kGravity), kStiffness},
    {"FEMMass_Tetrahedron", tetras("<NodalMassDensity property='3'/>" + ff("FEMMass"), kGravity), kEnergy | kStiffness},
    {"FEMMass_Hexahedron",
     hexas("<NodalMassDensity property='3'/>" + ff("FEMMass", "template='Vec3d,Hexahedron'"), kGravity),
     kEnergy | kStiffness},
};

// Registered force fields without a case, and why. None: the viewer-only components are no force
// fields, and every force field runs in batch mode.
const std::map<std::string, std::string> kExcluded = {
    // SOFA's SPH forces are explicit: addDForce adds nothing (its derivative list is never filled).
    {"SPHFluidForceField", "explicit by design in SOFA: no tangent (tests/sph/ checks the force itself)"},
    // SOFA's tangent keeps only ks·(n·dx)·n/|d|² (no geometric term, no damping term).
    {"ParticlesRepulsionForceField", "SOFA's simplified tangent is not ∂f/∂x by design"},
    // SOFA's tangent is diagonal (off-diagonal terms left out) and uses the smoothed length.
    {"PolynomialRestShapeSpringsForceField", "SOFA's diagonal tangent is not ∂f/∂x by design"},
    // SOFA's tangent is −k on the rotational diagonal of every listed frame (the first included):
    // the previous frame's term is left out. tests/forcefield/angular_spring_force_field_test.cpp
    // checks the torques, the tangent and its matrix.
    {"AngularSpringForceField", "SOFA's diagonal tangent is not ∂f/∂x by design"},
    // The gear angle (a mean of angles between axes) has no derivative across the gear axis, and SOFA's
    // coupling tangent ignores the pivots: tests/forcefield/gear_spring_test.cpp checks the tangent in
    // the directions where it is exact and the assembled matrix against add_dforce.
    {"GearSpringForceField", "SOFA's gear tangent is ∂f/∂x only along the gear axes, by design"},
};

std::vector<ForceFieldCase> cases_with(unsigned checks) {
  std::vector<ForceFieldCase> out;
  for (const auto& c : kCases)
    if ((c.checks & checks) != 0) out.push_back(c);
  return out;
}
std::string case_name(const ::testing::TestParamInfo<ForceFieldCase>& info) { return info.param.name; }

ForceField* find_force_field(Node& root, std::string_view name) {
  std::vector<ForceField*> all;
  root.collect_down(all);
  for (ForceField* f : all)
    if (f->name.value() == name) return f;
  return nullptr;
}

// ---------------------------------------------------------------- fixture
class ForceFieldBattery : public ::testing::TestWithParam<ForceFieldCase> {
 protected:
  void SetUp() override {
    scene_ = test::load(GetParam().scene);
    ASSERT_TRUE(scene_.root) << "the scene does not load";
    ff_ = find_force_field(*scene_.root, "ff");
    ASSERT_NE(ff_, nullptr) << "the scene has no force field named 'ff'";
    ASSERT_EQ(ff_->state(), ComponentState::valid) << ff_->class_name() << " is not valid after init";
    set_ = StateSet(ff_->states());
    ASSERT_GT(set_.size(), 0u);
    rest_ = set_.coords();
    length_ = set_.length_scale();
    set_.fill(kVelocity, 0.0);
  }

  bool has(unsigned check) const { return (GetParam().checks & check) != 0; }
  // A random direction of derivatives (zero on the held states with kFirstStateOnly).
  std::vector<double> direction(unsigned seed) const {
    std::vector<double> u = set_.random_direction(seed, length_);
    if (has(kFirstStateOnly) && set_.states().size() > 1)
      std::fill(u.begin() + static_cast<long>(set_.offset(1)), u.end(), 0.0);
    return u;
  }

  // The rest shape, moved rigidly for rotation-invariant fields (kRigidRest).
  StateSet::Coords rest_frame() const {
    return has(kRigidRest) && set_.all_spatial() ? set_.rigid_motion(rest_, length_) : rest_;
  }
  // rest_frame() plus random displacements (5% of the scene size and 0.05 rad by default).
  StateSet::Coords deformed(unsigned seed = 1) const {
    set_.move(rest_frame(), set_.random_direction(seed, length_), GetParam().deform);
    return set_.coords();
  }

  std::vector<double> force_at(const StateSet::Coords& x) const {
    set_.set_coords(x);
    set_.fill(kForce, 0.0);
    ff_->add_force(MechParams{});
    return set_.get(kForce);
  }
  double energy_at(const StateSet::Coords& x) const {
    force_at(x);
    return ff_->potential_energy().value_or(std::nan(""));
  }
  // kfactor · K · dx at the positions of the last add_force.
  std::vector<double> dforce(const std::vector<double>& dx, double kfactor = 1.0) const {
    set_.set(kDx, dx);
    set_.fill(kDforce, 0.0);
    MechParams p;
    p.k = kfactor;
    ff_->add_dforce(p, kfactor);
    return set_.get(kDforce);
  }
  // (f(x ⊕ h·u) − f(x ⊖ h·u)) / 2h; leaves add_force evaluated at x.
  std::vector<double> fd_force(const StateSet::Coords& x, const std::vector<double>& u) const {
    set_.move(x, u, h_);
    const auto fp = force_at(set_.coords());
    set_.move(x, u, -h_);
    const auto fm = force_at(set_.coords());
    force_at(x);
    std::vector<double> d(fp.size());
    for (std::size_t i = 0; i < d.size(); ++i) d[i] = (fp[i] - fm[i]) / (2 * h_);
    return d;
  }
  // add_dforce against central differences of add_force along random directions at x.
  void expect_tangent(const StateSet::Coords& x, double tol, const std::string& where) const {
    for (unsigned seed : {2u, 3u}) {
      const auto u = direction(seed);
      force_at(x);
      const auto df = dforce(u);
      EXPECT_TRUE(near_rel(df, fd_force(x, u), tol, "add_dforce", "central differences of add_force", &set_))
          << where << ", direction seed " << seed;
    }
  }

  scene::LoadedScene scene_;
  ForceField* ff_ = nullptr;
  StateSet set_;
  StateSet::Coords rest_;
  double length_ = 1, h_ = 1e-6;
};

}  // namespace

// ---------------------------------------------------------------- add_force = −∇E
class ForceFieldEnergy : public ForceFieldBattery {};
TEST_P(ForceFieldEnergy, ForceIsMinusTheEnergyGradient) {
  const auto x = deformed();
  const auto f = force_at(x);
  ASSERT_TRUE(ff_->potential_energy().has_value()) << "the case says kEnergy but potential_energy() is not provided";
  std::vector<double> grad(set_.size());
  for (std::size_t i = 0; i < grad.size(); ++i) {
    std::vector<double> e(set_.size(), 0.0);
    e[i] = set_.is_rotation(i) ? 1.0 : length_;
    set_.move(x, e, h_);
    const double ep = energy_at(set_.coords());
    set_.move(x, e, -h_);
    const double em = energy_at(set_.coords());
    grad[i] = -(ep - em) / (2 * h_ * e[i]);
  }
  EXPECT_TRUE(near_rel(f, grad, GetParam().tol, "add_force", "−(central differences of potential_energy)", &set_));
}
INSTANTIATE_TEST_SUITE_P(Battery, ForceFieldEnergy, ::testing::ValuesIn(cases_with(kEnergy)), case_name);

// ---------------------------------------------------------------- add_dforce = ∂f/∂x
class ForceFieldTangent : public ForceFieldBattery {};
TEST_P(ForceFieldTangent, DforceMatchesFiniteDifferencesOfAddForce) {
  const auto x = deformed();
  expect_tangent(x, GetParam().tol, "at the deformed state");
  // Linear in kfactor.
  const auto u = direction(4);
  force_at(x);
  const auto df = dforce(u);
  auto scaled = dforce(u, -0.7);
  for (double& v : scaled) v /= -0.7;
  EXPECT_TRUE(near_rel(scaled, df, 1e-12, "add_dforce(kfactor = −0.7) / −0.7", "add_dforce(kfactor = 1)", &set_));
}
INSTANTIATE_TEST_SUITE_P(Battery, ForceFieldTangent, ::testing::ValuesIn(kCases), case_name);

class ForceFieldTangentAtRest : public ForceFieldBattery {};
TEST_P(ForceFieldTangentAtRest, DforceIsExactAtTheRestShape) {
  expect_tangent(rest_frame(), 1e-6, has(kRigidRest) ? "at a rigid motion of the rest shape" : "at the rest shape");
}
INSTANTIATE_TEST_SUITE_P(Battery, ForceFieldTangentAtRest, ::testing::ValuesIn(cases_with(kExactAtRest)), case_name);

// ---------------------------------------------------------------- build_stiffness = add_dforce
class ForceFieldStiffness : public ForceFieldBattery {};
TEST_P(ForceFieldStiffness, AssembledStiffnessMatchesDforce) {
  force_at(has(kStiffnessAtRest) ? rest_ : deformed());
  MatrixSink sink;
  ASSERT_TRUE(ff_->build_stiffness(sink)) << "build_stiffness returned false (cannot assemble)";
  const std::size_t n = set_.size();
  std::vector<double> K(n * n, 0.0), Kdf(n * n, 0.0);
  for (const MatrixSink::Entry& e : sink.entries()) {
    const int r = set_.index_of(e.row_state), c = set_.index_of(e.col_state);
    ASSERT_TRUE(r >= 0 && c >= 0) << "an entry refers to a state the force field does not act on";
    const std::size_t gr = set_.offset(r) + e.row, gc = set_.offset(c) + e.col;
    ASSERT_TRUE(gr < n && gc < n) << "entry (" << e.row << ", " << e.col << ") out of range";
    K[gr * n + gc] += e.value;
  }
  // Column j of K against add_dforce(e_j), all at once (row-major both).
  for (std::size_t j = 0; j < n; ++j) {
    std::vector<double> ej(n, 0.0);
    ej[j] = 1.0;
    const auto col = dforce(ej);
    for (std::size_t i = 0; i < n; ++i) Kdf[i * n + j] = col[i];
  }
  const auto r = near_rel(K, Kdf, 1e-10, "build_stiffness", "add_dforce on unit vectors");
  if (!r) {
    std::size_t worst = 0;
    for (std::size_t k = 0; k < K.size(); ++k)
      if (std::fabs(K[k] - Kdf[k]) > std::fabs(K[worst] - Kdf[worst])) worst = k;
    ADD_FAILURE() << r.message() << "\n  entry (row " << set_.describe(worst / n) << ", column "
                  << set_.describe(worst % n) << ")";
  }
}
INSTANTIATE_TEST_SUITE_P(Battery, ForceFieldStiffness, ::testing::ValuesIn(cases_with(kStiffness | kStiffnessAtRest)),
                         case_name);

// ---------------------------------------------------------------- internal forces
// Relative tolerance of the balance checks: SOFA rounds some element matrices to
// float (HexahedralFEMForceField), far below any missing or wrong force.
constexpr double kBalanceTol = 1e-6;

class ForceFieldBalance : public ForceFieldBattery {};
TEST_P(ForceFieldBalance, NoNetForceNorTorque) {
  const auto x = deformed();
  const auto f = force_at(x);
  const Wrench w = net_wrench(set_, x, f);
  ASSERT_GT(w.force_scale, 0.0) << "no force at the deformed state: the check would be empty";
  EXPECT_LE(w.force.norm(), kBalanceTol * w.force_scale)
      << "net force (" << w.force.transpose() << ") of internal forces summing to " << w.force_scale << " in magnitude";
  if (has(kMomentum)) {
    EXPECT_LE(w.torque.norm(), kBalanceTol * w.torque_scale)
        << "net torque (" << w.torque.transpose() << ") about the origin; Σ|x||f| = " << w.torque_scale;
  }
}
INSTANTIATE_TEST_SUITE_P(Battery, ForceFieldBalance, ::testing::ValuesIn(cases_with(kNetForce | kMomentum)), case_name);

class ForceFieldRigidMotion : public ForceFieldBattery {};
TEST_P(ForceFieldRigidMotion, RestShapeMovedRigidlyHasNoForce) {
  ASSERT_TRUE(set_.all_spatial());
  const double scale = max_abs(force_at(deformed()));
  ASSERT_GT(scale, 0.0);
  EXPECT_LE(max_abs(force_at(rest_)), kBalanceTol * scale) << "force at rest";
  EXPECT_LE(max_abs(force_at(set_.rigid_motion(rest_, length_))), kBalanceTol * scale)
      << "force after a rigid motion of the rest shape (largest force when deformed: " << scale << ")";
}
INSTANTIATE_TEST_SUITE_P(Battery, ForceFieldRigidMotion, ::testing::ValuesIn(cases_with(kRigidRest)), case_name);

// ---------------------------------------------------------------- build_damping = ∂f/∂v
class ForceFieldDamping : public ForceFieldBattery {};
TEST_P(ForceFieldDamping, AssembledDampingMatchesFiniteDifferencesInVelocity) {
  const auto x = deformed();
  set_.set_coords(x);
  const std::size_t n = set_.size();
  const auto v0 = set_.random_direction(5, length_);
  const auto dv = set_.random_direction(6, length_);
  auto f_at_v = [&](double h) {
    std::vector<double> v = v0;
    for (std::size_t i = 0; i < n; ++i) v[i] += h * dv[i];
    set_.set(kVelocity, v);
    return force_at(x);
  };
  const auto fp = f_at_v(h_), fm = f_at_v(-h_);
  std::vector<double> fd(n);
  for (std::size_t i = 0; i < n; ++i) fd[i] = (fp[i] - fm[i]) / (2 * h_);
  MatrixSink sink;
  ASSERT_TRUE(ff_->build_damping(sink));
  std::vector<double> Bdv(n, 0.0);
  for (const MatrixSink::Entry& e : sink.entries()) {
    const int r = set_.index_of(e.row_state), c = set_.index_of(e.col_state);
    ASSERT_TRUE(r >= 0 && c >= 0) << "an entry refers to a state the force field does not act on";
    Bdv[set_.offset(r) + e.row] += e.value * dv[set_.offset(c) + e.col];
  }
  EXPECT_TRUE(near_rel(Bdv, fd, 1e-6, "build_damping·dv", "central differences of add_force in v", &set_));
}
INSTANTIATE_TEST_SUITE_P(Battery, ForceFieldDamping, ::testing::ValuesIn(cases_with(kDamping)), case_name);

// ---------------------------------------------------------------- enrolment
// Every registered class whose objects are force fields has a case (or a reason in kExcluded).
TEST(ForceFieldBatteryEnrolment, EveryRegisteredForceFieldHasACase) {
  register_all_components();
  std::set<std::string> enrolled;
  for (const auto& c : kCases) {
    auto s = test::load(c.scene);
    ASSERT_TRUE(s.root) << c.name;
    ForceField* ff = find_force_field(*s.root, "ff");
    ASSERT_NE(ff, nullptr) << c.name;
    enrolled.insert(ff->class_name());
  }
  int force_fields = 0;
  for (const auto& [name, info] : registry().all()) {
    const std::string tmpl = info.default_template;
    auto obj = info.create(tmpl);
    if (!dynamic_cast<ForceField*>(obj.get())) continue;
    ++force_fields;
    EXPECT_TRUE(enrolled.count(name) || kExcluded.count(name))
        << name << " is a registered force field without a line in kCases (force_field_battery_test.cpp)";
  }
  EXPECT_GT(force_fields, 20);
}

// potential_energy() is provided exactly by the cases that say kEnergy, so no energy goes unchecked.
TEST(ForceFieldBatteryEnrolment, EnergyIsProvidedWhereTheCaseSaysSo) {
  for (const auto& c : kCases) {
    auto s = test::load(c.scene);
    ASSERT_TRUE(s.root) << c.name;
    ForceField* ff = find_force_field(*s.root, "ff");
    ASSERT_NE(ff, nullptr) << c.name;
    ASSERT_EQ(ff->state(), ComponentState::valid) << c.name;
    StateSet set(ff->states());
    set.fill(kForce, 0.0);
    ff->add_force(MechParams{});
    EXPECT_EQ(ff->potential_energy().has_value(), (c.checks & kEnergy) != 0) << c.name;
  }
}
