// Numerical kernel shared by SOFA's TetrahedronFEMForceField and
// TetrahedralCorotationalFEMForceField (methods small, large, polar, svd;
// plasticity; computeGlobalMatrix), as plain per-element arrays and free
// functions. Nothing here knows about scenes or topologies.
//
// Everything reproduces SOFA to round-off: every sum is written out in SOFA's
// evaluation order (left to right, only the structurally non-zero terms),
// Eigen is used only as storage. Spec: shared/spec/mechanics.md §2.0–§2.2.
//
// Conventions (SOFA's): J is the 12×6 strain–displacement matrix built from
// cofactors (J = ±6V·∇N); the material matrix K is D/(36·V0) with V0 the
// absolute rest volume; displacements are Δ = rest − current, so the force of
// an element is F = J·K·Jᵀ·Δ. A frame R has rows = local axes (world → local);
// rot[e] = Rᵀ (local → world), as SOFA stores it.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "math/types.h"

namespace sinew::fem {

enum class TetraMethod { small, large, polar, svd };

// SOFA's J (12 rows × 6 columns). Entries that are structurally zero stay 0.
struct TetraJ {
  double m[12][6] = {};
  double operator()(int r, int c) const { return m[r][c]; }
  double& operator()(int r, int c) { return m[r][c]; }
};

// The three distinct entries of K = D/(36·V0): diagonal of the normal block,
// off-diagonal of the normal block, shear diagonal.
struct TetraMaterial {
  double d = 0, o = 0, s = 0;
};

// Material entries as SOFA computes them: unit diagonal, ν/(1−ν) off-diagonal,
// (1−2ν)/(2(1−ν)) shear, all multiplied by E(1−ν)/((1+ν)(1−2ν)) then divided
// by volume·36.
TetraMaterial tetra_material(double young, double poisson, double volume);

// |signed volume| with SOFA's expression dot(cross(b−a, c−a), d−a)/6.
double tetra_signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
inline double tetra_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double v = tetra_signed_volume(a, b, c, d);
  return v < 0 ? -v : v;
}

// J from four node positions (SOFA computeStrainDisplacement).
void tetra_strain_displacement(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, TetraJ& J);

// Frame of the "large" method: x along b−a, z ⟂ (b−a, c−a), y = z × x. Rows = axes.
Mat3 tetra_frame_large(const Vec3& a, const Vec3& b, const Vec3& c);

// F = J·(K·(Jᵀ·Δ)) with SOFA's zero pattern; when `plastic` is given, the
// plastic strain is updated (SOFA's rule) and removed from the strain first.
struct TetraPlasticity {
  double max_threshold = 0;  // 0: plasticity off
  double yield_threshold = 0;
  double creep = 0;
};
void tetra_force(const TetraJ& J, const TetraMaterial& K, const double D[12], double F[12]);
void tetra_force_plastic(const TetraJ& J, const TetraMaterial& K, const double D[12], const TetraPlasticity& p,
                         double plastic_strain[6], double F[12]);
// Same with K·Jᵀ·Δ scaled by `fact` before the last product (SOFA's addDForce).
void tetra_force_scaled(const TetraJ& J, const TetraMaterial& K, const double D[12], double fact, double F[12]);

// Element stiffness JKJt = (J·K)·Jᵀ (12×12, plain products as SOFA's Mat).
using Mat12 = Eigen::Matrix<double, 12, 12, Eigen::RowMajor>;
void tetra_jkjt(const TetraJ& J, const TetraMaterial& K, Mat12& out);
// S = RR·JKJt and SR = S·RRᵀ with RR = blockdiag(rot) (SOFA computeStiffnessMatrix).
void tetra_rotated_stiffness(const Mat12& JKJt, const Mat3& rot, Mat12& S, Mat12& SR);

// A problem found by TetraFEM::init (element = −1: whole input).
struct TetraIssue {
  int element = -1;
  bool fatal = true;
  std::string message;
};

// Hot data of one tetrahedral FEM force field. Vectors are indexed by element.
struct TetraFEM {
  TetraMethod method = TetraMethod::large;
  bool update_stiffness_matrix = false;  // SOFA updateStiffnessMatrix
  bool assembling = false;               // SOFA computeGlobalMatrix
  // updateStiffnessMatrix (large) also writes the two copies of each J entry
  // (TetrahedralCorotationalFEMForceField) or only the 9 listed entries
  // (TetrahedronFEMForceField).
  bool symmetric_update = false;
  TetraPlasticity plasticity;            // TetrahedronFEMForceField only
  bool split_from_hexahedra = false;     // elements made by split_hexahedra (no tetrahedra in the topology)

  std::vector<std::array<int, 4>> tetra;
  std::vector<Vec3> X0;                        // rest positions (small: Δ uses them)
  std::vector<TetraJ> J;
  std::vector<TetraMaterial> K;
  std::vector<Mat3> rot;                       // Rᵀ of the last add_force (identity for small)
  std::vector<Mat3> rot0;                      // SOFA _initialRotations = R0ᵀ
  std::vector<std::array<Vec3, 4>> rest;       // rotated initial nodes (large: recentred)
  std::vector<Mat3> T0;                        // svd: inverse rest edge matrix
  std::vector<std::array<double, 6>> plastic;  // plastic strain per element
  double rest_volume = 0;                      // Σ V0
  std::vector<double> lame_lambda, lame_mu;    // von Mises only
  std::vector<int> vm_count;                   // von Mises: elements per point (scratch, kept)
  std::vector<Eigen::Matrix4d> shape_inv;      // von Mises only: inverse of rows (1, X0_k)

  // Precompute everything from rest positions X0 and per-element E, ν
  // (already broadcast and validated; E may include localStiffnessFactor).
  std::vector<TetraIssue> init(std::span<const Vec3> X0, std::span<const std::array<int, 4>> tetra,
                               std::span<const double> E, std::span<const double> nu, TetraMethod m);

  std::size_t size() const { return tetra.size(); }
  void reset_plasticity();

  // Topological changes (core/topology_change.h), element by element as SOFA's per-element
  // data: the same arrays init would build from the changed lists, without rebuilding them.
  // Elements `decreasing` leave by swap-with-last; points `decreasing` leave the same way
  // (the last point's index renamed in the elements); end_change then rebuilds the
  // point incidence and the sums (O(elements), no element data recomputed).
  void remove_elements(const std::vector<unsigned>& decreasing);
  void remove_points(const std::vector<unsigned>& decreasing);
  void end_change();

  // f += element forces in element order; updates rot (and J when
  // update_stiffness_matrix), and the plastic strains.
  void add_force(std::span<const Vec3> x, std::span<Vec3> f);
  // False when SOFA adds no force in this configuration (computeGlobalMatrix
  // with polar/svd or with plasticity): the caller reports it.
  bool forces_supported() const;

  // df −= kfactor · rot·JKJᵀ·rotᵀ · dx per element.
  void add_dforce(std::span<const Vec3> dx, std::span<Vec3> df, double kfactor) const;

  // Per-point rotation used by the Warp/PrecomputedWarp preconditioners
  // (SOFA TetrahedronFEMForceField::getRotation): polar(Σ_e rot_e·R0_e / n_e)
  // over the n_e incident elements in element order when the topology has
  // tetrahedra (`average`); otherwise (hexahedra split internally: SOFA finds
  // no tetrahedra around the point) and for points without element,
  // rot_e·R0_e of the last element listing the point (element 0 if none).
  // Identity everywhere for the small method. out.size() = number of points.
  void node_rotations(std::span<Mat3> out, bool average = true) const;

  // von Mises stress (output only, SOFA computeVonMisesStress): mode 1 from the
  // corotational small strain of Δ (large/polar/svd; updates rot like SOFA),
  // mode 2 from the Green strain of x − X0, mode 3 TetrahedralCorotational's
  // variant (always the large frame and partial Δ, material entries divided by
  // 36·V0, zero unless method large). Per element, then averaged over the
  // incident elements of each point. Needs prepare_von_mises() first.
  void prepare_von_mises(std::span<const double> E, std::span<const double> nu);
  void von_mises(std::span<const Vec3> x, int mode, std::vector<double>& per_element,
                 std::vector<double>& per_node);

  // sink(row_node, col_node, block) with block = −rot·JKJt·rotᵀ (node pair
  // (n1, n2) of each element, n1 outer); blocks of shared nodes must be summed.
  template <class Sink>
  void add_stiffness_blocks(Sink&& sink) const;

  // ---- parallel evaluation (bit-identical to the sequential loops)
  static constexpr std::size_t kParallelMinElements = 4096;
  std::vector<std::uint32_t> node_start, node_slot;   // point → (element·4 + corner) slots, CSR
  mutable std::vector<std::array<Vec3, 4>> slots;     // per-element nodal contributions
  void build_incidence(std::size_t n_points);
  bool parallel() const;

 private:
  template <class Sink>
  void force_range(std::size_t e_begin, std::size_t e_end, std::span<const Vec3> x, Sink& sink);
  template <class Sink>
  void dforce_range(std::size_t e_begin, std::size_t e_end, std::span<const Vec3> dx, double kfactor,
                    Sink& sink) const;
  void gather_slots(std::span<Vec3> out, bool subtract) const;

  // ---- fast force differential (bit-identical to dforce_range): element data
  // packed per block of kLanes elements (SoA inside the block) with J reduced to
  // its 12 distinct entries, evaluated kLanes elements at a time, each lane doing
  // exactly the scalar sequence of operations. Used only when every element's J
  // has the structure of tetra_strain_displacement (bitwise copies); rebuilt
  // lazily when J/K (j_gen) or rot (r_gen) changed.
 public:
  static constexpr int kLanes = 4;
  struct alignas(32) HotBlock {
    double j[12][kLanes];  // per node k: b_k, c_k, d_k (J(3k,0), J(3k+1,1), J(3k+2,2))
    double k[3][kLanes];   // K.d, K.o, K.s
    double r[9][kLanes];   // rot[e](i, j) at 3i + j
    std::int32_t n[4][kLanes];
  };
  // Call after writing J/K (j = true) or rot directly (add_force/init/von_mises do it).
  void touch(bool j) {
    ++r_gen;
    if (j) ++j_gen;
  }

 private:
  std::uint64_t j_gen = 1, r_gen = 1;
  mutable std::uint64_t hot_j_gen = 0, hot_r_gen = 0;
  mutable bool hot_ok = false;  // every J has the compact structure
  mutable std::vector<HotBlock> hot;
  // SR = rot·JKJt·rotᵀ per element from the last add_force with computeGlobalMatrix.
  std::vector<Mat12> sr_cache;
  std::uint64_t sr_j_gen = 0, sr_r_gen = 0;
  mutable std::vector<Mat12> jkjt_cache;  // add_stiffness_blocks: JKJt per element (valid for jkjt_gen)
  mutable std::uint64_t jkjt_gen = 0;
  bool refresh_hot(bool rot_written = false) const;  // false: use dforce_range
  template <class Sink>
  void force_blocks_large(std::size_t b_begin, std::size_t b_end, std::span<const Vec3> x, Sink& sink);
  template <bool kRot, class Sink>
  void dforce_blocks(std::size_t b_begin, std::size_t b_end, std::span<const Vec3> dx, double kfactor,
                     Sink& sink) const;
};

template <class Sink>
void TetraFEM::add_stiffness_blocks(Sink&& sink) const {
  Mat12 jkjt, S, SRl;
  // add_force (computeGlobalMatrix) already computed SR with the same J, K and
  // rot this step: reuse it.
  const bool cached = sr_cache.size() == tetra.size() && sr_r_gen == r_gen && sr_j_gen == j_gen;
  // JKJt depends on J and K only: kept from one call to the next.
  const bool keep_jkjt = !cached && !update_stiffness_matrix;
  const bool jkjt_ok = keep_jkjt && jkjt_cache.size() == tetra.size() && jkjt_gen == j_gen;
  if (keep_jkjt && !jkjt_ok) jkjt_cache.resize(tetra.size());
  for (std::size_t e = 0; e < tetra.size(); ++e) {
    if (!cached) {
      const Mat12* jk = &jkjt;
      if (jkjt_ok) {
        jk = &jkjt_cache[e];
      } else {
        tetra_jkjt(J[e], K[e], jkjt);
        if (keep_jkjt) jkjt_cache[e] = jkjt;
      }
      const Mat3 r = method == TetraMethod::small ? Mat3::Identity() : rot[e];
      tetra_rotated_stiffness(*jk, r, S, SRl);
    }
    const Mat12& SR = cached ? sr_cache[e] : SRl;
    for (int n1 = 0; n1 < 4; ++n1)
      for (int n2 = 0; n2 < 4; ++n2) {
        Mat3 b;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) b(i, j) = -SR(3 * n1 + i, 3 * n2 + j);
        sink(tetra[e][n1], tetra[e][n2], b);
      }
  }
  if (keep_jkjt) jkjt_gen = j_gen;
}

// SOFA's hexahedron → 6 tetrahedra split used by TetrahedronFEMForceField when
// its topology has hexahedra only (nx, ny: grid cells along x, y).
std::vector<std::array<int, 4>> split_hexahedra(std::span<const std::array<unsigned, 8>> hexa, int nx, int ny);

}  // namespace sinew::fem
