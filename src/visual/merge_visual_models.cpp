// MergeVisualModels (SOFA's Sofa.GL.Component.Rendering3D): an OglModel whose
// geometry is the concatenation of `nb` input models (input1, input2, ...):
// positions, render vertices, texture coordinates and elements, the indices
// of each input shifted past those of the inputs before it. The inputs are
// read at init and after each step (SOFA's updateVisual), so a merged model
// follows inputs moved by mappings.
#include <string>
#include <vector>

#include "core/path.h"
#include "core/registry.h"
#include "core/value_text.h"
#include "visual/ogl_model.h"

namespace sinew {

namespace {

class MergeVisualModels final : public OglModel {
 public:
  Field<unsigned> nb{this, "nb", 1u, "number of input visual models to merge", "Visual"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override {
    OglModel::parse(attrs, diag);
    // input1 .. input<nb>: object links, SOFA's vector of links sized by `nb`.
    paths_.assign(nb.value(), {});
    for (unsigned i = 0; i < nb.value(); ++i)
      if (const std::string* p = attrs.take("input" + std::to_string(i + 1))) paths_[i] = *p;
  }

  void init() override {
    inputs_.clear();
    for (unsigned i = 0; i < paths_.size(); ++i) {
      const std::string& p = paths_[i];
      if (p.empty()) continue;  // SOFA skips an unset link
      std::string why;
      Base* b = node() ? resolve_object_path(*node(), this, p.substr(p.rfind('@') + 1),
                                             [](Base* x) { return dynamic_cast<OglModel*>(x) != nullptr; }, &why)
                       : nullptr;
      if (!b) {
        msg_error("input" + std::to_string(i + 1) + " " + quote_value(p) + " is not a visual model: " + why);
        set_state(ComponentState::invalid);
        return;
      }
      inputs_.push_back(static_cast<OglModel*>(b));
    }
    merge();
    OglModel::init();
  }

  void handle_event(Event& e) override {
    if (e.kind == Event::Kind::animate_end && state() == ComponentState::valid) merge_positions();
    OglModel::handle_event(e);
  }

 private:
  static std::size_t render_vertices(const OglModel& m) {
    return m.vertices.get().empty() ? m.visual_size() : m.vertices.get().size();
  }

  template <class Elem>
  static void append_shifted(std::vector<Elem>& out, const std::vector<Elem>& in, unsigned shift) {
    for (Elem e : in) {
      for (auto& i : e) i += shift;
      out.push_back(e);
    }
  }

  void merge() {
    std::vector<Vec3> vert;
    std::vector<Vec2> tex;
    std::vector<unsigned> pos_idx, norm_idx;
    std::vector<Edge> edg;
    std::vector<Triangle> tri;
    std::vector<Quad> qua;
    unsigned points = 0, positions = 0;
    for (const OglModel* m : inputs_) {
      vert.insert(vert.end(), m->vertices.get().begin(), m->vertices.get().end());
      tex.insert(tex.end(), m->texcoords.get().begin(), m->texcoords.get().end());
      for (unsigned i : m->vert_pos_idx.get()) pos_idx.push_back(i + positions);
      for (unsigned i : m->vert_norm_idx.get()) norm_idx.push_back(i + positions);
      append_shifted(edg, m->edges.get(), points);
      append_shifted(tri, m->triangles.get(), points);
      append_shifted(qua, m->quads.get(), points);
      points += static_cast<unsigned>(render_vertices(*m));
      positions += static_cast<unsigned>(m->visual_size());
    }
    vertices.set(std::move(vert));
    texcoords.set(std::move(tex));
    vert_pos_idx.set(std::move(pos_idx));
    vert_norm_idx.set(std::move(norm_idx));
    edges.set(std::move(edg));
    triangles.set(std::move(tri));
    quads.set(std::move(qua));
    merge_positions();
  }

  // Positions only: sizes are fixed after init, so this writes in place.
  void merge_positions() {
    std::size_t n = 0;
    for (const OglModel* m : inputs_) n += m->position.get().data.size();
    std::vector<double>& x = position.edit().data;
    x.resize(n);
    std::size_t at = 0;
    for (const OglModel* m : inputs_) {
      const std::vector<double>& in = m->position.get().data;
      std::copy(in.begin(), in.end(), x.begin() + static_cast<std::ptrdiff_t>(at));
      at += in.size();
    }
  }

  std::vector<std::string> paths_;
  std::vector<OglModel*> inputs_;
};

}  // namespace

void register_merge_visual_models(Registry& r) {
  ComponentInfo info;
  info.name = "MergeVisualModels";
  info.category = "Visual";
  info.description = "visual model concatenating the geometry of several visual models";
  info.create = creator<MergeVisualModels>();
  r.add(std::move(info));
}

}  // namespace sinew
