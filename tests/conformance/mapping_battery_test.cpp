// Mapping battery: every registered mapping is checked on a small scene of
// its own, one line in kCases below (spec/mechanics.md §6, framework.md §6.6):
//
// * apply_j = central differences of apply (Rigid3d outputs differenced on
//   the rotation group; translation rows only with kTranslationRowsOnly),
//   along random input directions;
// * apply_jt is the adjoint of apply_j (⟨J·u, w⟩ = ⟨u, Jᵀ·w⟩) and adds to
//   the input forces;
// * jacobian() entries = apply_j on every unit vector, with a pattern that
//   does not depend on the positions (kJacobian);
// * apply_djt = central differences of Jᵀ(x)·w (kGeometric, non-linear
//   mappings) and build_geometric_stiffness = apply_djt on unit vectors
//   (kAssembledGeometric).
//
// Each check runs with the inputs moved away from their initial positions by
// seeded random displacements (10% of the scene size, rotations in radians).
// A new mapping joins with one line; EveryRegisteredMappingHasACase fails
// until it does.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <tuple>

#include "components/register_all.h"
#include "conformance.h"
#include "core/registry.h"
#include "test_scene.h"

using namespace sinew;
using namespace sinew::conformance;

namespace {

enum Check : unsigned {
  kJacobian = 1u << 0,            // jacobian() provides J
  kGeometric = 1u << 1,           // apply_djt is the exact geometric stiffness
  kAssembledGeometric = 1u << 2,  // build_geometric_stiffness = apply_djt
  // Rigid3d outputs whose J is SOFA's and not the derivative of apply for the
  // rotation (BarycentricMapping Vec3d,Rigid3d): only the translation rows are
  // compared with finite differences; Jᵀ must still be the adjoint of that J.
  kTranslationRowsOnly = 1u << 3,
  // Rigid3d inputs whose geometric stiffness is SOFA's and not the derivative of Jᵀ·w for
  // the rotation (DistanceFromTargetMapping's (I − u uᵀ)·λ/d is 6×6: λ/d on the rotation
  // diagonal although J ignores the orientation): apply_djt is compared with finite
  // differences on the translation rows only; build_geometric_stiffness must still match it.
  kGeometricTranslationRowsOnly = 1u << 4,
};

struct MappingCase {
  const char* name;   // test name: the class, then the template or variant
  std::string scene;  // the mapping under test is named "map"
  unsigned checks;
};
void PrintTo(const MappingCase& c, std::ostream* os) { *os << c.name; }

std::string node(const std::string& body) { return "<Node name='root' gravity='0 0 0'>" + body + "</Node>"; }
// `extra` and the input state 'in' (with `in_attrs`) in the root; the output 'out' (with `out_attrs`)
// and the mapping under test <cls name='map' map_attrs/> in a child node.
std::string mapped(const std::string& in_attrs, const std::string& out_attrs, const std::string& cls,
                   const std::string& map_attrs = "", const std::string& extra = "") {
  return node(extra + "<MechanicalObject name='in' " + in_attrs + "/><Node name='child'><MechanicalObject name='out' " +
              out_attrs + "/><" + cls + " name='map' " + map_attrs + "/></Node>");
}
const std::string kPoints = "position='0 0 0  1.5 0.2 0  0.3 1.1 0.4  2 2 -1'";
const std::string kFrames = "template='Rigid3d' position='1 2 3 0 0 0.6 0.8  -1 0.5 2 0.28 0 0 0.96'";
const std::string kVec1 = "template='Vec1d'";
const std::string kEdges = "<MeshTopology name='topo' edges='0 1  1 2  2 0  3 1'/>";
const std::string kTetPoints = "position='0 0 0  1 0 0  0 1 0  0 0 1  1 1 1' tetrahedra='0 1 2 3  1 2 3 4'";
const std::string kEmbedded = "position='0.1 0.2 0.3  0.6 0.6 0.6  0.3 0.1 0.1'";
const std::string kExact = "geometricStiffness='Exact' ";
const std::string kTwoInputs =
    node("<Node name='a'><MechanicalObject name='pa' position='0 0 0  1 0 0'/></Node>"
         "<Node name='b'><MechanicalObject name='pb' position='3 1 0  4 4 1'/></Node>"
         "<Node name='link'><MechanicalObject name='out' template='Vec1d'/>"
         "<MeshTopology name='edges' edges='0 1  1 2'/>"
         "<DistanceMultiMapping name='map' template='Vec3d,Vec1d' topology='@edges' input='@../a @../b' output='@out'"
         " indexPairs='0 1  1 0  1 1' restLengths='1 0.5' geometricStiffness='Exact'/></Node>");

// Points in the second of two frames (index 1), the frames in another branch.
const std::string kOnFrame =
    node("<MechanicalObject name='frames' " + kFrames + "/>"
         "<Node name='local'><MechanicalObject name='pts' " + kPoints + "/></Node>"
         "<Node name='child'><MechanicalObject name='out'/>"
         "<DeformableOnRigidFrameMapping name='map' input1='@../local/pts' input2='@../frames' output='@out'"
         " index='1'/></Node>");

// ---------------------------------------------------------------- cases: one line per mapping (template)
const std::vector<MappingCase> kCases = {
    {"IdentityMapping", mapped(kPoints, "", "IdentityMapping"), kJacobian},
    {"IdentityMapping_Vec1d", mapped(kVec1 + " position='1 2 3'", kVec1, "IdentityMapping"), kJacobian},
    {"IdentityMapping_Rigid3d", mapped(kFrames, "template='Rigid3d'", "IdentityMapping"), kJacobian},
    {"IdentityMapping_Rigid3dToVec3d", mapped(kFrames, "", "IdentityMapping"), kJacobian},
    {"IdentityMapping_Rigid2dToVec2d",
     mapped("template='Rigid2d' position='1 2 0.3  -1 0 2'", "template='Vec2d'", "IdentityMapping"), kJacobian},
    {"SubsetMapping", mapped(kPoints, "", "SubsetMapping", "indices='3 1 1' handleTopologyChange='false'"), kJacobian},
    {"SubsetMapping_Rigid3d",
     mapped(kFrames, "template='Rigid3d'", "SubsetMapping", "indices='1' handleTopologyChange='false'"), kJacobian},
    {"BarycentricMapping_RegularGrid",
     mapped("", "position='0.5 0.25 1.5  1.9 1.1 0.2  2.5 -0.5 1'", "BarycentricMapping", "",
            "<RegularGridTopology name='grid' n='3 3 3' min='0 0 0' max='2 2 2'/>"),
     kJacobian},
    {"BarycentricMapping_MeshTopology",
     mapped("", kEmbedded, "BarycentricMapping", "", "<MeshTopology name='topo' " + kTetPoints + "/>"), kJacobian},
    {"BarycentricMapping_TetrahedronSet",
     mapped("", kEmbedded, "BarycentricMapping", "",
            "<TetrahedronSetTopologyContainer name='topo' " + kTetPoints + "/>"),
     kJacobian},
    {"BarycentricMapping_Rigid3d",
     mapped("", "template='Rigid3d' position='0.1 0.2 0.3 0 0 0 1  0.6 0.6 0.6 0.28 0 0 0.96'", "BarycentricMapping",
            "", "<TetrahedronSetTopologyContainer name='topo' " + kTetPoints + "/>"),
     kJacobian | kTranslationRowsOnly},
    // No assembled geometric stiffness (build_geometric_stiffness returns false).
    // Each point blends its two nearest frames (1/d² weights); J is the derivative of apply,
    // SOFA gives no geometric stiffness.
    {"SkinningMapping", mapped(kFrames, kPoints, "SkinningMapping", "nbRef='2'"), kJacobian},
    {"RigidMapping",
     mapped(kFrames, "position='1 0 0  0 0.5 1  -0.3 0.2 0.1'", "RigidMapping", kExact + "rigidIndexPerPoint='0 1 1'"),
     kJacobian | kGeometric},
    {"RigidMapping_Rigid3dToRigid3d",
     mapped(kFrames, "template='Rigid3d' position='1 0 0 0 0 0 1  0 0.5 1 0.28 0 0 0.96  -0.3 0.2 0.1 0 0.6 0 0.8'",
            "RigidMapping", kExact + "rigidIndexPerPoint='0 1 1'"),
     kJacobian | kGeometric},
    {"RigidMapping_Rigid2d",
     mapped("template='Rigid2d' position='0 0 0  5 0 1.5707963267948966'", "template='Vec2d' position='1 0  1 0.5'",
            "RigidMapping", "rigidIndexPerPoint='0 1'"),
     kJacobian},
    {"BeamLinearMapping",
     mapped("template='Rigid3d' position='0 0 0 0 0 0.6 0.8  1 1 0 0.28 0 0 0.96  2 1.5 0.5 0 0.6 0 0.8'",
            "position='0.3 0.1 -0.2  1.6 -0.1 0.05  1.0 0.2 0.2'", "BeamLinearMapping"),
     kJacobian},
    {"TubularMapping", mapped(kFrames, "", "TubularMapping", "nbPointsOnEachCircle='5' radius='0.3'"), kJacobian},
    {"TubularMapping_Peak", mapped(kFrames, "", "TubularMapping", "nbPointsOnEachCircle='3' radius='0.7' peak='-1'"),
     kJacobian},
    {"DistanceMapping", mapped(kPoints, kVec1, "DistanceMapping", kExact + "topology='@../topo'", kEdges),
     kJacobian | kGeometric | kAssembledGeometric},
    {"DistanceMapping_Rigid3d",
     mapped(kFrames, kVec1, "DistanceMapping", kExact + "topology='@../topo'",
            "<MeshTopology name='topo' edges='0 1'/>"),
     kJacobian | kGeometric | kAssembledGeometric},
    {"SquareDistanceMapping", mapped(kPoints, kVec1, "SquareDistanceMapping", kExact + "topology='@../topo'", kEdges),
     kJacobian | kGeometric | kAssembledGeometric},
    {"DistanceMultiMapping", kTwoInputs, kJacobian | kGeometric | kAssembledGeometric},
    {"DistanceFromTargetMapping",
     mapped(kPoints, kVec1, "DistanceFromTargetMapping",
            kExact + "indices='3 1 0' targetPositions='0.5 0.5 0.5  -1 0 2  1 1 1' restLengths='0.2 0 1'"),
     kJacobian | kGeometric | kAssembledGeometric},
    // Vec1d: u = ±1, so I − u uᵀ = 0: no geometric stiffness, which is the exact one.
    {"DistanceFromTargetMapping_Vec1d",
     mapped(kVec1 + " position='1 2 3'", kVec1, "DistanceFromTargetMapping", kExact + "targetPositions='0.5 4 -1'"),
     kJacobian},
    {"DistanceFromTargetMapping_Rigid3d",
     mapped(kFrames, kVec1, "DistanceFromTargetMapping",
            kExact + "indices='1 0' targetPositions='0 0 0 0 0 0 1  2 2 2 0 0 0 1'"),
     kJacobian | kGeometric | kAssembledGeometric | kGeometricTranslationRowsOnly},
    {"SquareMapping", mapped(kVec1 + " position='1 -2 0.5'", kVec1, "SquareMapping"),
     kJacobian | kGeometric | kAssembledGeometric},
    {"DistanceToPlaneMapping", mapped(kPoints, kVec1, "DistanceToPlaneMapping", "planeNormal='1 2 2' planePoint='0 0 1'"),
     kJacobian},
    {"DistanceToPlaneMapping_Rigid3d",
     mapped(kFrames, kVec1, "DistanceToPlaneMapping", "template='Rigid3d' planeNormal='0 3 4' planePoint='1 1 1'"),
     kJacobian},
    // Triangle 1 3 2 is listed out of vertex order (SOFA sorts each row's entries).
    {"AreaMapping",
     mapped(kPoints, kVec1, "AreaMapping", kExact + "topology='@../topo'",
            "<MeshTopology name='topo' triangles='0 1 2  1 3 2  3 0 2'/>"),
     kJacobian | kGeometric | kAssembledGeometric},
    {"VolumeMapping",
     mapped("position='0 0 0  1 0 0  0 1 0  0 0 1  1 1 1'", kVec1, "VolumeMapping", kExact + "topology='@../topo'",
            "<MeshTopology name='topo' tetrahedra='0 1 2 3  4 2 1 3'/>"),
     kJacobian | kGeometric | kAssembledGeometric},
    // Frames of masses 2 (UniformMass): the centre is their mean.
    {"CenterOfMassMapping",
     node("<MechanicalObject name='in' " + kFrames +
          "/><UniformMass template='Rigid3d' vertexMass='2'/>"
          "<Node name='child'><MechanicalObject name='out' position='0 0 0'/>"
          "<CenterOfMassMapping name='map' template='Rigid3d,Vec3d'/></Node>"),
     kJacobian},
    {"CenterOfMassMapping_Rigid2d",
     node("<MechanicalObject name='in' template='Rigid2d' position='1 2 0.3  -1 0 2  0 4 1'/>"
          "<UniformMass template='Rigid2d' vertexMass='1'/>"
          "<Node name='child'><MechanicalObject name='out' template='Vec2d' position='0 0'/>"
          "<CenterOfMassMapping name='map' template='Rigid2d,Vec2d'/></Node>"),
     kJacobian},
    {"SubsetMultiMapping",
     node("<Node name='a'><MechanicalObject name='pa' position='0 0 0  1 0 0'/></Node>"
          "<Node name='b'><MechanicalObject name='pb' position='3 1 0  4 4 1'/></Node>"
          "<Node name='all'><MechanicalObject name='out'/>"
          "<SubsetMultiMapping name='map' input='@../a @../b' output='@out' indexPairs='1 1  0 0  1 0'/></Node>"),
     kJacobian},
    {"IdentityMultiMapping",
     node("<Node name='a'><MechanicalObject name='pa' position='0 0 0  1 0 0'/></Node>"
          "<Node name='b'><MechanicalObject name='pb' position='3 1 0  4 4 1'/></Node>"
          "<Node name='all'><MechanicalObject name='out'/>"
          "<IdentityMultiMapping name='map' input='@../a @../b' output='@out'/></Node>"),
     kJacobian},
    {"DeformableOnRigidFrameMapping", kOnFrame, kJacobian},
    // A three-frame arm hung from a turned base frame: a ball joint (two rotations, Euler order)
    // then a slider and a hinge, joint axes not unit (normalised by the mapping).
    {"ArticulatedSystemMapping",
     node("<MechanicalObject name='q' template='Vec1d' position='0.4 -0.7 0.3 1.1'/>"
          "<Node name='base'><MechanicalObject name='frame' template='Rigid3d' position='1 2 3 0 0 0.6 0.8'/></Node>"
          "<Node name='body'><MechanicalObject name='out' template='Rigid3d'"
          " position='0 0 0 0 0 0 1  0 0 0 0 0 0 1  0 0 0 0 0 0 1'/>"
          "<ArticulatedSystemMapping name='map' input1='@../q' input2='@../base/frame' output='@out'/></Node>"
          "<ArticulatedHierarchyContainer/><Node name='centers'>"
          "<Node name='c1'><ArticulationCenter parentIndex='0' childIndex='1' posOnParent='0.5 0.2 0'"
          " posOnChild='-0.6 0 0.1'/><Node name='a'><Articulation articulationIndex='0' rotation='1' axis='0 0 2'/>"
          "<Articulation articulationIndex='1' rotation='1' axis='0 1 1'/></Node></Node>"
          "<Node name='c2'><ArticulationCenter parentIndex='1' childIndex='2' posOnParent='0.7 0 0'"
          " posOnChild='-0.4 0.1 0'/><Node name='a'><Articulation articulationIndex='2' translation='1' axis='1 1 0'/>"
          "<Articulation articulationIndex='3' rotation='1' axis='1 0 0'/></Node></Node></Node>"),
     kJacobian},
    // Two tetrahedra refined by their topological mapping: input points and edge midpoints.
    {"SimpleTesselatedTetraMechanicalMapping",
     node("<TetrahedronSetTopologyContainer name='topo' " + kTetPoints +
          "/><MechanicalObject name='in'/><Node name='child'><TetrahedronSetTopologyContainer name='fine'/>"
          "<SimpleTesselatedTetraTopologicalMapping input='@../topo' output='@fine'/><MechanicalObject name='out'/>"
          "<SimpleTesselatedTetraMechanicalMapping name='map'/></Node>"),
     kJacobian},
};

// Registered mappings without a case, and why. None (visual models such as OglModel are mapping
// outputs, not mappings).
const std::map<std::string, std::string> kExcluded = {
    // A visual surface whose vertex count follows the fluid: no Jacobian (SOFA's applyJ and
    // applyJT do nothing); tests/sph/ checks the surface.
    {"SPHFluidSurfaceMapping", "iso-surface of a fluid: no Jacobian"},
    // SOFA rounds the coarse displacements to single precision in apply and applyJ: central
    // differences of apply are noise at the battery's step; hexahedron_composite_fem_test.cpp
    // checks rigid translations and ⟨J·v, f⟩ = ⟨v, Jᵀ·f⟩ to single precision.
    {"HexahedronCompositeFEMMapping", "single-precision displacements (SOFA): no finite differences"},
};

std::string case_name(const ::testing::TestParamInfo<MappingCase>& info) { return info.param.name; }
std::vector<MappingCase> cases_with(unsigned checks) {
  std::vector<MappingCase> out;
  for (const auto& c : kCases)
    if ((c.checks & checks) != 0) out.push_back(c);
  return out;
}

Mapping* find_mapping(Node& root, std::string_view name) {
  std::vector<Mapping*> all;
  root.collect_down(all);
  for (Mapping* m : all)
    if (m->name.value() == name) return m;
  return nullptr;
}

// out = (a ⊖ b) / (2h) for output coordinates: differences of positions; for
// Rigid3d the rotation vector of q_a·q_b⁻¹ (world frame, as SOFA's velocities).
std::vector<double> coord_difference(const MechanicalState& s, const std::vector<double>& a,
                                     const std::vector<double>& b, double two_h) {
  const int cw = s.info().coord_width, dw = s.info().deriv_width;
  std::vector<double> d(s.size() * dw);
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double* p = &a[i * cw];
    const double* q = &b[i * cw];
    double* o = &d[i * dw];
    if (s.state_type() == StateType::rigid3) {
      for (int c = 0; c < 3; ++c) o[c] = (p[c] - q[c]) / two_h;
      const Eigen::Quaterniond qa(p[6], p[3], p[4], p[5]), qb(q[6], q[3], q[4], q[5]);
      const Eigen::AngleAxisd r(qa * qb.inverse());
      const Vec3 w = r.axis() * (r.angle() > M_PI ? r.angle() - 2 * M_PI : r.angle());
      for (int c = 0; c < 3; ++c) o[3 + c] = w[c] / two_h;
    } else {
      for (int c = 0; c < dw; ++c) o[c] = (p[c] - q[c]) / two_h;
    }
  }
  return d;
}

class MappingBattery : public ::testing::TestWithParam<MappingCase> {
 protected:
  void SetUp() override {
    scene_ = test::load(GetParam().scene);
    ASSERT_TRUE(scene_.root) << "the scene does not load";
    map_ = find_mapping(*scene_.root, "map");
    ASSERT_NE(map_, nullptr) << "the scene has no mapping named 'map'";
    ASSERT_EQ(map_->state(), ComponentState::valid) << map_->class_name() << " is not valid after init";
    ASSERT_NE(map_->output(), nullptr) << "the mapping under test must have a mechanical output";
    in_ = StateSet(map_->inputs());
    out_ = StateSet({map_->output()});
    ASSERT_GT(in_.size(), 0u);
    ASSERT_GT(out_.size(), 0u);
    length_ = in_.length_scale();
    // Away from the initial positions, so that non-linear terms are exercised.
    in_.move(in_.coords(), in_.random_direction(1, length_), 0.1);
    x_ = in_.coords();
    map_->apply(kPosition);
  }
  bool has(unsigned check) const { return (GetParam().checks & check) != 0; }

  // J·u through apply_j (role kDx), per output scalar.
  std::vector<double> apply_j(const std::vector<double>& u) const {
    in_.set(kDx, u);
    out_.fill(kDx, 0.0);
    map_->apply_j(kDx, kDx);
    return out_.get(kDx);
  }
  // Jᵀ·w through apply_jt (role kForce), with the input forces starting at `start`.
  std::vector<double> apply_jt(const std::vector<double>& w, const std::vector<double>& start) const {
    in_.set(kForce, start);
    out_.set(kForce, w);
    map_->apply_jt(kForce, kForce);
    return in_.get(kForce);
  }
  // Output positions with the inputs at x ⊕ h·u.
  std::vector<double> mapped_at(const std::vector<double>& u, double h) const {
    in_.move(x_, u, h);
    map_->apply(kPosition);
    return map_->output()->read(kPosition);
  }

  scene::LoadedScene scene_;
  Mapping* map_ = nullptr;
  StateSet in_, out_;
  StateSet::Coords x_;
  double length_ = 1, h_ = 1e-6;
};

}  // namespace

TEST_P(MappingBattery, ApplyJMatchesFiniteDifferencesOfApply) {
  for (unsigned seed : {2u, 3u}) {
    const auto u = in_.random_direction(seed, length_);
    const auto yp = mapped_at(u, h_), ym = mapped_at(u, -h_);
    mapped_at(u, 0.0);
    auto fd = coord_difference(*map_->output(), yp, ym, 2 * h_);
    auto ju = apply_j(u);
    if (has(kTranslationRowsOnly))
      for (std::size_t i = 0; i < ju.size(); ++i)
        if (i % 6 >= 3) ju[i] = fd[i] = 0.0;
    EXPECT_TRUE(near_rel(ju, fd, 1e-6, "apply_j", "central differences of apply", &out_))
        << "direction seed " << seed;
  }
}

TEST_P(MappingBattery, ApplyJtIsTheAdjointOfApplyJ) {
  const auto u = in_.random_direction(4, 1.0);
  const auto w = random_vector(out_.size(), 5);
  const auto ju = apply_j(u);
  const auto jtw = apply_jt(w, std::vector<double>(in_.size(), 0.0));
  const double lhs = dot(ju, w), rhs = dot(u, jtw);
  EXPECT_NEAR(lhs, rhs, 1e-12 * (std::fabs(lhs) + max_abs(ju) * max_abs(w)))
      << "⟨J·u, w⟩ = " << lhs << " but ⟨u, Jᵀ·w⟩ = " << rhs;
  EXPECT_GT(std::fabs(lhs), 1e-6) << "degenerate test vectors";
  // apply_jt adds to the input forces.
  const auto start = random_vector(in_.size(), 6);
  auto added = apply_jt(w, start);
  for (std::size_t i = 0; i < added.size(); ++i) added[i] -= start[i];
  EXPECT_TRUE(near_rel(added, jtw, 1e-12, "apply_jt onto non-zero forces − those forces", "apply_jt onto zero",
                       &in_));
}

INSTANTIATE_TEST_SUITE_P(Battery, MappingBattery, ::testing::ValuesIn(kCases), case_name);

// ---------------------------------------------------------------- jacobian()
class MappingJacobian : public MappingBattery {};
TEST_P(MappingJacobian, EntriesMatchApplyJ) {
  std::vector<JacobianEntry> entries;
  ASSERT_TRUE(map_->jacobian(entries)) << "the case says kJacobian but jacobian() returned false";
  const std::size_t n = in_.size(), m = out_.size();
  std::vector<double> J(m * n, 0.0), Jj(m * n, 0.0);
  for (const JacobianEntry& e : entries) {
    ASSERT_LT(e.input, in_.states().size());
    const std::size_t c = in_.offset(e.input) + e.col;
    ASSERT_TRUE(e.row < m && c < n) << "entry (" << e.row << ", " << e.col << ") of input " << e.input
                                    << " out of range";
    J[e.row * n + c] += e.value;
  }
  for (std::size_t j = 0; j < n; ++j) {
    std::vector<double> ej(n, 0.0);
    ej[j] = 1.0;
    const auto col = apply_j(ej);
    for (std::size_t i = 0; i < m; ++i) Jj[i * n + j] = col[i];
  }
  EXPECT_TRUE(near_rel(J, Jj, 1e-12, "jacobian()", "apply_j on unit vectors"));
  // The pattern (order of (input, row, col)) does not depend on the positions.
  auto pattern = [](const std::vector<JacobianEntry>& es) {
    std::vector<std::tuple<unsigned, unsigned, unsigned>> p;
    for (const auto& e : es) p.emplace_back(e.input, e.row, e.col);
    return p;
  };
  in_.move(x_, in_.random_direction(7, length_), 0.05);
  map_->apply(kPosition);
  std::vector<JacobianEntry> moved;
  ASSERT_TRUE(map_->jacobian(moved));
  EXPECT_EQ(pattern(moved), pattern(entries)) << "the Jacobian pattern changed with the positions";
}
INSTANTIATE_TEST_SUITE_P(Battery, MappingJacobian, ::testing::ValuesIn(cases_with(kJacobian)), case_name);

// ---------------------------------------------------------------- geometric stiffness
class MappingGeometricStiffness : public MappingBattery {
 protected:
  // k · (∂Jᵀ/∂x · w) · u through apply_djt, with w the output force.
  std::vector<double> djt(const std::vector<double>& w, const std::vector<double>& u, double k) const {
    out_.set(kForce, w);
    in_.set(kDx, u);
    in_.fill(kDforce, 0.0);
    map_->apply_djt(kDforce, kDx, k);
    return in_.get(kDforce);
  }
};
TEST_P(MappingGeometricStiffness, ApplyDjtMatchesFiniteDifferencesOfJt) {
  const auto w = random_vector(out_.size(), 8);
  const std::vector<double> zero(in_.size(), 0.0);
  for (unsigned seed : {9u, 10u}) {
    const auto u = in_.random_direction(seed, length_);
    mapped_at(u, h_);
    const auto gp = apply_jt(w, zero);
    mapped_at(u, -h_);
    const auto gm = apply_jt(w, zero);
    mapped_at(u, 0.0);
    std::vector<double> fd(in_.size());
    for (std::size_t i = 0; i < fd.size(); ++i) fd[i] = (gp[i] - gm[i]) / (2 * h_);
    auto k = djt(w, u, 1.0);
    EXPECT_GT(max_abs(k), 0.0) << "no geometric stiffness: the check would be empty";
    if (has(kGeometricTranslationRowsOnly))
      for (std::size_t i = 0; i < k.size(); ++i)
        if (i % 6 >= 3) k[i] = fd[i] = 0.0;
    EXPECT_TRUE(near_rel(k, fd, 1e-6, "apply_djt", "central differences of Jᵀ(x)·w", &in_))
        << "direction seed " << seed;
    auto scaled = djt(w, u, -0.3);
    for (double& v : scaled) v /= -0.3;
    if (has(kGeometricTranslationRowsOnly))
      for (std::size_t i = 0; i < scaled.size(); ++i)
        if (i % 6 >= 3) scaled[i] = 0.0;
    EXPECT_TRUE(near_rel(scaled, k, 1e-12, "apply_djt(k = −0.3) / −0.3", "apply_djt(k = 1)", &in_));
  }
}
INSTANTIATE_TEST_SUITE_P(Battery, MappingGeometricStiffness, ::testing::ValuesIn(cases_with(kGeometric)), case_name);

class MappingAssembledGeometricStiffness : public MappingGeometricStiffness {};
TEST_P(MappingAssembledGeometricStiffness, MatchesApplyDjt) {
  const auto w = random_vector(out_.size(), 8);
  out_.set(kForce, w);
  MatrixSink sink;
  ASSERT_TRUE(map_->build_geometric_stiffness(sink));
  const std::size_t n = in_.size();
  std::vector<double> K(n * n, 0.0), Kd(n * n, 0.0);
  for (const MatrixSink::Entry& e : sink.entries()) {
    const int r = in_.index_of(e.row_state), c = in_.index_of(e.col_state);
    ASSERT_TRUE(r >= 0 && c >= 0) << "an entry refers to a state that is not an input";
    K[(in_.offset(r) + e.row) * n + in_.offset(c) + e.col] += e.value;
  }
  for (std::size_t j = 0; j < n; ++j) {
    std::vector<double> ej(n, 0.0);
    ej[j] = 1.0;
    const auto col = djt(w, ej, 1.0);
    for (std::size_t i = 0; i < n; ++i) Kd[i * n + j] = col[i];
  }
  EXPECT_GT(max_abs(Kd), 0.0);
  EXPECT_TRUE(near_rel(K, Kd, 1e-12, "build_geometric_stiffness", "apply_djt on unit vectors"));
}
INSTANTIATE_TEST_SUITE_P(Battery, MappingAssembledGeometricStiffness,
                         ::testing::ValuesIn(cases_with(kAssembledGeometric)), case_name);

// ---------------------------------------------------------------- enrolment
TEST(MappingBatteryEnrolment, EveryRegisteredMappingHasACase) {
  register_all_components();
  std::set<std::string> enrolled;
  for (const auto& c : kCases) {
    auto s = test::load(c.scene);
    ASSERT_TRUE(s.root) << c.name;
    Mapping* m = find_mapping(*s.root, "map");
    ASSERT_NE(m, nullptr) << c.name;
    enrolled.insert(m->class_name());
  }
  int mappings = 0;
  for (const auto& [name, info] : registry().all()) {
    auto obj = info.create(info.default_template);
    if (!dynamic_cast<Mapping*>(obj.get())) continue;
    ++mappings;
    EXPECT_TRUE(enrolled.count(name) || kExcluded.count(name))
        << name << " is a registered mapping without a line in kCases (mapping_battery_test.cpp)";
  }
  EXPECT_GE(mappings, 8);
}
