// Second half of scene loading: element tree → nodes and components.
//
// Creates every component through the registry in document order, inserts
// it in its node before parsing its attributes (so links to earlier objects
// resolve at once), names unnamed objects ClassName1, ClassName2, ... per
// node, resolves resource files, data links and object links, and reports
// every problem as file:line with spelling suggestions. Loading goes on past
// bad elements; the scene is refused when any error was reported.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/node.h"
#include "scene/resource_paths.h"
#include "scene/xml_tree.h"

namespace sinew::scene {

struct MissingComponent {
  std::string type;
  SourceLocation where;
};

struct LoadOptions {
  std::vector<std::string> data_paths;  // searched after the scene's folder, in order
  bool use_sofa_data_path = true;       // also honour $SOFA_DATA_PATH
  std::vector<std::string> script_args; // a Python scene's sys.argv[1:] (runSofa's --argv)
};

struct LoadedScene {
  std::unique_ptr<Node> root;                 // null when the file could not be read at all
  std::vector<MissingComponent> missing;      // components Sinew does not implement (yet)
  std::string file;
  Diagnostics& diagnostics() { return root->diagnostics(); }
  bool ok() const { return root && !root->diagnostics().has_errors(); }
};

// How unnamed objects are named: SOFA's XML numbers them per class and node
// ("MechanicalObject1"), SofaPython3 gives the class name.
enum class DefaultNames { xml, python };

// One component to create from attribute text, as an XML element describes it.
struct ObjectSpec {
  std::string type;            // class name or alias
  AttributeMap attributes;     // name → text (SOFA's syntax, links as "@path")
  SourceLocation where;        // for messages
  std::string base_dir;        // folder relative file names start from
  DefaultNames names = DefaultNames::xml;
  bool report_unused = true;   // warn about attributes the component did not read
  std::vector<std::string> unused;  // out: those attributes, described with a suggestion
};

// Creates `spec.type` in `node` as the XML loader does: registry and template
// choice, default name, insertion, `src=`, attribute parsing, resource files,
// data links to fields that exist already (the others are resolved later by
// resolve_pending_links). Returns nullptr after reporting why to `diag`;
// unknown types are also appended to `missing`.
Component* add_object(Node& node, ObjectSpec& spec, const ResourcePaths& paths, Diagnostics& diag,
                      std::vector<MissingComponent>* missing = nullptr);

// Loads and builds (does not initialise). Messages from reading the XML and
// building go to the root's diagnostics (or to `diag_if_no_root` when there is no root).
LoadedScene load_scene(const std::string& path, const LoadOptions& options, Diagnostics& diag_if_no_root);

// Loaders of other scene formats, chosen by file extension (lower case, with
// the dot). The Python front end registers ".py", ".py3", ".pyscn", ".py3scn".
using SceneFileLoader = LoadedScene (*)(const std::string& path, const LoadOptions& options, Diagnostics& diag);
void register_scene_loader(const std::string& extension, SceneFileLoader loader);

// Builds a graph from an element tree.
LoadedScene build_scene(const Element& root, const ResourcePaths& paths);

// Whether the registry knows a tag (class names, aliases, renamed classes).
bool is_known_component(std::string_view tag);

}  // namespace sinew::scene
