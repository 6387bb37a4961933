// TopologicalChangeProcessor (spec/interaction.md §7.4): replays a list of
// topological changes read from a file (plain or gzip) at the times it gives.
//
// At every AnimateBeginEvent, with t = time + shift, lines are read while the
// current block is due (time ≤ t up to machine epsilon); a `T=` line that is
// due discards what was collected, so only the last due block runs. Then each
// `REMOVE= n` line with its index line calls removeItems on the first topology
// modifier found from the topology's node upwards; an `ADD= Kind n [Ancestor(s)
// a1 … an]` line with its vertex line adds n elements through the first modifier
// of that kind found the same way: Edge(s) → addEdges, Triangle(s) →
// addTriangles (one ancestor per triangle when given), Quad(s) → addQuads,
// Tetrahedron/Tetrahedra → addTetrahedra, Hexahedron/Hexahedra → addHexahedra.
// `ADD= PointInTriangle(s) n` adds points interpolated in triangles (addPoints
// with ancestors and coefficients). With `useDataInputs` the file is not read:
// the *ToRemove lists are removed once time passes timeToRemove (then every
// `interval`).
// `INCISE= n` with its line of n points ("triangle x y z" or "x y z" each) cuts
// the triangle surface along the polyline they make (SOFA's incision: split along
// the path, then the path's points duplicated), with saveIndicesAtInit as SOFA.
// The path snaps onto close vertices and the border (epsilonSnapPath, epsilonSnapBorder).
// Refused at init with an error naming file:line: malformed ADD= lines (count,
// vertex line, missing modifier) and malformed INCISE= blocks.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/roles.h"
#include "math/types.h"

namespace sinew {

class PointSetTopologyModifier;
namespace incision {
struct Mesh;
}

class TopologicalChangeProcessor : public Component {
 public:
  TopologicalChangeProcessor();

  Field<std::string> filename{this, "filename", "", "input file name for topological changes", "Changes"};
  Field<std::vector<double>> list_changes{this, "listChanges", {}, "0 for adding, 1 for removing, 2 for cutting and associated indices (unused, as in SOFA)", "Changes"};
  Field<double> interval{this, "interval", 0.0, "time duration between 2 actions (useDataInputs)", "Changes", "time"};
  Field<double> shift{this, "shift", 0.0, "shift between times in the file and times when they are read", "Changes", "time"};
  Field<bool> loop{this, "loop", false, "re-read the file when reaching its end", "Changes"};
  Field<bool> use_data_inputs{this, "useDataInputs", false, "remove the elements of the Data lists at timeToRemove instead of reading the file", "Changes"};
  Field<double> time_to_remove{this, "timeToRemove", 0.0, "useDataInputs: time of the removals", "Changes", "time"};
  Field<std::vector<unsigned>> points_to_remove{this, "pointsToRemove", {}, "point ids to remove (useDataInputs)", "Changes"};
  Field<std::vector<unsigned>> edges_to_remove{this, "edgesToRemove", {}, "edge ids to remove (useDataInputs)", "Changes"};
  Field<std::vector<unsigned>> triangles_to_remove{this, "trianglesToRemove", {}, "triangle ids to remove (useDataInputs)", "Changes"};
  Field<std::vector<unsigned>> quads_to_remove{this, "quadsToRemove", {}, "quad ids to remove (useDataInputs)", "Changes"};
  Field<std::vector<unsigned>> tetrahedra_to_remove{this, "tetrahedraToRemove", {}, "tetrahedron ids to remove (useDataInputs)", "Changes"};
  Field<std::vector<unsigned>> hexahedra_to_remove{this, "hexahedraToRemove", {}, "hexahedron ids to remove (useDataInputs)", "Changes"};
  Field<bool> save_indices_at_init{this, "saveIndicesAtInit", false, "save the incision indices at init (INCISE)", "Changes"};
  Field<double> epsilon_snap_path{this, "epsilonSnapPath", 0.1, "epsilon snap path (INCISE)", "Changes"};
  Field<double> epsilon_snap_border{this, "epsilonSnapBorder", 0.25, "epsilon snap border (INCISE)", "Changes"};
  Field<bool> draw{this, "draw", false, "draw information (viewer)", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "link to the topology container (default: the node's)"};

  void init() override;
  void reinit() override { init(); }
  void handle_event(Event& e) override;
  bool wants_events() const override { return true; }

  // One step's work (public for tests): reads the blocks due at `t` and applies them.
  void process(double t);
  // useDataInputs (SOFA's processTopologicalChanges(time)): once time > timeToRemove, the listed
  // hexahedra, tetrahedra, quads, triangles, edges then points are removed (removeItems of the
  // first modifier of that kind from the topology's node upwards); timeToRemove then advances
  // by `interval`, or to 2^32 − 1 (never again) when interval is 0. Public for tests.
  void process_data_inputs(double time);

  // The element kinds an ADD= line adds.
  enum class AddKind { edge, triangle, quad, tetrahedron, hexahedron };

 private:
  // SOFA's readNext: the lines of the last due block (T= lines included).
  std::vector<std::size_t> read_due(double t);
  std::string where(std::size_t line) const;
  // One ADD= line (at `line`) with its vertex line (the next one).
  struct AddCommand {
    AddKind kind = AddKind::edge;
    unsigned arity = 0;              // vertices per element: 2, 3, 4 or 8
    std::vector<unsigned> vertices;  // n * arity
    std::vector<std::vector<unsigned>> ancestors;  // empty, or one row per element
    PointSetTopologyModifier* modifier = nullptr;  // of the kind's modifier class
  };
  // Parses and checks it; false with `why` (without the file:line prefix) when refused.
  bool parse_add(std::size_t line, AddCommand* out, std::string* why) const;
  void apply_add(const AddCommand& a);

  // `ADD= PointInTriangle(s) n` with its line "t b0 b1" × n: n points, each interpolated from the
  // vertices of triangle t with coefficients (b0, b1, 1 − b0 − b1), added with their DoFs through
  // the TriangleSetTopologyModifier. Parsed (and checked) at init; triangles are checked when applied.
  struct PointsInTriangle {
    std::vector<unsigned> triangles;
    std::vector<std::array<double, 2>> bary;
  };
  static bool is_points_in_triangle(const std::string& line);
  bool parse_points_in_triangle(std::size_t line, PointsInTriangle* out, std::string* why) const;
  void apply_points_in_triangle(std::size_t line, const PointsInTriangle& p);

  // `INCISE= n` with its line of points: checked at init (SOFA's value-count rules).
  bool check_incise(std::size_t line, std::string* why);
  std::size_t incisions_ = 0;

  // Incisions (topological_change_processor_incise.cpp, SOFA's INCISE= branch). With
  // saveIndicesAtInit the points of every INCISE= block are located at init (triangle and
  // barycentric coefficients, SOFA's saveIndices) and the cut due at time t is the block whose
  // T= equals t within 1e-10 (inciseWithSavedIndices); otherwise the block's points are read
  // when due. Each pair of consecutive points is one cut: path, split, incision (triangle_incision.h).
  struct SavedIncision {
    double time = 0;
    std::size_t line = 0;  // of its INCISE= line (messages)
    std::vector<unsigned> triangles;
    std::vector<Vec3> barycoefs;
    std::vector<Vec3> coordinates;  // from the triangles' current positions (computeCoordinates)
  };
  std::vector<SavedIncision> saved_;
  bool incision_mesh(incision::Mesh* m) const;
  // SOFA's getValuesInLine: the numbers of the line (empty, with an error, when too few).
  std::vector<double> incise_values(std::size_t line, std::size_t n);
  void save_incisions();
  void compute_coordinates(const incision::Mesh& m, SavedIncision& s) const;
  void incise_saved(double time);
  void incise_from_file(std::size_t line);
  // One cut per pair of consecutive points; `saved`: SOFA's inciseWithSavedIndices (ending event
  // and saved triangles updated after each cut).
  void incise_points(incision::Mesh& m, std::size_t line, std::vector<unsigned> triangles,
                     const std::vector<Vec3>& points, SavedIncision* saved);
  void update_saved(const incision::Mesh& m);

  std::vector<std::string> lines_;  // as getline returns them; the last one reaches end of file
  std::size_t next_ = 0;            // next line to read
  std::string cmd_;                 // first token of the last non-blank line (kept on blank lines, as a stream read)
  double next_time_ = 0, loop_time_ = 0;
  PointSetTopologyModifier* modifier_ = nullptr;
};

}  // namespace sinew
