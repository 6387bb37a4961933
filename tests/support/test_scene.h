// Helpers shared by the component tests: build a scene from an XML string,
// find components, write temporary scene files.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "components/register_all.h"
#include "core/node.h"
#include "core/simulation.h"
#include "scene/builder.h"
#include "scene/xml_tree.h"
#include "test_paths.h"

namespace sinew::test {

// Parses and builds `xml` (as if read from /virtual/test.scn); does not initialise.
// `tree_diag` receives the messages of the XML stage.
inline scene::LoadedScene build(const std::string& xml, Diagnostics* tree_diag = nullptr) {
  register_all_components();
  Diagnostics local;
  Diagnostics& d = tree_diag ? *tree_diag : local;
  scene::ResourcePaths paths;
  auto tree = scene::parse_scene_tree(xml, "/virtual/test.scn", paths, scene::is_known_component, d);
  if (!tree) {
    ADD_FAILURE() << "XML could not be parsed";
    return {};
  }
  return scene::build_scene(*tree, paths);
}

// Builds and initialises; fails the test when building reported an error.
inline scene::LoadedScene load(const std::string& xml) {
  scene::LoadedScene s = build(xml);
  if (!s.root) return s;
  for (const Message& m : s.root->diagnostics().messages())
    if (m.severity == Severity::error) ADD_FAILURE() << "load error: " << Diagnostics::format(m);
  init_root(*s.root);
  return s;
}

// The component named `name` in `node` cast to T (nullptr if absent or of another type).
template <class T>
T* get(Node& node, std::string_view name) {
  return dynamic_cast<T*>(node.find_object_named(name));
}

// Every formatted message of severity `s`.
inline std::vector<std::string> messages(const Diagnostics& d, Severity s) {
  std::vector<std::string> out;
  for (const Message& m : d.messages())
    if (m.severity == s) out.push_back(Diagnostics::format(m));
  return out;
}

inline bool any_contains(const std::vector<std::string>& v, std::string_view needle) {
  for (const auto& s : v)
    if (s.find(needle) != std::string::npos) return true;
  return false;
}

// A fresh folder under the system temp dir, removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "sinew_comp_XXXXXX").string();
    path_ = std::filesystem::path(mkdtemp(pattern.data()));
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  std::string write(const std::string& rel, const std::string& text) const {
    const auto p = path_ / rel;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p) << text;
    return p.string();
  }
  std::string dir() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace sinew::test
