// TopologicalChangeProcessor's INCISE= blocks (SOFA's INCISE= branch of
// processTopologicalChanges, saveIndices, inciseWithSavedIndices,
// updateTriangleIncisionInformation). The cutting itself is topology/algorithm/triangle_incision.h.
#include <cmath>
#include <sstream>

#include "core/node.h"
#include "topology/algorithm/triangle_incision.h"
#include "topology/dynamic/triangle_set_topology_modifier.h"
#include "topology/utility/topological_change_processor.h"

namespace sinew {

bool TopologicalChangeProcessor::incision_mesh(incision::Mesh* m) const {
  MeshTopologyBase* t = topology.get();
  if (!t && node()) t = node()->get_mesh_topology_link();
  if (!t || !t->node()) return false;
  m->topology = t;
  m->state = t->node()->get_mechanical_state();
  m->modifier = t->node()->find_up<TriangleSetTopologyModifier>();
  return m->state && m->state->info().coord_width == 3 && m->modifier;
}

std::vector<double> TopologicalChangeProcessor::incise_values(std::size_t line, std::size_t n) {
  std::vector<double> v;
  if (line >= lines_.size()) return v;
  std::istringstream s(lines_[line]);
  double x;
  while (s >> x) v.push_back(x);
  if (v.size() < 3 * n) {  // SOFA aborts the incision (checked at init already)
    msg_error(where(line) + "INCISE=: not enough values; incision aborted");
    v.clear();
  }
  return v;
}

void TopologicalChangeProcessor::compute_coordinates(const incision::Mesh& m, SavedIncision& s) const {
  s.coordinates.assign(s.triangles.size(), Vec3::Zero());
  const auto& tris = m.topology->triangles();
  for (std::size_t i = 0; i < s.triangles.size(); ++i) {
    if (s.triangles[i] >= tris.size()) continue;  // reported where it was lost
    for (int k = 0; k < 3; ++k) s.coordinates[i] += m.position(tris[s.triangles[i]][k]) * s.barycoefs[i][k];
  }
}

// SOFA's saveIndices: every INCISE= block (after its T= line, blank lines skipped) located now,
// blocks of the same time merged; then a block starting where the previous one ended has its
// first point moved 1e-5 of the way to its second (SOFA's guard against a cut starting exactly
// on the previous cut's end).
void TopologicalChangeProcessor::save_incisions() {
  saved_.clear();
  incision::Mesh m;
  if (!incision_mesh(&m)) {
    msg_error("INCISE= needs a Vec3 MechanicalObject and a TriangleSetTopologyModifier with the topology");
    return;
  }
  std::vector<std::size_t> nonblank;
  for (std::size_t i = 0; i < lines_.size(); ++i)
    if (!lines_[i].empty()) nonblank.push_back(i);
  for (std::size_t k = 0; k < nonblank.size(); ++k) {
    const std::size_t i = nonblank[k];
    if (lines_[i].find("INCISE") == std::string::npos) continue;
    if (k == 0 || lines_[nonblank[k - 1]].find("T=") == std::string::npos || k + 1 >= nonblank.size()) {
      msg_error(where(i) + "INCISE= must follow its T= line and precede its line of points; block not saved");
      continue;
    }
    std::istringstream ts(lines_[nonblank[k - 1]]);
    std::string tok;
    double time = 0;
    ts >> tok >> time;
    std::istringstream is(lines_[i]);
    std::size_t n = 0;
    is >> tok >> n;
    const std::size_t vl = nonblank[k + 1];
    const std::vector<double> values = incise_values(vl, n);
    if (values.empty()) continue;
    const bool only_coordinates = values.size() == 3 * n;
    const std::size_t step = only_coordinates ? 3 : 4;
    SavedIncision* s = nullptr;
    for (auto& x : saved_)
      if (std::fabs(time - x.time) < 1e-10) s = &x;
    if (!s) {
      saved_.push_back({});
      s = &saved_.back();
      s->time = time;
      s->line = i;
    }
    for (std::size_t j = 0; j + step <= values.size(); j += step) {
      Vec3 c;
      unsigned tri;
      if (only_coordinates) {
        c = Vec3(values[j], values[j + 1], values[j + 2]);
        tri = incision::find_element_index(m, c, incision::kInvalid);
      } else {
        c = Vec3(values[j + 1], values[j + 2], values[j + 3]);
        tri = values[j] < 0 ? incision::kInvalid : static_cast<unsigned>(values[j]);
      }
      if (tri >= m.topology->triangles().size()) {
        msg_error(where(vl) + "point (" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " +
                  std::to_string(c[2]) + ") is in no triangle of the mesh; this incision is dropped");
        s->triangles.clear();
        s->barycoefs.clear();
        break;
      }
      s->triangles.push_back(tri);
      s->barycoefs.push_back(incision::triangle_barycoefs(m, tri, c));
    }
  }
  for (std::size_t i = 0; i < saved_.size(); ++i) {
    compute_coordinates(m, saved_[i]);
    if (i == 0 || saved_[i].coordinates.size() < 2 || saved_[i - 1].coordinates.empty()) continue;
    const double eps = 1e-5;
    bool equal = true;
    for (int j = 0; j < 3; ++j)
      equal &= std::fabs(saved_[i].coordinates.front()[j] - saved_[i - 1].coordinates.back()[j]) < eps;
    if (!equal) continue;
    const Vec3 moved = saved_[i].coordinates[0] + (saved_[i].coordinates[1] - saved_[i].coordinates[0]) * eps;
    const unsigned tri = incision::find_element_index(m, moved, incision::kInvalid);
    if (tri == incision::kInvalid) {
      msg_error(where(saved_[i].line) + "the moved first point of this incision is in no triangle");
      continue;
    }
    saved_[i].triangles[0] = tri;
    saved_[i].barycoefs[0] = incision::triangle_barycoefs(m, tri, moved);
    compute_coordinates(m, saved_[i]);
  }
}

// SOFA's updateTriangleIncisionInformation: after a cut, every saved point is located again
// (keeping its triangle when it still holds it) and its coefficients recomputed.
void TopologicalChangeProcessor::update_saved(const incision::Mesh& m) {
  for (SavedIncision& s : saved_)
    for (std::size_t j = 0; j < s.triangles.size(); ++j) {
      if (j >= s.coordinates.size()) break;
      const unsigned t = incision::find_element_index(m, s.coordinates[j], s.triangles[j]);
      if (t == incision::kInvalid) {
        msg_warning(where(s.line) + "a point of this incision is no longer in any triangle");
        break;
      }
      s.triangles[j] = t;
      s.barycoefs[j] = incision::triangle_barycoefs(m, t, s.coordinates[j]);
    }
}

void TopologicalChangeProcessor::incise_saved(double time) {
  incision::Mesh m;
  if (!incision_mesh(&m)) return;  // said at init
  SavedIncision* s = nullptr;
  for (auto& x : saved_)
    if (std::fabs(time - x.time) < 1e-10) s = &x;
  if (!s) {
    // SOFA logs this as an error and runs on; here an error would stop the run, so it is a warning.
    // It happens in SOFA's own scene: accumulated time drifts past T= by one step (2.1 is first
    // due at 2.11), and the saved times are matched within 1e-10.
    const SavedIncision* nearest = nullptr;
    for (const auto& x : saved_)
      if (!nearest || std::fabs(x.time - time) < std::fabs(nearest->time - time)) nearest = &x;
    std::ostringstream w;
    w.precision(17);
    w << "no saved incision at time " << time << " (" << saved_.size() << " saved";
    if (nearest) w << ", nearest T= " << nearest->time << " (" << filename.value() << ":" << nearest->line + 1 << ")";
    w << "); none made (SOFA: error, simulation goes on)";
    msg_warning(w.str());
    return;
  }
  for (auto& x : saved_) compute_coordinates(m, x);
  if (s->triangles.empty()) {
    msg_warning(where(s->line) + "this incision has no point (dropped at init); none made");
    return;
  }
  incise_points(m, s->line, s->triangles, s->coordinates, s);
}

void TopologicalChangeProcessor::incise_from_file(std::size_t line) {
  incision::Mesh m;
  if (!incision_mesh(&m)) {
    msg_error(where(line) + "INCISE= needs a Vec3 MechanicalObject and a TriangleSetTopologyModifier");
    return;
  }
  std::istringstream is(lines_[line]);
  std::string tok;
  std::size_t n = 0;
  is >> tok >> n;
  const std::vector<double> values = incise_values(line + 1, n);
  if (values.empty()) return;
  const bool only_coordinates = values.size() == 3 * n;
  std::vector<unsigned> tris;
  std::vector<Vec3> points;
  const std::size_t step = only_coordinates ? 3 : 4;
  for (std::size_t j = 0; j + step <= values.size() && points.size() < n; j += step) {
    if (only_coordinates) {
      points.emplace_back(values[j], values[j + 1], values[j + 2]);
    } else {
      tris.push_back(values[j] < 0 ? incision::kInvalid : static_cast<unsigned>(values[j]));
      points.emplace_back(values[j + 1], values[j + 2], values[j + 3]);
    }
  }
  incise_points(m, line, only_coordinates ? std::vector<unsigned>{} : tris, points, nullptr);
}

void TopologicalChangeProcessor::incise_points(incision::Mesh& m, std::size_t line, std::vector<unsigned> tris,
                                               const std::vector<Vec3>& points, SavedIncision* saved) {
  if (points.size() < 2) return;
  // Without triangles the points are located when used (after the previous cuts).
  auto triangle_of = [&](std::size_t i) {
    if (saved) return saved->triangles[i];
    if (!tris.empty()) return tris[i];
    return incision::find_element_index(m, points[i], incision::kInvalid);
  };
  unsigned ta = triangle_of(0);
  unsigned a_last = incision::kInvalid;
  Vec3 a = points[0];
  for (std::size_t i = 1; i < points.size(); ++i) {
    unsigned tb = triangle_of(i);
    const Vec3 b = points[i];
    if (a_last != incision::kInvalid) a = m.position(a_last);  // the previous cut's end, as it is now
    incision::Path path;
    std::string why;
    if (!incision::intersected_objects_list(m, a_last, a, b, ta, tb, path, &why)) {
      // SOFA: error, and the simulation goes on (a warning here: an error would stop the run).
      msg_warning(where(line) + "invalid incision path from point " + std::to_string(i - 1) + " to point " +
                std::to_string(i) + ": " + why);
      break;
    }
    std::vector<unsigned> new_edges;
    // SOFA passes the Data's epsilons with saved indices, fixed 0.1 and 0.25 otherwise.
    const double eps_path = saved ? epsilon_snap_path.value() : 0.1;
    const double eps_border = saved ? epsilon_snap_border.value() : 0.25;
    Vec3 b_end = b;
    if (incision::split_along_path(m, a_last, a, incision::kInvalid, b_end, path, new_edges, eps_path, eps_border,
                                   &why) < 0) {
      msg_warning(where(line) + "incision path not split: " + why);
      break;
    }
    std::vector<unsigned> new_points, end_points;
    bool reach_border = false;
    if (!incision::incise_along_edge_list(m, new_edges, new_points, end_points, reach_border, &why))
      msg_warning(where(line) + "incision not opened: " + why);
    if (!end_points.empty()) a_last = end_points.back();
    ta = tb;
    if (saved) {
      m.modifier->notify_ending_event();
      update_saved(m);
    }
  }
}

}  // namespace sinew
