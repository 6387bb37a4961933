// First half of SOFA `.scn` loading: XML text → element tree.
//
// The tree produced here is what SOFA calls the "element tree" (framework.md §1.1,
// §1.2 step 1): no component exists yet. Everything that is purely textual is already
// done when these functions return:
//   * `<Object type="X" .../>` is normalised to an element with tag X;
//   * `<include href=.../>` elements and XML macro objects (`<BoxConstraint .../>`
//     backed by `Objects/BoxConstraint.xml`) are expanded, including the `Group` /
//     `_Group_` splice, the `_Merge_` merge, `name` renaming and replacement attributes
//     (framework.md §1.5, §1.6);
//   * legacy `<Attribute type="a"><Data value="v"/></Attribute>` children are folded
//     into attribute a="v" of the enclosing component;
//   * comments and text are dropped.
// What remains for the scene builder: turning each element into a Node or a component
// (factory lookup, renamed classes, templates, unused-attribute warnings, default
// names) and resolving resource names with ResourcePaths::resolve(name, e.base_dir).
//
// Error handling: nothing throws. Every problem becomes a Message in the Diagnostics
// given by the caller, with the file and line it comes from. Problems in part of the
// document (a bad include, a dropped element) are reported and loading goes on, so a
// single run reports as many problems as possible; the caller refuses the scene when
// `diag.has_errors()`. Only an unreadable or malformed main document, or a root that is
// not `<Node>`, makes the functions return nullopt.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/diagnostics.h"
#include "scene/resource_paths.h"

namespace sinew::scene {

// One element of the expanded scene tree: a Node or a component description.
struct Element {
  // "Node" for nodes; otherwise the component class name as written in the scene
  // (`<Object type="X">` gives tag X). Renamed/aliased class names are NOT mapped
  // here: that is the factory's job.
  std::string tag;
  bool is_node = false;

  // Every XML attribute in document order, values verbatim (XML entities decoded),
  // except the consumed ones: `type` (class name of `<Object>`; on `<Node>` it is
  // consumed too, as SOFA does). `name` is kept as an ordinary attribute. Include
  // replacement values and legacy <Attribute> values are already applied; an
  // attribute added by them (legacy form, `_Merge_`, include `name` on a root
  // without one) is appended, except `name`, which is inserted first.
  std::vector<std::pair<std::string, std::string>> attributes;

  // Child nodes and components, in document order, includes expanded in place.
  // Components never have children (SOFA cannot create nested components; they are
  // dropped with a message).
  std::vector<Element> children;

  // File (absolute, normalised path; for parse_scene_tree the virtual path as given)
  // and 1-based line of the element's start tag. Elements coming from an included
  // file report that file.
  SourceLocation where;

  // Folder against which this element's relative resource names resolve
  // (regression-protocol §8): the folder of the file that contains the element,
  // except for elements moved out of an included `Group`/`_Group_`/`_Merge_` root,
  // which resolve against the folder of the file that contains the include.
  // Absolute and normalised; pass it to ResourcePaths::resolve.
  std::string base_dir;

  // Value of attribute `name`, or nullptr when absent. The pointer is valid until
  // `attributes` is modified.
  const std::string* find(std::string_view name) const;

  // Value of the `name` attribute, or "" when absent (SOFA's default for nodes; the
  // builder chooses default component names).
  std::string_view name() const;

  // Sets attribute `name` to `value`: in place when present, appended otherwise.
  void set(std::string_view name, std::string value);
};

// Tells whether a tag names a component the factory can create (class names and
// registered aliases, including renamed classes). Only consulted for tags that are
// not keywords (Node, Object, include, Attribute, Data): an unknown tag is looked up
// as an XML macro before being kept as is.
using KnownTypePredicate = std::function<bool(std::string_view)>;

// Loads the scene file at `path` (relative paths are taken from the current
// directory) into an element tree.
//
// Rules (framework.md §1.1, §1.5, §1.6):
//  * The document root must be `<Node>`; otherwise an error and nullopt.
//  * A non-keyword tag with a `type` attribute cannot be created: it is dropped (with
//    its content) and an info message is reported, as SOFA does.
//  * A component tag T with `is_known_type(T) == false` is looked up as the macro file
//    `Objects/T.xml` (relative to the folder of the file containing the element, then
//    the data folders of `paths`); if found it is expanded as
//    `<include href="Objects/T.xml" .../>` with the element's other attributes (name
//    included) as include attributes; if not found the element is kept unchanged so
//    that the builder can report the unknown class with suggestions.
//  * `<include href="f" name="N" a="v" X__b="w"/>`: `f` is resolved against the
//    folder of the including file, then the data folders. Missing/empty href, a file
//    that cannot be found or parsed, or an include cycle is an error at the include's
//    file:line and the include is skipped. `name` renames the included root; then a
//    root named `Group`/`_Group_` has its children spliced in place of the include,
//    `_Merge_` has its attributes (except name) copied onto the including element and
//    its children merged (same tag and same non-empty name → merged recursively,
//    others appended); any other root becomes a normal child. `a="v"` overwrites `a`
//    on every component of the included tree that already has `a`; `X__b="w"` only on
//    components named X. Nodes are never changed by replacement attributes (SOFA
//    applies them when creating components only). Attributes are processed in
//    document order, so a later replacement wins over an earlier one; an outer
//    include's replacements win over an inner include's.
//  * `<Attribute type="a"><Data value="v"/></Attribute>` inside a component sets a="v"
//    on that component (the last Data child wins; no Data child sets ""). Elsewhere
//    it has no effect in SOFA and is reported as a warning.
//  * Malformed XML (main or included file): error with the file and the line tinyxml2
//    reports.
//
// Preconditions: `is_known_type` is callable (an empty function means "every tag is
// known", i.e. no macro expansion). Never throws; returns nullopt only when the main
// file is missing, unreadable, malformed or has a non-Node root. Otherwise the tree is
// returned even when errors were reported — check `diag.has_errors()`.
std::optional<Element> load_scene_tree(const std::string& path, const ResourcePaths& paths,
                                       const KnownTypePredicate& is_known_type, Diagnostics& diag);

// Same as load_scene_tree, from XML text. `virtual_path` stands for the file: it is
// used verbatim in messages and `Element::where.file`, and its folder (made absolute)
// is the base folder for includes, macros and resource names. It need not exist, but
// when it does, an include of it is detected as a cycle.
std::optional<Element> parse_scene_tree(std::string_view xml, const std::string& virtual_path,
                                        const ResourcePaths& paths, const KnownTypePredicate& is_known_type,
                                        Diagnostics& diag);

}  // namespace sinew::scene
