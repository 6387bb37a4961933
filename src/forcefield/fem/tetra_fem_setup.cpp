#include "forcefield/fem/tetra_fem_setup.h"

#include "core/node.h"
#include "core/parse.h"
#include "topology/grid/regular_grid_topology.h"

namespace sinew {

fem::TetraMethod parse_tetra_method(const std::string& name, bool allow_svd, bool& known) {
  known = true;
  if (name == "small") return fem::TetraMethod::small;
  if (name == "large") return fem::TetraMethod::large;
  if (name == "polar") return fem::TetraMethod::polar;
  if (allow_svd && name == "svd") return fem::TetraMethod::svd;
  known = false;
  return fem::TetraMethod::large;
}

bool setup_tetra_fem(ForceField& c, const TetraFEMSetup& in, fem::TetraFEM& fem) {
  MeshTopologyBase* topo = in.topology;
  if (!topo) {
    c.msg_error("no topology found (a tetrahedral mesh is required)");
    return false;
  }
  MechanicalState* s = c.mstate.get();
  if (!s || s->state_type() != StateType::vec3) {
    c.msg_error("only Vec3d states are supported");
    return false;
  }
  std::vector<std::array<int, 4>> tets;
  fem.split_from_hexahedra = false;
  const auto& tt = topo->tetrahedra();
  if (!tt.empty()) {
    tets.reserve(tt.size());
    for (const auto& t : tt)
      tets.push_back({static_cast<int>(t[0]), static_cast<int>(t[1]), static_cast<int>(t[2]), static_cast<int>(t[3])});
  } else if (in.allow_hexa_split && !topo->hexahedra().empty()) {
    int nx = 2, ny = 1;  // SOFA's values for non-grid topologies
    if (auto* grid = dynamic_cast<RegularGridTopology*>(topo)) {
      nx = grid->dims()[0] - 1;
      ny = grid->dims()[1] - 1;
    }
    tets = fem::split_hexahedra(topo->hexahedra(), nx, ny);
    fem.split_from_hexahedra = true;
  } else {
    c.msg_error("the topology " + topo->describe() + " has no tetrahedra");
    return false;
  }

  const std::size_t ne = tets.size();
  std::vector<double> E(ne), nu(ne);
  const auto& ey = in.young;
  const auto& pr = in.poisson;
  const auto& lsf = in.local_stiffness_factor;
  bool warned_e = false, warned_nu = false;
  for (std::size_t i = 0; i < ne; ++i) {
    double e = ey.empty() ? 5000.0 : (i < ey.size() ? ey[i] : ey[0]);
    double v = pr.empty() ? 0.45 : (i < pr.size() ? pr[i] : pr[0]);
    if (e < 0) {
      if (!warned_e)
        c.msg_warning("youngModulus of element " + std::to_string(i) + " is " + parse::format_double(e) +
                      " (must be positive): replaced by 5000");
      warned_e = true;
      e = 5000.0;
    } else if (e == 0 && !warned_e) {
      c.msg_warning("youngModulus of element " + std::to_string(i) + " is 0: the element has no stiffness");
      warned_e = true;
    }
    if (v < 0 || v >= 0.5) {
      if (!warned_nu)
        c.msg_warning("poissonRatio of element " + std::to_string(i) + " is " + parse::format_double(v) +
                      " (must be in [0, 0.5)): replaced by 0.45");
      warned_nu = true;
      v = 0.45;
    }
    const double f = lsf.empty() ? 1.0 : lsf[i * lsf.size() / ne];
    E[i] = f * e;
    nu[i] = v;
  }

  const std::vector<double>& x0 = s->read(kRestPosition);
  const auto issues = fem.init(as_vec3(x0), tets, E, nu, in.method);
  bool fatal = false;
  for (const auto& is : issues) {
    const std::string where = is.element >= 0 ? "element " + std::to_string(is.element) + ": " : "";
    if (is.fatal) {
      c.msg_error(where + is.message);
      fatal = true;
    } else {
      c.msg_warning(where + is.message);
    }
  }
  if (!fatal && in.von_mises) fem.prepare_von_mises(E, nu);
  return !fatal;
}

void add_tetra_fem_force(fem::TetraFEM& fem, MechanicalState& s, const MechParams& p) {
  const std::vector<double>& x = s.read(p.x);
  std::vector<double>& f = s.write(p.f);
  fem.add_force(as_vec3(x), as_vec3(f));
}

void add_tetra_fem_dforce(const fem::TetraFEM& fem, MechanicalState& s, const MechParams& p, double kfactor) {
  const std::vector<double>& dx = s.read(p.dx);
  std::vector<double>& df = s.write(p.df);
  fem.add_dforce(as_vec3(dx), as_vec3(df), kfactor);
}

void add_tetra_fem_stiffness(const fem::TetraFEM& fem, const MechanicalState* s, MatrixSink& K) {
  fem.add_stiffness_blocks([&](int i, int j, const Mat3& b) { K.add_block(s, 3 * i, s, 3 * j, b); });
}

}  // namespace sinew
