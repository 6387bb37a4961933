#include "scene/builder.h"

#include <cstdlib>
#include <set>
#include <sstream>

#include "core/engine.h"
#include "core/path.h"
#include "core/value_text.h"
#include "core/registry.h"

namespace sinew::scene {

bool is_known_component(std::string_view tag) { return registry().find(renamed_component(tag)) != nullptr; }

namespace {

// Node attributes that only configure a viewer (deprecated display flags).
bool is_viewer_node_attribute(std::string_view a) {
  static const std::set<std::string, std::less<>> names = {
      "showVisualModels", "showBehaviorModels", "showCollisionModels", "showBoundingCollisionModels",
      "showMappings",     "showMechanicalMappings", "showForceFields", "showInteractionForceFields",
      "showWireFrame",    "showNormals",          "showAll",          "showVisual",
      "showBehavior",     "showCollision",        "showProcessorColor", "multiThreadSimulation"};
  return names.count(a) > 0;
}

std::string suggestion_text(const std::vector<std::string>& names) {
  if (names.empty()) return {};
  std::string s = " (did you mean ";
  for (std::size_t i = 0; i < names.size(); ++i) s += (i ? ", '" : "'") + names[i] + "'";
  return s + "?)";
}

class Builder {
 public:
  Builder(const ResourcePaths& paths, LoadedScene& out) : paths_(paths), out_(out) {}

  void build(const Element& e) {
    out_.root = std::make_unique<Node>();
    out_.root->where = e.where;
    diag_ = &out_.root->diagnostics();
    build_node(e, *out_.root);
    resolve_pending_links();
    report_link_cycles();
  }

  Diagnostics* diag_ = nullptr;

 private:
  void build_node(const Element& e, Node& node) {
    for (const auto& [key, value] : e.attributes) {
      if (BaseField* f = node.find_field(key)) {
        const bool read_ok = f->read(value);
        if (const std::string count = value_count_problem(*f, value); !count.empty())
          diag_->warning(e.where, "node '" + std::string(e.name()) + "': field '" + key + "': " + count + ": " +
                                      quote_value(value));
        else if (!read_ok && !value.empty())
          diag_->warning(e.where, "could not read value for node field '" + key + "': " + quote_value(value));
      } else if (is_viewer_node_attribute(key)) {
        // Display flags only matter to a viewer.
      } else if (!(key.rfind("_", 0) == 0 || key.rfind("NO", 0) == 0)) {
        std::vector<std::string> names;
        for (BaseField* f : node.fields()) names.push_back(f->name());
        diag_->warning(e.where, "unused attribute '" + key + "' on node '" + std::string(e.name()) + "'" +
                                    suggestion_text(closest_names(key, names)));
      }
    }
    for (const Element& child : e.children) {
      if (child.is_node) {
        auto n = std::make_unique<Node>();
        n->where = child.where;
        Node* raw = node.add_child(std::move(n));
        build_node(child, *raw);
      } else {
        build_object(child, node);
      }
    }
  }

  void build_object(const Element& e, Node& node) {
    AttributeMap attrs;
    for (const auto& [k, v] : e.attributes) attrs.set(k, v);
    const std::string* tmpl = attrs.peek("template");
    Registry::Created created = registry().create(e.tag, tmpl ? *tmpl : std::string_view{}, node, attrs);
    for (const auto& w : created.warnings) diag_->warning(e.where, "'" + e.tag + "': " + w);
    if (!created.component) {
      std::string text = "unknown component '" + e.tag + "'";
      if (registry().find(renamed_component(e.tag))) {
        text = "cannot create '" + e.tag + "'";
      } else {
        text += suggestion_text(closest_names(e.tag, registry().names()));
        out_.missing.push_back({e.tag, e.where});
      }
      diag_->error(e.where, text);
      for (std::size_t i = 1; i < created.errors.size(); ++i) diag_->error(e.where, created.errors[i]);
      return;
    }
    for (const auto& err : created.errors) diag_->error(e.where, "'" + e.tag + "': " + err);
    const ComponentInfo* info = registry().find(renamed_component(e.tag));
    // Type, location and name before insertion, so that messages raised by the
    // insertion itself (a single slot taken over) and while parsing name the
    // component; unnamed objects are ClassName1, ClassName2, ... per node (trap T17).
    Component* c = created.component.get();
    c->set_type(info->name, created.used_template);
    c->where = e.where;
    const std::string* given = attrs.peek("name");
    if (given && !given->empty()) c->name.set(*given);
    else c->name.set(info->name + std::to_string(node.next_default_index(info->name)));
    if (!node.add_object(std::move(created.component))) return;
    if (const std::string* src = attrs.take("src")) apply_src(*c, node, *src, attrs, e);
    c->parse(attrs, *diag_);
    if (c->name.value().empty()) c->name.set(info->name + std::to_string(node.next_default_index(info->name)));

    // Unread attributes: SOFA warns ("Unused attribute"), except names starting with '_' or 'NO'.
    if (!c->accepts_any_attribute())
      for (const auto& [key, entry] : attrs.entries()) {
        if (entry.used || key.rfind("_", 0) == 0 || key.rfind("NO", 0) == 0) continue;
        std::vector<std::string> names;
        for (BaseField* f : c->fields()) names.push_back(f->name());
        for (BaseLink* l : c->links()) names.push_back(l->name());
        diag_->warning(e.where, c->describe() + ": unused attribute '" + key + "' = " + quote_value(entry.value) +
                                    suggestion_text(closest_names(key, names)));
      }

    for (BaseField* f : c->fields()) {
      if (f->is_file() && f->is_set() && f->link_path().empty()) resolve_file(*c, *f, e);
      if (!f->link_path().empty() && !try_field_link(*c, *f)) pending_.push_back({c, f});
    }
  }

  void apply_src(Component& c, Node& node, const std::string& src, const AttributeMap& attrs, const Element& e) {
    if (src.empty() || src[0] != '@') {
      diag_->error(e.where, c.describe() + ": src must start with '@' (" + quote_value(src) + ")");
      return;
    }
    if (src == "@") {
      diag_->warning(e.where, c.describe() + ": empty src ignored");
      return;
    }
    std::string why;
    Base* target = resolve_object_path(node, &c, src.substr(src.rfind('@') + 1),
                                       [](Base* b) { return dynamic_cast<Component*>(b) != nullptr; }, &why);
    if (!target) {
      diag_->error(e.where, c.describe() + ": source object " + quote_value(src) + " not found: " + why);
      return;
    }
    for (BaseField* from : target->fields()) {
      if (!from->autolink() || from->name() == "type" || from->name() == "filename" || from->name() == "name")
        continue;
      std::vector<std::string> names{from->name()};
      names.insert(names.end(), from->aliases().begin(), from->aliases().end());
      for (const auto& n : names) {
        if (attrs.peek(n)) continue;  // given explicitly on the element
        BaseField* to = c.find_field(n);
        if (to && to->autolink() && to != from) {
          to->set_parent(from);
          break;
        }
      }
    }
  }

  void resolve_file(Component& c, BaseField& f, const Element& e) {
    std::string value = f.text();
    if (value.empty()) return;
    if (auto found = paths_.resolve(value, e.base_dir)) {
      f.read(*found);
    } else if (f.file_required()) {
      diag_->error(e.where, c.describe() + ": file not found: " + quote_value(value) + " (searched " + e.base_dir +
                                " and the data paths)");
    }
  }

  bool try_field_link(Component& c, BaseField& f, std::string* why = nullptr) {
    BaseField* parent = resolve_field_link(*c.node(), &c, f.link_path(), why);
    if (!parent) return false;
    if (parent == &f) {
      if (why) *why = "a field cannot be linked to itself";
      return false;
    }
    f.set_parent(parent);
    f.set_link_path({});
    return true;
  }

  void resolve_pending_links() {
    // Data links to objects declared later, then object links (SOFA's UpdateLinks).
    // SOFA warns about a data link it cannot resolve and goes on with the field unset (its
    // default, and components then fall back as for an absent attribute); some of SOFA's own
    // examples hold such links, so Sinew does the same, loudly.
    for (auto& [c, f] : pending_) {
      std::string why;
      if (try_field_link(*c, *f, &why)) continue;
      diag_->warning(c->where, c->describe() + ": cannot resolve link " + f->name() + "=" +
                                   quote_value(f->link_path()) + ": " + why + "; '" + f->name() +
                                   "' keeps its default, as if not given (as in SOFA)");
      f->set_link_path({});
      f->unset();
    }
    for_each_node(*out_.root, [&](Node& n) {
      for (auto& o : n.objects())
        for (BaseLink* l : o->links()) {
          if (!l->is_set()) continue;
          std::string why;
          std::string path = l->path();
          if (l->is_multi()) {  // several whitespace-separated paths
            l->clear_targets();
            std::istringstream tokens(path);
            for (std::string p; tokens >> p;) {
              std::string w;
              Base* t = resolve_object_path(n, o.get(), p, [l](Base* b) { return l->accept(b); }, &w);
              if (t) l->add_target(t);
              else
                diag_->error(o->where, o->describe() + ": cannot resolve link " + l->name() + "=" + quote_value(p) +
                                           ": " + (w.empty() ? "wrong type" : w));
            }
            continue;
          }
          // Single links: one path.
          Base* t = resolve_object_path(n, o.get(), path, [l](Base* b) { return l->accept(b); }, &why);
          if (!t || !l->accept(t))
            diag_->error(o->where, o->describe() + ": cannot resolve link " + l->name() + "=" + quote_value(path) +
                                       ": " + (why.empty() ? "wrong type" : why));
        }
    });
  }

  // Data links (and engines whose outputs feed their own inputs) that form a
  // cycle: no value can be computed; the scene is refused.
  void report_link_cycles() {
    std::vector<const BaseField*> all;
    for_each_node(*out_.root, [&](Node& n) {
      for (const BaseField* f : n.fields()) all.push_back(f);
      for (auto& o : n.objects())
        for (const BaseField* f : o->fields()) all.push_back(f);
    });
    for (const auto& cycle : find_field_cycles(all)) {
      const Base* first = cycle.front()->owner();
      diag_->error(first ? first->where : SourceLocation{},
                   "link cycle (each takes its value from the next): " + describe_field_cycle(cycle));
    }
  }

  const ResourcePaths& paths_;
  LoadedScene& out_;
  std::vector<std::pair<Component*, BaseField*>> pending_;
};

}  // namespace

LoadedScene build_scene(const Element& root, const ResourcePaths& paths) {
  LoadedScene out;
  out.file = root.where.file;
  Builder b(paths, out);
  b.build(root);
  // Components that write next to the data (SOFA's DataRepository first path) read them at init.
  if (out.root) out.root->data_dirs = paths.dirs();
  return out;
}

LoadedScene load_scene(const std::string& path, const LoadOptions& options, Diagnostics& diag_if_no_root) {
  ResourcePaths paths;
  for (const auto& d : options.data_paths) paths.add(d);
  if (options.use_sofa_data_path) paths.add_from_env();
  Diagnostics tree_diag;
  auto tree = load_scene_tree(path, paths, is_known_component, tree_diag);
  if (!tree) {
    for (const auto& m : tree_diag.messages()) diag_if_no_root.add(m.severity, m.where, m.who, m.text);
    LoadedScene out;
    out.file = path;
    return out;
  }
  LoadedScene out = build_scene(*tree, paths);
  out.file = path;
  // Messages from reading the XML come first.
  Diagnostics merged;
  for (const auto& m : tree_diag.messages()) merged.add(m.severity, m.where, m.who, m.text);
  for (const auto& m : out.root->diagnostics().messages()) merged.add(m.severity, m.where, m.who, m.text);
  out.root->diagnostics() = std::move(merged);
  return out;
}

}  // namespace sinew::scene
