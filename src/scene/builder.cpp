#include "scene/builder.h"

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <map>
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

void apply_src(Component& c, Node& node, const std::string& src, const AttributeMap& attrs, const SourceLocation& where,
               Diagnostics& diag) {
  if (src.empty() || src[0] != '@') {
    diag.error(where, c.describe() + ": src must start with '@' (" + quote_value(src) + ")");
    return;
  }
  if (src == "@") {
    diag.warning(where, c.describe() + ": empty src ignored");
    return;
  }
  std::string why;
  Base* target = resolve_object_path(node, &c, src.substr(src.rfind('@') + 1),
                                     [](Base* b) { return dynamic_cast<Component*>(b) != nullptr; }, &why);
  if (!target) {
    diag.error(where, c.describe() + ": source object " + quote_value(src) + " not found: " + why);
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

void resolve_file(Component& c, BaseField& f, const ObjectSpec& spec, const ResourcePaths& paths, Diagnostics& diag) {
  // A list of files (OglShader's fileVertexShaders): each name resolves on its own.
  if (auto* list = dynamic_cast<Field<std::vector<std::string>>*>(&f)) {
    std::vector<std::string> names = list->value();
    for (std::string& n : names) {
      if (auto found = paths.resolve(n, spec.base_dir)) n = *found;
      else if (f.file_required())
        diag.error(spec.where, c.describe() + ": file not found: " + quote_value(n) + " (searched " + spec.base_dir +
                                   " and the data paths)");
    }
    list->set(std::move(names));
    return;
  }
  std::string value = f.text();
  if (value.empty()) return;
  if (auto found = paths.resolve(value, spec.base_dir)) {
    f.read(*found);
  } else if (f.file_required()) {
    diag.error(spec.where, c.describe() + ": file not found: " + quote_value(value) + " (searched " + spec.base_dir +
                               " and the data paths)");
  }
}

// A data link whose target exists already is made at once; the others wait
// for resolve_pending_links (end of the file, or init).
void try_field_link(Component& c, BaseField& f) {
  BaseField* parent = resolve_field_link(*c.node(), &c, f.link_path());
  if (!parent || parent == &f) return;
  f.set_parent(parent);
  f.set_link_path({});
}

std::string default_name(Node& node, const std::string& cls, DefaultNames naming) {
  // SOFA's XML convention numbers unnamed objects per class and node (trap T17);
  // SofaPython3's gives the bare class name.
  return naming == DefaultNames::python ? cls : cls + std::to_string(node.next_default_index(cls));
}

class Builder {
 public:
  Builder(const ResourcePaths& paths, LoadedScene& out) : paths_(paths), out_(out) {}

  void build(const Element& e) {
    out_.root = std::make_unique<Node>();
    out_.root->where = e.where;
    diag_ = &out_.root->diagnostics();
    build_node(e, *out_.root);
    resolve_pending_links(*out_.root, *diag_);
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
    ObjectSpec spec;
    spec.type = e.tag;
    for (const auto& [k, v] : e.attributes) spec.attributes.set(k, v);
    spec.where = e.where;
    spec.base_dir = e.base_dir;
    Component* c = add_object(node, spec, paths_, *diag_, &out_.missing);
    if (c && c->class_name() == "AddDataRepository") add_data_repository(*c, spec);
  }

  // SOFA's AddDataRepository adds its folder to the data paths as it is parsed,
  // so the files named after it in the scene are also searched there. A
  // relative folder is taken from the scene file's folder (SOFA loads a file
  // from its own directory). The field is rewritten with the absolute path, as SOFA does.
  void add_data_repository(Component& c, const ObjectSpec& spec) {
    BaseField* f = c.find_field("path");
    if (!f) return;
    std::string dir = f->text();
    if (dir.empty()) {
      diag_->error(spec.where, c.describe() + ": 'path' is empty: no folder added to the data paths");
      return;
    }
    if (dir.front() != '/') dir = spec.base_dir + "/" + dir;
    dir = absolute_normal(dir);
    std::error_code ec;
    if (!std::filesystem::exists(dir, ec)) {
      diag_->error(spec.where, c.describe() + ": " + dir + " does not exist: not added to the data paths");
      return;
    }
    if (!std::filesystem::is_directory(dir, ec)) {
      diag_->error(spec.where, c.describe() + ": " + dir + " is not a folder: not added to the data paths");
      return;
    }
    f->read(dir);
    paths_.add(dir);
  }

 public:
  const ResourcePaths& paths() const { return paths_; }

 private:

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

  ResourcePaths paths_;  // a copy: AddDataRepository extends it while the scene is built
  LoadedScene& out_;
};

}  // namespace

Component* add_object(Node& node, ObjectSpec& spec, const ResourcePaths& paths, Diagnostics& diag,
                      std::vector<MissingComponent>* missing) {
  AttributeMap& attrs = spec.attributes;
  const std::string& type = spec.type;
  const std::string* tmpl = attrs.peek("template");
  Registry::Created created = registry().create(type, tmpl ? *tmpl : std::string_view{}, node, attrs);
  for (const auto& w : created.warnings) diag.warning(spec.where, "'" + type + "': " + w);
  if (!created.component) {
    std::string text = "unknown component '" + type + "'";
    if (registry().find(renamed_component(type))) {
      text = "cannot create '" + type + "'";
    } else {
      text += suggestion_text(closest_names(type, registry().names()));
      if (missing) missing->push_back({type, spec.where});
    }
    diag.error(spec.where, text);
    for (std::size_t i = 1; i < created.errors.size(); ++i) diag.error(spec.where, created.errors[i]);
    return nullptr;
  }
  for (const auto& err : created.errors) diag.error(spec.where, "'" + type + "': " + err);
  const ComponentInfo* info = registry().find(renamed_component(type));
  // Type, location and name before insertion, so that messages raised by the
  // insertion itself (a single slot taken over) and while parsing name the component.
  Component* c = created.component.get();
  c->set_type(info->name, created.used_template);
  c->where = spec.where;
  const std::string* given = attrs.peek("name");
  if (given && !given->empty()) c->name.set(*given);
  else c->name.set(default_name(node, info->name, spec.names));
  if (!node.add_object(std::move(created.component))) return nullptr;
  if (const std::string* src = attrs.take("src")) apply_src(*c, node, *src, attrs, spec.where, diag);
  c->parse(attrs, diag);
  if (c->name.value().empty()) c->name.set(default_name(node, info->name, spec.names));

  // Unread attributes: SOFA warns ("Unused attribute"), except names starting with '_' or 'NO'.
  spec.unused.clear();
  if (!c->accepts_any_attribute())
    for (const auto& [key, entry] : attrs.entries()) {
      if (entry.used || key.rfind("_", 0) == 0 || key.rfind("NO", 0) == 0) continue;
      std::vector<std::string> names;
      for (BaseField* f : c->fields()) names.push_back(f->name());
      for (BaseLink* l : c->links()) names.push_back(l->name());
      std::string text = "unused attribute '" + key + "' = " + quote_value(entry.value) +
                         suggestion_text(closest_names(key, names));
      if (spec.report_unused) diag.warning(spec.where, c->describe() + ": " + text);
      spec.unused.push_back(std::move(text));
    }

  for (BaseField* f : c->fields()) {
    if (f->is_file() && f->is_set() && f->link_path().empty()) resolve_file(*c, *f, spec, paths, diag);
    if (!f->link_path().empty()) try_field_link(*c, *f);
  }
  return c;
}

LoadedScene build_scene(const Element& root, const ResourcePaths& paths) {
  LoadedScene out;
  out.file = root.where.file;
  Builder b(paths, out);
  b.build(root);
  // Components that write next to the data (SOFA's DataRepository first path) read them at init.
  if (out.root) out.root->data_dirs = b.paths().dirs();
  return out;
}

namespace {
std::map<std::string, SceneFileLoader>& scene_loaders() {
  static std::map<std::string, SceneFileLoader> loaders;
  return loaders;
}
}  // namespace

void register_scene_loader(const std::string& extension, SceneFileLoader loader) {
  scene_loaders()[extension] = loader;
}

LoadedScene load_scene(const std::string& path, const LoadOptions& options, Diagnostics& diag_if_no_root) {
  if (const auto dot = path.find_last_of('.'); dot != std::string::npos && path.find('/', dot) == std::string::npos) {
    std::string ext = path.substr(dot);
    for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (auto it = scene_loaders().find(ext); it != scene_loaders().end()) return it->second(path, options, diag_if_no_root);
  }
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
