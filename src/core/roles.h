// Roles: the abstract kinds of component the framework drives.
//
// A node files each component in slots by role (spec/framework.md §3.1);
// solvers and the animation loop talk to components only through these
// interfaces. One virtual call per component per operation: element loops
// live inside the implementations.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "core/component.h"
#include "core/constraint_matrix.h"
#include "core/matrix_sink.h"
#include "core/topology_change.h"
#include "math/types.h"

namespace sinew {

class MechanicalOps;

// ---------------------------------------------------------------- state
// Identifiers of state vectors. Standard ones are fields of the state;
// solvers allocate further ids (>= kFirstDynamicVec) for their temporaries.
enum VecId : int {
  kPosition = 0,
  kVelocity,
  kForce,
  kExternalForce,
  kRestPosition,
  kDx,
  kDforce,
  kFreePosition,
  kFreeVelocity,
  kResetPosition,
  kResetVelocity,
  kFirstDynamicVec = 16,
  // Solvers' temporaries that hold positions (Rigid3d: 7 scalars per DoF, not 6).
  kFirstDynamicCoordVec = 1 << 24,
};
// Whether an id holds coordinates (positions) rather than derivatives.
constexpr bool is_coord_vec(int id) {
  return id == kPosition || id == kRestPosition || id == kFreePosition || id == kResetPosition ||
         id >= kFirstDynamicCoordVec;
}

enum class StateType { vec1, vec2, vec3, vec6, rigid2, rigid3 };
struct StateTypeInfo {
  const char* name;    // SOFA template name: "Vec3d", "Rigid3d", ...
  int coord_width;     // scalars per position
  int deriv_width;     // scalars per velocity/force
  int spatial_dim;     // dimension of the point (centre for rigids)
};
const StateTypeInfo& state_type_info(StateType t);
// SOFA template name (after alias resolution) → type; false when not a state type.
bool state_type_from_name(std::string_view name, StateType& out);

class MechanicalState : public Component {
 public:
  virtual StateType state_type() const = 0;
  const StateTypeInfo& info() const { return state_type_info(state_type()); }
  virtual std::size_t size() const = 0;
  virtual void resize(std::size_t n) = 0;
  // Point removal of the state's topology (SOFA's handleStateChange on POINTSREMOVED): for
  // each index (decreasing), every vector's last DoF moves into the slot; then size −= n.
  virtual void remove_points(const std::vector<unsigned>& decreasing) = 0;
  // Point addition (SOFA's handleStateChange on POINTSADDED): `n` DoFs appended; with ancestors
  // (one row per new point, empty when none), each new DoF of every allocated vector is the
  // weighted sum of its ancestors' (coefficients default to 1/k for k ancestors).
  virtual void add_points(std::size_t n, const std::vector<std::vector<unsigned>>& ancestors,
                          const std::vector<std::vector<double>>& coefficients) = 0;
  // Vector `id` (coordinate or derivative layout), allocated and zero-filled
  // to size() on first use. Standard ids are the state's fields.
  // read(): the values; the vector's version is left alone, so a version
  // that moved means a value that was written (viewer, Python, links).
  virtual const std::vector<double>& read(int id) const = 0;
  // write(): the values, to be changed: the vector's version moves.
  virtual std::vector<double>& write(int id) = 0;
  // Marks a standard vector as changed again (after a write through a pointer kept earlier).
  virtual void touch(int id) = 0;
  // x_out = x_in + h·v, with the Rigid rule (quaternion exponential) for rigid states.
  virtual void add_deriv_to_coord(int x_out, int x_in, int v, double h) = 0;
  // Empties externalForce (end of each step).
  virtual void end_integration() = 0;
  // Independent ⇔ its node has no mechanical mapping.
  bool independent() const;
  // Whether vector `id` holds values yet (FreeMotionAnimationLoop initialises
  // the free vectors from x and v only while they are empty).
  virtual bool has_vec(int id) const = 0;

  // Rows of the Lagrangian constraint Jacobian on this state (spec/interaction.md §5.2),
  // rebuilt by the constraint solver every step.
  ConstraintMatrix& constraint_jacobian() { return jacobian_; }
  const ConstraintMatrix& constraint_jacobian() const { return jacobian_; }
  // Where a constraint solver stores Jᵀλ of its last solve (SOFA's "lambda" vector);
  // null for states that keep none.
  virtual Field<FlatVec>* lambda_field() { return nullptr; }

 private:
  ConstraintMatrix jacobian_;
};

// The vector a mechanical operation uses on state `s` for `id`: solver
// vectors (dynamic ids) exist only on independent states; on mapped states
// the standard vector of the same role is used instead (framework.md §6.1).
inline int vec_for(const MechanicalState& s, int id, int role) {
  return id < kFirstDynamicVec || s.independent() ? id : role;
}

// ---------------------------------------------------------------- mechanics
// Parameters of a mechanical operation: which vectors play x, v, f, dx, df,
// and the factors of m·M + b·B + k·K.
struct MechParams {
  int x = kPosition, v = kVelocity, f = kForce, dx = kDx, df = kDforce;
  double m = 0, b = 0, k = 0;
  bool implicit = false;
};

class ForceField : public Component {
 public:
  Field<double> rayleigh_stiffness{this, "rayleighStiffness", 0.0,
                                   "stiffness-proportional Rayleigh damping coefficient (>= 0)", "Rayleigh", "time"};
  Link<MechanicalState> mstate{this, "mstate", "state this force field acts on (default: the node's)"};

  // f += f(x, v) on the acted state(s).
  virtual void add_force(const MechParams& p) = 0;
  // df += kfactor · K · dx, with K = ∂f/∂x.
  virtual void add_dforce(const MechParams& p, double kfactor) = 0;
  // True for force fields between two states (springs, contacts).
  virtual bool is_interaction() const { return false; }
  // States this force field reads and writes (one for single-state force fields).
  virtual std::vector<MechanicalState*> states() const { return {mstate.get()}; }
  // The state when states() holds exactly one, else nullptr. Read by the
  // mechanical operations on every force evaluation, so it must not allocate.
  virtual MechanicalState* single_state() const { return mstate.get(); }

  // Assembled systems: add the raw entries of K = ∂f/∂x (resp. B = ∂f/∂v).
  // Return false when this component cannot assemble (the assembler reports it).
  virtual bool build_stiffness(MatrixSink& K) { return false; }
  virtual bool build_damping(MatrixSink& B) { return true; }  // no damping matrix by default
  // Potential energy at the current positions (SOFA's getPotentialEnergy), so that
  // add_force = −∂E/∂x. Like SOFA, some components compute it along with the force:
  // read it after add_force at those positions. nullopt: not provided.
  virtual std::optional<double> potential_energy() const { return std::nullopt; }

  void init() override;  // binds mstate to the node's state when not linked
  double k_factor(const MechParams& p) const { return p.k + p.b * rayleigh_stiffness.value(); }
};

class Mass : public ForceField {
 public:
  Field<double> rayleigh_mass{this, "rayleighMass", 0.0, "mass-proportional Rayleigh damping coefficient (>= 0)",
                              "Rayleigh", "1/time"};
  Field<bool> separate_gravity{this, "separateGravity", false, "add gravity to velocity instead of forces",
                               "Physics"};

  // res += factor · M · dx
  virtual void add_mdx(const MechParams& p, int res, int dx, double factor) = 0;
  // a = M⁻¹ f (diagonal masses only)
  virtual void acc_from_f(const MechParams& p, int a, int f) = 0;
  // v += dt · g
  virtual void add_gravity_to_v(int v, double dt) = 0;
  virtual double total() const = 0;
  // Assembled systems: add the raw entries of M.
  virtual bool build_mass(MatrixSink& M) = 0;
  // Diagonal (lumped) masses can be inverted directly by explicit solvers.
  virtual bool is_diagonal() const { return true; }
  void add_dforce(const MechParams&, double) override {}  // masses have no stiffness by default
  bool build_stiffness(MatrixSink&) override { return true; }
};

class ProjectiveConstraint : public Component {
 public:
  Link<MechanicalState> mstate{this, "mstate", "state this constraint acts on (default: the node's)"};
  void init() override;
  virtual void project_response(int dx) = 0;
  virtual void project_velocity(int v, double t) = 0;
  virtual void project_position(int x, double t) = 0;
  // Removes the constraint response of the DOFs it projects from the rows of
  // the constraint Jacobian (SOFA's projectJacobianMatrix); each constraint
  // does what SOFA's does (some leave the rows alone).
  virtual void project_jacobian(ConstraintMatrix& J) = 0;
  // Assembled systems: scalar indices (in the state) whose rows and columns are
  // cleared with 1 on the diagonal. Constraints that project differently
  // (line, plane) return false and are handled by the assembler otherwise.
  virtual bool dirichlet_indices(std::vector<std::size_t>& out) { return false; }
};

// A state that mappings may write but mechanical operations never see: the
// points of a visual model (OglModel), SOFA's VisualState<Vec3d>. Always Vec3d
// (3 scalars per point); it has positions and rest positions, no velocities.
class VisualState : public Component {
 public:
  virtual std::size_t visual_size() const = 0;
  virtual void visual_resize(std::size_t n) = 0;
  // id kPosition (or a solver vector: its role is position) or kRestPosition;
  // nullptr for every other id (visual models have no derivatives).
  virtual std::vector<double>* visual_vec(int id) = 0;
};

// Where a mapping's Jᵀ of one constraint-row entry goes (apply_jt_constraints):
// per input, the row's values accumulated by input DoF.
class ConstraintRowSink {
 public:
  // values: the input's derivative width scalars, added to DoF `dof` of input `input`.
  void add(std::size_t input, unsigned dof, const double* values) {
    Acc& a = acc_[input];
    if (dof >= a.slot.size()) return;
    int& slot = a.slot[dof];
    const int w = a.width;
    if (slot < 0) {
      slot = static_cast<int>(a.dofs.size());
      a.dofs.push_back(static_cast<int>(dof));
      a.values.resize(a.values.size() + static_cast<std::size_t>(w), 0.0);
    }
    double* dst = &a.values[static_cast<std::size_t>(slot) * w];
    for (int c = 0; c < w; ++c) dst[c] += values[c];
  }

 private:
  friend class Mapping;
  struct Acc {
    int width = 3;
    std::vector<int> slot;        // per input DoF: index in dofs, or -1
    std::vector<int> dofs;        // DoFs touched by the current row
    std::vector<double> values;   // width values per touched DoF
  };
  std::vector<Acc> acc_;
};

class Mapping : public Component {
 public:
  Field<bool> map_forces{this, "mapForces", true, "propagate forces through this mapping", "Mapping"};
  Field<bool> map_constraints{this, "mapConstraints", true, "propagate constraints through this mapping", "Mapping"};
  Field<bool> map_masses{this, "mapMasses", true, "propagate masses through this mapping", "Mapping"};
  Field<bool> map_matrices{this, "mapMatrices", false, "propagate assembled matrices through this mapping", "Mapping"};
  Field<bool> apply_rest_position{this, "applyRestPosition", false, "also map the rest positions at init", "Mapping"};

  // Input states (several for multi-mappings) and the output; the output is
  // null when it is not a mechanical state (a visual model, see visual_output()).
  virtual std::vector<MechanicalState*> inputs() const = 0;
  virtual MechanicalState* output() const = 0;
  virtual VisualState* visual_output() const { return nullptr; }
  // Whether the output's points are the input's (SOFA's sameTopology): a point removal
  // of the input's topology then also removes the output's DoFs.
  virtual bool same_topology() const { return false; }
  // Mechanical mappings carry forces and dx (framework.md trap T1: mappings to
  // visual models are flagged non-mechanical at init). A mechanical mapping
  // with mapForces=false prunes the force/dx visitors below it.
  bool is_mechanical() const { return output() != nullptr; }

  // `isMechanical` is an alias of both mapForces and mapMasses (SOFA BaseMapping).
  void parse(AttributeMap& attrs, Diagnostics& diag) override;

  // Each id is resolved per state with vec_for(state, id, role).
  // out.x ← f(in.x)   (role kPosition)
  virtual void apply(int x) = 0;
  // out.v ← J·in.v    (role kVelocity for velocities, kDx for position variations)
  virtual void apply_j(int v, int role) = 0;
  // in.f += Jᵀ·out.f  (role kForce or kDforce)
  virtual void apply_jt(int f, int role) = 0;
  // in.df += k · (∂Jᵀ/∂x · out.force) · in.dx: geometric stiffness of non-linear mappings.
  virtual void apply_djt(int df, int dx, double k) {}
  // Assembled systems: J as entries (false when not available), and the
  // geometric stiffness as raw entries on the input states.
  virtual bool jacobian(std::vector<JacobianEntry>& out) { return false; }
  virtual bool build_geometric_stiffness(MatrixSink& K) { return true; }
  // in.constraint_jacobian += rows of out.constraint_jacobian expressed on the
  // inputs' DOFs (same row ids), SOFA's applyJT on MatrixDeriv. The default
  // goes through jacobian(); false when this mapping cannot carry constraints.
  virtual bool apply_jt_constraints();
  // Fast path of apply_jt_constraints for mappings that can give Jᵀ of one
  // output entry (DoF `out_dof`, derivative `v`) without assembling J.
  virtual bool has_jt_entry() const { return false; }
  virtual void jt_entry(unsigned out_dof, const double* v, ConstraintRowSink& sink) const {}

 private:
  // Scratch of apply_jt_constraints, kept between steps (no allocation once warm).
  std::vector<JacobianEntry> constraint_j_, constraint_sorted_;
  std::vector<int> constraint_row_start_;
  ConstraintRowSink constraint_sink_;
};

class OdeSolver : public Component {
 public:
  OdeSolver();
  ~OdeSolver() override;
  // Advances the subtree of the solver's node by dt, writing positions/velocities to x_result/v_result.
  virtual void solve(double dt, int x_result, int v_result) = 0;
  // How much a solution dx of the solver's linear system moves positions and
  // velocities (SOFA's getPositionIntegrationFactor / getVelocityIntegrationFactor),
  // read by constraint corrections. Default: implicit Euler's dt and 1.
  virtual double position_integration_factor(double dt) const { return dt; }
  virtual double velocity_integration_factor(double dt) const { return 1.0; }
  // Advice closing the message of the check stage when this solver's states stop being finite.
  virtual const char* divergence_hint() const { return "reduce dt or check the material parameters"; }

 protected:
  // The subtree of the solver's node, gathered on first use and again
  // whenever the graph's structure changed.
  MechanicalOps& scope();

 private:
  std::unique_ptr<MechanicalOps> scope_;
};

class LinearSolver : public Component {
 public:
  // Prepares A = m·M + b·B + k·K over the scope of `ops` (assembly for assembled systems).
  virtual void build_system(MechanicalOps& ops, double m, double b, double k) = 0;
  // Solves A·x = rhs; x and rhs are vector ids on the scope's independent states.
  virtual void solve_system(MechanicalOps& ops, int x, int rhs) = 0;
};

class AnimationLoop : public Component {
 public:
  virtual void step(double dt) = 0;
};

// ---------------------------------------------------------------- topology
using Edge = std::array<unsigned, 2>;
using Triangle = std::array<unsigned, 3>;
using Quad = std::array<unsigned, 4>;
using Tetra = std::array<unsigned, 4>;
using Hexa = std::array<unsigned, 8>;
// Corner k of a hexahedron in SOFA's node order, as (x, y, z) in {0, 1}: the bottom face
// counter-clockwise, then the top face.
inline constexpr int kHexaCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                          {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

class MeshTopologyBase : public Component {
 public:
  virtual std::size_t nb_points() const = 0;
  virtual bool has_positions() const = 0;
  virtual Vec3 point(std::size_t i) const = 0;
  virtual const std::vector<Edge>& edges() const = 0;
  virtual const std::vector<Triangle>& triangles() const = 0;
  virtual const std::vector<Quad>& quads() const = 0;
  virtual const std::vector<Tetra>& tetrahedra() const = 0;
  virtual const std::vector<Hexa>& hexahedra() const = 0;
  // Version of one element list: moves whenever that list may have changed
  // (elements added, removed or renumbered). Components that keep data per
  // element compare it, never the list's size (a remove-one-add-one change
  // keeps the size). 0 for topologies whose lists never change.
  enum class Elements { edges, triangles, quads, tetrahedra, hexahedra };
  virtual std::uint64_t elements_version(Elements) const { return 0; }

  // Topological changes (core/topology_change.h). Handlers are called in
  // registration order for every event being propagated; the list is only
  // filled during a propagation (empty otherwise).
  ~MeshTopologyBase() override;
  const std::vector<TopologyHandler*>& topology_handlers() const { return handlers_; }
  const std::vector<TopologyChange>& topology_changes() const { return changes_; }
  std::vector<TopologyChange>& edit_topology_changes() { return changes_; }

  // Neighbourhood queries (SOFA's XAroundY / XInY), built on first use and
  // cached until the element lists change; one entry per vertex/edge/...
  // "Around" lists hold element indices in increasing order, except
  // triangles_around_edge, where a triangle that runs along the edge's
  // direction comes first (SOFA). Default: empty (topology without support).
  using IndexList = std::vector<unsigned>;
  static constexpr unsigned kInvalidIndex = ~0u;
  virtual const std::vector<IndexList>& edges_around_vertex() const { return empty_lists(); }
  virtual const std::vector<IndexList>& triangles_around_vertex() const { return empty_lists(); }
  virtual const std::vector<IndexList>& triangles_around_edge() const { return empty_lists(); }
  virtual const std::vector<IndexList>& quads_around_vertex() const { return empty_lists(); }
  virtual const std::vector<IndexList>& quads_around_edge() const { return empty_lists(); }
  virtual const std::vector<IndexList>& tetrahedra_around_vertex() const { return empty_lists(); }
  virtual const std::vector<IndexList>& tetrahedra_around_edge() const { return empty_lists(); }
  virtual const std::vector<IndexList>& tetrahedra_around_triangle() const { return empty_lists(); }
  virtual const std::vector<IndexList>& hexahedra_around_vertex() const { return empty_lists(); }
  virtual const std::vector<IndexList>& hexahedra_around_edge() const { return empty_lists(); }
  virtual const std::vector<IndexList>& hexahedra_around_quad() const { return empty_lists(); }
  // Edge j of triangle = edge opposite vertex j; of quad = (q[j+1], q[j+2]);
  // of tetra/hexa = edge j of SOFA's local edge table; triangle j of a tetra =
  // face opposite vertex j; quad j of a hexa = face j of SOFA's face table.
  virtual const std::vector<std::array<unsigned, 3>>& edges_in_triangle() const { return empty_of<3>(); }
  virtual const std::vector<std::array<unsigned, 4>>& edges_in_quad() const { return empty_of<4>(); }
  virtual const std::vector<std::array<unsigned, 6>>& edges_in_tetrahedron() const { return empty_of<6>(); }
  virtual const std::vector<std::array<unsigned, 4>>& triangles_in_tetrahedron() const { return empty_of<4>(); }
  virtual const std::vector<std::array<unsigned, 12>>& edges_in_hexahedron() const { return empty_of<12>(); }
  virtual const std::vector<std::array<unsigned, 6>>& quads_in_hexahedron() const { return empty_of<6>(); }
  // Index of the element with these vertices (any order/orientation), or kInvalidIndex.
  virtual unsigned edge_index(unsigned, unsigned) const { return kInvalidIndex; }
  virtual unsigned triangle_index(unsigned, unsigned, unsigned) const { return kInvalidIndex; }
  virtual unsigned quad_index(unsigned, unsigned, unsigned, unsigned) const { return kInvalidIndex; }

 protected:
  friend class TopologyHandler;
  std::vector<TopologyHandler*> handlers_;
  std::vector<TopologyChange> changes_;
  static const std::vector<IndexList>& empty_lists() {
    static const std::vector<IndexList> e;
    return e;
  }
  template <std::size_t N>
  static const std::vector<std::array<unsigned, N>>& empty_of() {
    static const std::vector<std::array<unsigned, N>> e;
    return e;
  }
};

// Other topology objects (modifiers, geometry algorithms): filed in topologyObject.
class TopologyObject : public Component {};

// Collision models (spheres, triangles, lines, points of a body); the
// collision module (src/collision/) defines what they hold.
class CollisionModel : public Component {};

// A collision pipeline (CollisionPipeline, CompositeCollisionPipeline): the
// collision stage of a step runs the pipeline of every node that has one, top-down
// (spec/interaction.md §1.3, §1.7). Contacts are added to and removed from the
// graph while it runs (the graph is not locked during that stage).
class CollisionPipelineBase : public Component {
 public:
  // Reset (last step's responses detached), detection, then response.
  virtual void collide(double dt) = 0;
};

// Visual-only components (OglModel, VisualStyle, lights...): nothing in batch runs.
class VisualComponent : public Component {};

// Components that change the context of their node (Gravity).
class ContextObject : public Component {
 public:
  virtual void apply(Node& node) = 0;
};

}  // namespace sinew
