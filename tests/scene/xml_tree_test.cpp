#include "scene/xml_tree.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>
#include "test_paths.h"

namespace fs = std::filesystem;
using sinew::Diagnostics;
using sinew::Message;
using sinew::Severity;
using sinew::scene::Element;
using sinew::scene::load_scene_tree;
using sinew::scene::parse_scene_tree;
using sinew::scene::ResourcePaths;

namespace {

// A fresh folder under the system temp dir, removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "sinew_xml_XXXXXX").string();
    path_ = fs::path(mkdtemp(pattern.data()));
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  std::string dir() const { return path_.string(); }
  // Writes `text` to `rel` (creating folders); returns the absolute path.
  std::string write(const std::string& rel, const std::string& text) const {
    const fs::path p = path_ / rel;
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text;
    return p.string();
  }

 private:
  fs::path path_;
};

bool all_known(std::string_view) { return true; }

std::vector<std::string> tags(const Element& e) {
  std::vector<std::string> out;
  for (const Element& c : e.children) out.push_back(c.tag);
  return out;
}

std::string attr(const Element& e, std::string_view name) {
  const std::string* v = e.find(name);
  return v ? *v : "<absent>";
}

// Messages of one severity, formatted ("file:line: error: text").
std::vector<std::string> messages(const Diagnostics& d, Severity s) {
  std::vector<std::string> out;
  for (const Message& m : d.messages()) {
    if (m.severity == s) out.push_back(Diagnostics::format(m));
  }
  return out;
}

const Message* first_of(const Diagnostics& d, Severity s) {
  for (const Message& m : d.messages()) {
    if (m.severity == s) return &m;
  }
  return nullptr;
}

using Attrs = std::vector<std::pair<std::string, std::string>>;

}  // namespace

// ---------------------------------------------------------------------------------------
// Document structure

TEST(XmlTree, NodesObjectsAttributesAndLines) {
  const char* xml =
      "<?xml version=\"1.0\"?>\n"
      "<!-- comment -->\n"
      "<Node name=\"root\" dt=\"0.02\" gravity=\"0 -10 0\">\n"
      "  some text\n"
      "  <MechanicalObject name=\"mo\" template=\"Vec3d\" position=\"0 0 0\"/>\n"
      "  <Node name=\"child\">\n"
      "    <!-- <UniformMass/> -->\n"
      "    <UniformMass totalMass=\"2\"/>\n"
      "  </Node>\n"
      "  <Object type=\"EulerImplicitSolver\" name=\"ode\" rayleighMass=\"0.1\"/>\n"
      "</Node>\n";
  Diagnostics diag;
  const auto root = parse_scene_tree(xml, "/virtual/scene.scn", ResourcePaths{}, all_known, diag);
  ASSERT_TRUE(root.has_value());
  EXPECT_TRUE(diag.messages().empty());
  EXPECT_TRUE(root->is_node);
  EXPECT_EQ(root->tag, "Node");
  EXPECT_EQ(root->attributes, (Attrs{{"name", "root"}, {"dt", "0.02"}, {"gravity", "0 -10 0"}}));
  EXPECT_EQ(root->where.file, "/virtual/scene.scn");
  EXPECT_EQ(root->where.line, 3);
  EXPECT_EQ(root->base_dir, "/virtual");
  ASSERT_EQ(tags(*root), (std::vector<std::string>{"MechanicalObject", "Node", "EulerImplicitSolver"}));

  const Element& mo = root->children[0];
  EXPECT_FALSE(mo.is_node);
  EXPECT_EQ(mo.attributes, (Attrs{{"name", "mo"}, {"template", "Vec3d"}, {"position", "0 0 0"}}));
  EXPECT_EQ(mo.where.line, 5);
  EXPECT_EQ(mo.name(), "mo");

  const Element& child = root->children[1];
  EXPECT_TRUE(child.is_node);
  ASSERT_EQ(tags(child), (std::vector<std::string>{"UniformMass"}));
  EXPECT_EQ(child.children[0].where.line, 8);
  EXPECT_EQ(attr(child.children[0], "totalMass"), "2");
  EXPECT_EQ(child.children[0].name(), "");

  // <Object type="X"> is normalised: tag X, the type attribute consumed.
  const Element& ode = root->children[2];
  EXPECT_FALSE(ode.is_node);
  EXPECT_EQ(ode.attributes, (Attrs{{"name", "ode"}, {"rayleighMass", "0.1"}}));
  EXPECT_EQ(ode.find("type"), nullptr);
  EXPECT_EQ(ode.where.line, 10);
}

TEST(XmlTree, EntitiesAreDecodedAndValuesKeptVerbatim) {
  Diagnostics diag;
  const auto root = parse_scene_tree("<Node><Foo a=\"x &amp; y\" b=\"  1\n 2 \"/></Node>", "s.scn", ResourcePaths{},
                                     all_known, diag);
  ASSERT_TRUE(root.has_value());
  EXPECT_EQ(attr(root->children.at(0), "a"), "x & y");
  EXPECT_EQ(attr(root->children.at(0), "b"), "  1\n 2 ");
}

TEST(XmlTree, NonKeywordTagWithTypeIsDroppedWithInfo) {
  Diagnostics diag;
  const auto root = parse_scene_tree(
      "<Node>\n  <MechanicalObject type=\"Vec3d\"><Foo/></MechanicalObject>\n  <UniformMass/>\n"
      "  <Bar type=\"default\" x=\"1\"/>\n</Node>",
      "s.scn", ResourcePaths{}, all_known, diag);
  ASSERT_TRUE(root.has_value());
  // type="default" counts as no type in SOFA.
  ASSERT_EQ(tags(*root), (std::vector<std::string>{"UniformMass", "Bar"}));
  EXPECT_EQ(root->children[1].attributes, (Attrs{{"x", "1"}}));
  EXPECT_FALSE(diag.has_errors());
  const Message* info = first_of(diag, Severity::info);
  ASSERT_NE(info, nullptr);
  EXPECT_EQ(info->where.file, "s.scn");
  EXPECT_EQ(info->where.line, 2);
  EXPECT_NE(info->text.find("MechanicalObject"), std::string::npos);
}

TEST(XmlTree, ObjectWithoutTypeIsAnError) {
  Diagnostics diag;
  const auto root = parse_scene_tree("<Node>\n<Object name=\"x\"/>\n</Node>", "s.scn", ResourcePaths{}, all_known, diag);
  ASSERT_TRUE(root.has_value());
  EXPECT_TRUE(root->children.empty());
  ASSERT_EQ(diag.error_count(), 1);
  EXPECT_EQ(first_of(diag, Severity::error)->where.line, 2);
}

TEST(XmlTree, RootMustBeNode) {
  Diagnostics diag;
  const auto root =
      parse_scene_tree("<!-- x -->\n<MechanicalObject/>\n", "/v/s.scn", ResourcePaths{}, all_known, diag);
  EXPECT_FALSE(root.has_value());
  ASSERT_EQ(diag.error_count(), 1);
  const Message* e = first_of(diag, Severity::error);
  EXPECT_EQ(e->where.file, "/v/s.scn");
  EXPECT_EQ(e->where.line, 2);
  EXPECT_NE(e->text.find("<Node>"), std::string::npos);
}

TEST(XmlTree, MalformedXmlReportsFileAndLine) {
  Diagnostics diag;
  const auto root = parse_scene_tree("<Node>\n  <A>\n  <B/>\n</Node>\n", "/v/bad.scn", ResourcePaths{}, all_known, diag);
  EXPECT_FALSE(root.has_value());
  ASSERT_EQ(diag.error_count(), 1);
  const Message* e = first_of(diag, Severity::error);
  EXPECT_EQ(e->where.file, "/v/bad.scn");
  // tinyxml2 reports the element left open: <A>, line 2.
  EXPECT_EQ(e->where.line, 2);
  EXPECT_NE(e->text.find("XML_ERROR_MISMATCHED_ELEMENT"), std::string::npos) << e->text;
  EXPECT_NE(e->text.find("malformed XML"), std::string::npos);
}

TEST(XmlTree, EmptyDocumentIsAnError) {
  Diagnostics diag;
  EXPECT_FALSE(parse_scene_tree("", "e.scn", ResourcePaths{}, all_known, diag).has_value());
  EXPECT_EQ(diag.error_count(), 1);
}

TEST(XmlTree, LoadMissingFileIsAnError) {
  TempDir t;
  Diagnostics diag;
  const std::string path = t.dir() + "/nope.scn";
  EXPECT_FALSE(load_scene_tree(path, ResourcePaths{}, all_known, diag).has_value());
  ASSERT_EQ(diag.error_count(), 1);
  EXPECT_EQ(first_of(diag, Severity::error)->where.file, path);
}

TEST(XmlTree, LoadFileUsesAbsolutePathAndItsFolder) {
  TempDir t;
  const std::string path = t.write("sub/scene.scn", "<Node name=\"r\">\n<Foo/>\n</Node>");
  Diagnostics diag;
  const auto root = load_scene_tree(t.dir() + "/sub/../sub/scene.scn", ResourcePaths{}, all_known, diag);
  ASSERT_TRUE(root.has_value());
  EXPECT_EQ(root->where.file, path);
  EXPECT_EQ(root->base_dir, t.dir() + "/sub");
  EXPECT_EQ(root->children.at(0).where.file, path);
  EXPECT_EQ(root->children.at(0).where.line, 2);
  EXPECT_EQ(root->children.at(0).base_dir, t.dir() + "/sub");
}

TEST(XmlTree, MalformedFileReportsLine) {
  TempDir t;
  const std::string path = t.write("bad.scn", "<Node>\n\n<Foo a=\"1\" a=\"2\"/>\n</Node>");
  Diagnostics diag;
  EXPECT_FALSE(load_scene_tree(path, ResourcePaths{}, all_known, diag).has_value());
  ASSERT_EQ(diag.error_count(), 1);
  EXPECT_EQ(first_of(diag, Severity::error)->where.file, path);
  EXPECT_EQ(first_of(diag, Severity::error)->where.line, 3);
}

// ---------------------------------------------------------------------------------------
// Legacy <Attribute type="a"><Data value="v"/></Attribute>

TEST(XmlTree, LegacyAttributeDataSetsAttributesOnTheComponent) {
  const char* xml =
      "<Node>\n"
      "  <MechanicalObject name=\"m\" position=\"0\">\n"
      "    <Attribute type=\"position\"><Data value=\"1 2 3\"/></Attribute>\n"
      "    <Attribute type=\"velocity\"><Data value=\"4\"/><Data value=\"5\"/></Attribute>\n"
      "    <Attribute type=\"rest_position\"/>\n"
      "  </MechanicalObject>\n"
      "  <Attribute type=\"dt\"><Data value=\"9\"/></Attribute>\n"
      "</Node>\n";
  Diagnostics diag;
  const auto root = parse_scene_tree(xml, "s.scn", ResourcePaths{}, all_known, diag);
  ASSERT_TRUE(root.has_value());
  ASSERT_EQ(root->children.size(), 1u);
  const Element& mo = root->children[0];
  EXPECT_TRUE(mo.children.empty());
  EXPECT_EQ(mo.attributes,
            (Attrs{{"name", "m"}, {"position", "1 2 3"}, {"velocity", "5"}, {"rest_position", ""}}));
  // On a Node it has no effect in SOFA: warned, not applied.
  EXPECT_EQ(root->find("dt"), nullptr);
  ASSERT_EQ(diag.warning_count(), 1);
  EXPECT_EQ(first_of(diag, Severity::warning)->where.line, 7);
  EXPECT_FALSE(diag.has_errors());
}

TEST(XmlTree, NodeInsideComponentIsDropped) {
  Diagnostics diag;
  const auto root = parse_scene_tree("<Node>\n<Foo>\n<Node name=\"n\"/>\n<Bar/>\n</Foo>\n</Node>", "s.scn",
                                     ResourcePaths{}, all_known, diag);
  ASSERT_TRUE(root.has_value());
  ASSERT_EQ(tags(*root), (std::vector<std::string>{"Foo"}));
  EXPECT_TRUE(root->children[0].children.empty());
  EXPECT_EQ(first_of(diag, Severity::info)->where.line, 3);
  EXPECT_EQ(first_of(diag, Severity::warning)->where.line, 4);
}

// ---------------------------------------------------------------------------------------
// include

TEST(XmlTree, GroupIncludeIsSplicedInPlace) {
  TempDir t;
  const std::string inc = t.write("inc/common.xml",
                                  "<!-- prefab -->\n"
                                  "<Node name=\"Group\">\n"
                                  "  <A name=\"a\" file=\"m.obj\"/>\n"
                                  "  <Node name=\"sub\"><B/></Node>\n"
                                  "</Node>\n");
  const std::string scene = t.write("scene.scn",
                                    "<Node name=\"root\">\n"
                                    "  <First/>\n"
                                    "  <include href=\"inc/common.xml\"/>\n"
                                    "  <Last/>\n"
                                    "</Node>\n");
  Diagnostics diag;
  const auto root = load_scene_tree(scene, ResourcePaths{}, all_known, diag);
  ASSERT_TRUE(root.has_value());
  EXPECT_TRUE(diag.messages().empty());
  ASSERT_EQ(tags(*root), (std::vector<std::string>{"First", "A", "Node", "Last"}));
  const Element& a = root->children[1];
  EXPECT_EQ(a.where.file, inc);
  EXPECT_EQ(a.where.line, 3);
  // Moved out of a Group: resources resolve against the including file's folder.
  EXPECT_EQ(a.base_dir, t.dir());
  EXPECT_EQ(root->children[2].name(), "sub");
  EXPECT_EQ(root->children[2].base_dir, t.dir());
  EXPECT_EQ(root->children[2].children.at(0).base_dir, t.dir());
  EXPECT_EQ(root->children[3].where.file, scene);
  EXPECT_EQ(root->children[3].where.line, 4);
}

TEST(XmlTree, UnderscoreGroupIsSplicedToo) {
  TempDir t;
  t.write("g.xml", "<Node name=\"_Group_\"><A/><B/></Node>");
  const std::string scene = t.write("s.scn", "<Node><include href=\"g.xml\"/></Node>");
  Diagnostics diag;
  const auto root = load_scene_tree(scene, ResourcePaths{}, all_known, diag);
  ASSERT_TRUE(root.has_value());
  EXPECT_EQ(tags(*root), (std::vector<std::string>{"A", "B"}));
}

TEST(XmlTree, NamedRootBecomesChildAndKeepsItsFolder) {
  TempDir t;
  const std::string inc = t.write("Objects/Torus.xml",
                                  "<Node name=\"Torus\" dx=\"0\">\n"
                                  "  <Loader filename=\"torus.msh\"/>\n"
                                  "  <Node name=\"Visu\"><Ogl/></Node>\n"
                                  "</Node>\n");
  const std::string scene = t.write("scenes/s.scn",
                                    "<Node>\n"
                                    "  <include href=\"Objects/Torus.xml\"/>\n"
                                    "  <include name=\"FEM\" href=\"Objects/Torus.xml\"/>\n"
                                    "  <include href=\"Objects/Torus.xml\" name=\"Group\"/>\n"
                                    "</Node>\n");
  ResourcePaths paths;
  paths.add(t.dir());  // Objects/ is found through the data folder, not next to the scene
  Diagnostics diag;
  const auto root = load_scene_tree(scene, paths, all_known, diag);
  ASSERT_TRUE(root.has_value());
  EXPECT_TRUE(diag.messages().empty());
  // Plain include: the root is a child node; renamed include: new name;
  // renamed to Group: spliced.
  ASSERT_EQ(tags(*root), (std::vector<std::string>{"Node", "Node", "Loader", "Node"}));
  const Element& plain = root->children[0];
  EXPECT_EQ(plain.name(), "Torus");
  EXPECT_EQ(plain.where.file, inc);
  EXPECT_EQ(plain.where.line, 1);
  EXPECT_EQ(plain.base_dir, t.dir() + "/Objects");
  EXPECT_EQ(plain.children.at(0).base_dir, t.dir() + "/Objects");
  EXPECT_EQ(plain.children.at(1).children.at(0).base_dir, t.dir() + "/Objects");
  const Element& renamed = root->children[1];
  EXPECT_EQ(renamed.name(), "FEM");
  EXPECT_EQ(renamed.attributes, (Attrs{{"name", "FEM"}, {"dx", "0"}}));
  EXPECT_EQ(root->children[2].base_dir, t.dir() + "/scenes");
  EXPECT_EQ(root->children[3].name(), "Visu");
}

TEST(XmlTree, RenameAddsNameFirstWhenRootHasNone) {
  TempDir t;
  t.write("n.xml", "<Node gravity=\"0 0 0\"><A/></Node>");
  const std::string scene = t.write("s.scn", "<Node><include href=\"n.xml\" name=\"X\"/></Node>");
  Diagnostics diag;
  const auto root = load_scene_tree(scene, ResourcePaths{}, all_known, diag);
  ASSERT_TRUE(root.has_value());
  ASSERT_EQ(root->children.size(), 1u);
  EXPECT_EQ(root->children[0].attributes, (Attrs{{"name", "X"}, {"gravity", "0 0 0"}}));
}

TEST(XmlTree, MergeCopiesAttributesAndMergesChildren) {
  TempDir t;
  t.write("m.xml",
          "<Node name=\"_Merge_\" dt=\"0.5\" gravity=\"0 0 0\">\n"
          "  <Node name=\"a\">\n"
          "    <B name=\"b\" w=\"2\" v=\"3\"/>\n"
          "    <C/>\n"
          "  </Node>\n"
          "  <B name=\"a\"/>\n"
          "  <Node name=\"new\"/>\n"
          "</Node>\n");
  const std::string scene = t.write("s.scn",
                                    "<Node name=\"root\" dt=\"0.1\">\n"
                                    "  <Node name=\"a\"><B name=\"b\" v=\"1\"/><C/></Node>\n"
                                    "  <include href=\"m.xml\"/>\n"
                                    "</Node>\n");
  Diagnostics diag;
  const auto root = load_scene_tree(scene, ResourcePaths{}, all_known, diag);
  ASSERT_TRUE(root.has_value());
  EXPECT_TRUE(diag.messages().empty());
  EXPECT_EQ(root->attributes, (Attrs{{"name", "root"}, {"dt", "0.5"}, {"gravity", "0 0 0"}}));
  // Node 'a' merged; component B named 'a' is not a Node, so it is moved, as is 'new'.
  ASSERT_EQ(tags(*root), (std::vector<std::string>{"Node", "B", "Node"}));
  EXPECT_EQ(root->children[2].name(), "new");
  const Element& a = root->children[0];
  // B named 'b' merged (attributes updated in place, new ones appended); unnamed C moved.
  ASSERT_EQ(tags(a), (std::vector<std::string>{"B", "C", "C"}));
  EXPECT_EQ(a.children[0].attributes, (Attrs{{"name", "b"}, {"v", "3"}, {"w", "2"}}));
  EXPECT_EQ(a.children[0].where.line, 2);  // the merged element stays the scene's one
  EXPECT_EQ(a.children[2].where.line, 4);  // the moved one comes from m.xml
}

TEST(XmlTree, ReplacementAttributes) {
  TempDir t;
  t.write("Objects/T.xml",
          "<Node name=\"T\" dx=\"0\">\n"
          "  <MechanicalObject name=\"mo\" dx=\"0\" rx=\"0\"/>\n"
          "  <OglModel name=\"Visual\" dx=\"0\" rx=\"0\"/>\n"
          "  <UniformMass totalMass=\"1\"/>\n"
          "  <Node name=\"sub\" dx=\"0\">\n"
          "    <Foo name=\"f\" dx=\"0\"/>\n"
          "    <Bar name=\"Visual\" color=\"blue\"/>\n"
          "  </Node>\n"
          "</Node>\n");
  const std::string scene =
      t.write("s.scn",
              "<Node>\n"
              "  <include href=\"Objects/T.xml\" dx=\"2.5\" Visual__rx=\"90\" Visual__color=\"red\" template=\"Vec1\"/>\n"
              "</Node>\n");
  Diagnostics diag;
  const auto r2 = load_scene_tree(scene, ResourcePaths{}, all_known, diag);
  ASSERT_TRUE(r2.has_value());
  EXPECT_TRUE(diag.messages().empty());
  const Element& tnode = r2->children.at(0);
  EXPECT_EQ(attr(tnode, "dx"), "0");  // nodes are not changed by replacements
  ASSERT_EQ(tags(tnode), (std::vector<std::string>{"MechanicalObject", "OglModel", "UniformMass", "Node"}));
  const Element& mo = tnode.children[0];
  EXPECT_EQ(mo.attributes, (Attrs{{"name", "mo"}, {"dx", "2.5"}, {"rx", "0"}}));  // rx only on 'Visual'
  const Element& visual = tnode.children[1];
  EXPECT_EQ(visual.attributes, (Attrs{{"name", "Visual"}, {"dx", "2.5"}, {"rx", "90"}}));  // no color added
  EXPECT_EQ(tnode.children[2].attributes, (Attrs{{"totalMass", "1"}}));  // lacks dx, template: untouched
  const Element& sub = tnode.children[3];
  EXPECT_EQ(attr(sub, "dx"), "0");
  EXPECT_EQ(sub.children.at(0).attributes, (Attrs{{"name", "f"}, {"dx", "2.5"}}));
  EXPECT_EQ(sub.children.at(1).attributes, (Attrs{{"name", "Visual"}, {"color", "red"}}));
}

TEST(XmlTree, OuterReplacementReachesNestedIncludesAndWins) {
  TempDir t;
  t.write("inner.xml", "<Node name=\"Group\"><A k=\"0\" j=\"0\"/></Node>");
  t.write("outer.xml", "<Node name=\"O\"><include href=\"inner.xml\" k=\"inner\" j=\"inner\"/><B k=\"0\"/></Node>");
  const std::string scene = t.write("s.scn", "<Node><include href=\"outer.xml\" k=\"outer\"/></Node>");
  Diagnostics diag;
  const auto root = load_scene_tree(scene, ResourcePaths{}, all_known, diag);
  ASSERT_TRUE(root.has_value());
  const Element& o = root->children.at(0);
  ASSERT_EQ(tags(o), (std::vector<std::string>{"A", "B"}));
  EXPECT_EQ(attr(o.children[0], "k"), "outer");
  EXPECT_EQ(attr(o.children[0], "j"), "inner");
  EXPECT_EQ(attr(o.children[1], "k"), "outer");
  // A was spliced out of inner.xml's Group into O, the root of outer.xml.
  EXPECT_EQ(o.children[0].where.file, t.dir() + "/inner.xml");
  EXPECT_EQ(o.children[0].base_dir, t.dir());
}

TEST(XmlTree, LegacyAttributeThenReplacement) {
  TempDir t;
  t.write("i.xml",
          "<Node name=\"Group\"><M><Attribute type=\"scale\"><Data value=\"2\"/></Attribute></M></Node>");
  const std::string scene = t.write("s.scn", "<Node><include href=\"i.xml\" scale=\"7\"/></Node>");
  Diagnostics diag;
  const auto root = load_scene_tree(scene, ResourcePaths{}, all_known, diag);
  ASSERT_TRUE(root.has_value());
  EXPECT_EQ(attr(root->children.at(0), "scale"), "7");
}

TEST(XmlTree, IncludeWithoutHrefIsAnError) {
  Diagnostics diag;
  const auto root = parse_scene_tree("<Node>\n  <include name=\"x\"/>\n  <include href=\"\"/>\n  <A/>\n</Node>",
                                     "/v/s.scn", ResourcePaths{}, all_known, diag);
  ASSERT_TRUE(root.has_value());  // loading goes on, the caller refuses the scene
  EXPECT_EQ(tags(*root), (std::vector<std::string>{"A"}));
  const auto errors = messages(diag, Severity::error);
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0].rfind("/v/s.scn:2: error: ", 0), 0u) << errors[0];
  EXPECT_EQ(errors[1].rfind("/v/s.scn:3: error: ", 0), 0u) << errors[1];
  EXPECT_NE(errors[0].find("href"), std::string::npos);
}

TEST(XmlTree, IncludeOfMissingFileIsAnError) {
  TempDir t;
  const std::string scene = t.write("s.scn", "<Node>\n\n  <include href=\"nowhere/x.xml\"/>\n</Node>");
  Diagnostics diag;
  const auto root = load_scene_tree(scene, ResourcePaths{}, all_known, diag);
  ASSERT_TRUE(root.has_value());
  EXPECT_TRUE(root->children.empty());
  ASSERT_EQ(diag.error_count(), 1);
  const Message* e = first_of(diag, Severity::error);
  EXPECT_EQ(e->where.file, scene);
  EXPECT_EQ(e->where.line, 3);
  EXPECT_NE(e->text.find("nowhere/x.xml"), std::string::npos);
}

TEST(XmlTree, MalformedIncludedFileReportsItsOwnLine) {
  TempDir t;
  const std::string inc = t.write("i.xml", "<Node name=\"Group\">\n<A>\n</Node>\n");
  const std::string scene = t.write("s.scn", "<Node>\n<include href=\"i.xml\"/>\n<B/>\n</Node>");
  Diagnostics diag;
  const auto root = load_scene_tree(scene, ResourcePaths{}, all_known, diag);
  ASSERT_TRUE(root.has_value());
  EXPECT_EQ(tags(*root), (std::vector<std::string>{"B"}));
  ASSERT_EQ(diag.error_count(), 1);
  const Message* e = first_of(diag, Severity::error);
  EXPECT_EQ(e->where.file, inc);
  EXPECT_EQ(e->where.line, 2);  // <A> is never closed
  EXPECT_NE(e->text.find(scene + ":2"), std::string::npos) << e->text;
}

TEST(XmlTree, IncludeCycleIsAnError) {
  TempDir t;
  const std::string a = t.write("a.xml", "<Node name=\"A\">\n<include href=\"b.xml\"/>\n<X/>\n</Node>");
  const std::string b = t.write("b.xml", "<Node name=\"B\">\n\n<include href=\"a.xml\"/>\n<Y/>\n</Node>");
  const std::string scene = t.write("s.scn", "<Node>\n<include href=\"a.xml\"/>\n<include href=\"s.scn\"/>\n</Node>");
  Diagnostics diag;
  const auto root = load_scene_tree(scene, ResourcePaths{}, all_known, diag);
  ASSERT_TRUE(root.has_value());
  const auto errors = messages(diag, Severity::error);
  ASSERT_EQ(errors.size(), 2u);
  // b.xml line 3 includes a.xml while a.xml is being expanded; the scene includes itself.
  EXPECT_EQ(errors[0].rfind(b + ":3: error: include cycle", 0), 0u) << errors[0];
  EXPECT_EQ(errors[1].rfind(scene + ":3: error: include cycle", 0), 0u) << errors[1];
  // Everything but the cyclic includes is kept.
  ASSERT_EQ(root->children.size(), 1u);
  const Element& na = root->children[0];
  EXPECT_EQ(na.name(), "A");
  ASSERT_EQ(tags(na), (std::vector<std::string>{"Node", "X"}));
  EXPECT_EQ(na.children[0].name(), "B");
  EXPECT_EQ(tags(na.children[0]), (std::vector<std::string>{"Y"}));
  (void)a;
}

TEST(XmlTree, IncludeDepthIsBounded) {
  TempDir t;
  // f0 includes f1 includes ... f99: no cycle, but deeper than the loader accepts.
  for (int i = 0; i < 100; ++i) {
    t.write("f" + std::to_string(i) + ".xml",
            "<Node name=\"n" + std::to_string(i) + "\">\n<include href=\"f" + std::to_string(i + 1) + ".xml\"/>\n</Node>");
  }
  t.write("f100.xml", "<Node name=\"last\"/>");
  const std::string scene = t.write("s.scn", "<Node><include href=\"f0.xml\"/></Node>");
  Diagnostics diag;
  const auto root = load_scene_tree(scene, ResourcePaths{}, all_known, diag);
  ASSERT_TRUE(root.has_value());
  ASSERT_EQ(diag.error_count(), 1);
  const Message* e = first_of(diag, Severity::error);
  // At most 64 files are open at once: the scene and f0..f62, so f62's include is refused.
  EXPECT_EQ(e->where.file, t.dir() + "/f62.xml");
  EXPECT_EQ(e->where.line, 2);
}

TEST(XmlTree, SameFileIncludedTwiceIsNotACycle) {
  TempDir t;
  t.write("g.xml", "<Node name=\"Group\"><A/></Node>");
  const std::string scene = t.write("s.scn", "<Node><include href=\"g.xml\"/><include href=\"./g.xml\"/></Node>");
  Diagnostics diag;
  const auto root = load_scene_tree(scene, ResourcePaths{}, all_known, diag);
  ASSERT_TRUE(root.has_value());
  EXPECT_FALSE(diag.has_errors());
  EXPECT_EQ(tags(*root), (std::vector<std::string>{"A", "A"}));
}

// ---------------------------------------------------------------------------------------
// XML macro objects (Objects/<Type>.xml)

TEST(XmlTree, MacroExpandsUnknownTagWithReplacements) {
  TempDir t;
  const std::string macro = t.write("Objects/Foo.xml",
                                    "<Node name=\"Group\">\n"
                                    "  <BoxROI name=\"box_roi\" box=\"0 0 0 1 1 1\" drawBoxes=\"0\"/>\n"
                                    "  <FixedProjectiveConstraint indices=\"@box_roi.indices\"/>\n"
                                    "</Node>\n");
  const std::string scene = t.write("s.scn",
                                    "<Node>\n"
                                    "  <Foo box=\"1 2 3 4 5 6\"/>\n"
                                    "  <Bar/>\n"
                                    "  <Object type=\"Foo\" box=\"7 8 9 10 11 12\" drawBoxes=\"1\"/>\n"
                                    "  <Foo name=\"renamed\"/>\n"
                                    "</Node>\n");
  // Foo and Bar are not factory classes; only Foo has a macro file.
  const auto known = [](std::string_view tag) { return tag != "Foo" && tag != "Bar"; };
  Diagnostics diag;
  const auto root = load_scene_tree(scene, ResourcePaths{}, known, diag);
  ASSERT_TRUE(root.has_value());
  EXPECT_TRUE(diag.messages().empty());
  ASSERT_EQ(tags(*root), (std::vector<std::string>{"BoxROI", "FixedProjectiveConstraint", "Bar", "BoxROI",
                                                   "FixedProjectiveConstraint", "Node"}));
  const Element& box = root->children[0];
  EXPECT_EQ(box.attributes, (Attrs{{"name", "box_roi"}, {"box", "1 2 3 4 5 6"}, {"drawBoxes", "0"}}));
  EXPECT_EQ(box.where.file, macro);
  EXPECT_EQ(box.where.line, 2);
  EXPECT_EQ(box.base_dir, t.dir());
  EXPECT_EQ(root->children[1].attributes, (Attrs{{"indices", "@box_roi.indices"}}));
  // An unknown tag without macro is kept for the builder to report.
  EXPECT_EQ(root->children[2].where.line, 3);
  EXPECT_TRUE(root->children[2].attributes.empty());
  // <Object type="Foo"> expands the same way; 'type' is not a replacement.
  EXPECT_EQ(root->children[3].attributes, (Attrs{{"name", "box_roi"}, {"box", "7 8 9 10 11 12"}, {"drawBoxes", "1"}}));
  // 'name' renames the macro root like for include: no longer a Group, so a child node.
  const Element& renamed = root->children[5];
  EXPECT_TRUE(renamed.is_node);
  EXPECT_EQ(renamed.name(), "renamed");
  EXPECT_EQ(tags(renamed), (std::vector<std::string>{"BoxROI", "FixedProjectiveConstraint"}));
  EXPECT_EQ(renamed.base_dir, t.dir() + "/Objects");

  // A known class is never replaced by a macro.
  diag.clear();
  const auto plain = load_scene_tree(scene, ResourcePaths{}, all_known, diag);
  ASSERT_TRUE(plain.has_value());
  EXPECT_EQ(tags(*plain), (std::vector<std::string>{"Foo", "Bar", "Foo", "Foo"}));
  EXPECT_EQ(plain->children[2].attributes, (Attrs{{"box", "7 8 9 10 11 12"}, {"drawBoxes", "1"}}));
}

TEST(XmlTree, MacroIsFoundNextToTheFileThenInDataFolders) {
  TempDir t;
  t.write("data/Objects/Foo.xml", "<Node name=\"Group\"><FromData/></Node>");
  t.write("scenes/Objects/Foo.xml", "<Node name=\"Group\"><FromScene/></Node>");
  const std::string near = t.write("scenes/s.scn", "<Node><Foo/></Node>");
  const std::string far = t.write("other/s.scn", "<Node><Foo/></Node>");
  ResourcePaths paths;
  paths.add(t.dir() + "/data");
  const auto known = [](std::string_view tag) { return tag != "Foo"; };
  Diagnostics diag;
  const auto a = load_scene_tree(near, paths, known, diag);
  const auto b = load_scene_tree(far, paths, known, diag);
  ASSERT_TRUE(a.has_value());
  ASSERT_TRUE(b.has_value());
  EXPECT_TRUE(diag.messages().empty());
  EXPECT_EQ(tags(*a), (std::vector<std::string>{"FromScene"}));
  EXPECT_EQ(tags(*b), (std::vector<std::string>{"FromData"}));
  EXPECT_EQ(b->children[0].base_dir, t.dir() + "/other");
}

TEST(XmlTree, EmptyPredicateMeansEverythingIsKnown) {
  TempDir t;
  t.write("Objects/Foo.xml", "<Node name=\"Group\"><X/></Node>");
  const std::string scene = t.write("s.scn", "<Node><Foo/></Node>");
  Diagnostics diag;
  const auto root = load_scene_tree(scene, ResourcePaths{}, {}, diag);
  ASSERT_TRUE(root.has_value());
  EXPECT_EQ(tags(*root), (std::vector<std::string>{"Foo"}));
}

// ---------------------------------------------------------------------------------------
// Real SOFA scenes (SINEW_DATA_DIR)

namespace {

fs::path data_dir() { return fs::path(SINEW_DATA_DIR).lexically_normal(); }

ResourcePaths sofa_paths() {
  ResourcePaths paths;
  paths.add((data_dir() / "share").string());
  paths.add((data_dir() / "examples").string());
  return paths;
}

#define SKIP_WITHOUT_DATA()                                                                              \
  if (!fs::exists(data_dir() / "examples")) {                                                            \
    GTEST_SKIP() << "SOFA data not found at " << data_dir() << " (set SINEW_DATA_DIR to the sofa-data folder)"; \
  }

// A tag names a macro when examples/Objects/<tag>.xml exists.
bool is_macro_name(std::string_view tag) {
  std::error_code ec;
  return fs::exists(data_dir() / "examples/Objects" / (std::string(tag) + ".xml"), ec);
}

void collect_component_tags(const Element& e, std::set<std::string>& out) {
  for (const Element& c : e.children) {
    if (!c.is_node) out.insert(c.tag);
    collect_component_tags(c, out);
  }
}

struct SceneRow {
  std::string scene;
  std::set<std::string> components;
};

std::vector<SceneRow> read_scenes_tsv() {
  std::vector<SceneRow> rows;
  std::ifstream in(data_dir() / "SCENES.tsv");
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<std::string> cols;
    std::stringstream ss(line);
    std::string col;
    while (std::getline(ss, col, '\t')) cols.push_back(col);
    if (cols.size() < 7) continue;
    SceneRow row{cols[0], {}};
    std::stringstream comps(cols[6]);
    std::string c;
    while (comps >> c) row.components.insert(c);
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace

TEST(XmlTreeData, FembarIncludeIsSplicedIntoRoot) {
  SKIP_WITHOUT_DATA();
  const fs::path folder = data_dir() / "examples/Component/LinearSolver/Iterative";
  const std::string scene = (folder / "FEMBAR_CGLinearSolver.scn").string();
  const std::string common = (data_dir() / "examples/Component/LinearSolver/FEMBAR-common.xml").string();
  Diagnostics diag;
  const auto root = load_scene_tree(scene, sofa_paths(), [](std::string_view t) { return !is_macro_name(t); }, diag);
  ASSERT_TRUE(root.has_value());
  EXPECT_TRUE(diag.messages().empty()) << Diagnostics::format(diag.messages().front());
  EXPECT_EQ(root->name(), "root");
  EXPECT_EQ(attr(*root, "gravity"), "0 -10 0");
  ASSERT_EQ(tags(*root),
            (std::vector<std::string>{"Node", "VisualStyle", "DefaultAnimationLoop", "DefaultVisualManagerLoop",
                                      "EulerImplicitSolver", "MechanicalObject", "UniformMass", "RegularGridTopology",
                                      "BoxROI", "FixedProjectiveConstraint", "CGLinearSolver",
                                      "HexahedronFEMForceField"}));
  const Element& plugins = root->children[0];
  EXPECT_EQ(plugins.name(), "plugins");
  EXPECT_EQ(plugins.children.size(), 13u);
  EXPECT_EQ(attr(plugins.children.at(0), "pluginName"), "Sofa.Component.Constraint.Projective");
  EXPECT_EQ(attr(root->children[7], "nz"), "20");
  EXPECT_EQ(attr(root->children[8], "box"), "-10 -1 -0.0001  -5 4 0.0001");
  EXPECT_EQ(attr(root->children[11], "youngModulus"), "4000");
  for (std::size_t i = 0; i < 10; ++i) {
    EXPECT_EQ(root->children[i].where.file, common) << i;
    // Spliced from a Group: resources resolve next to the scene, not next to the include.
    EXPECT_EQ(root->children[i].base_dir, folder.string()) << i;
  }
  EXPECT_EQ(root->children[5].where.line, 25);  // <MechanicalObject name="DoFs" />
  EXPECT_EQ(root->children[10].where.file, scene);
  EXPECT_EQ(root->children[10].where.line, 5);
}

TEST(XmlTreeData, BoxConstraintMacroExpands) {
  SKIP_WITHOUT_DATA();
  const std::string scene = (data_dir() / "examples/Component/Topology/Container/Grid/RegularGridTopology.scn").string();
  Diagnostics diag;
  const auto root = load_scene_tree(scene, sofa_paths(), [](std::string_view t) { return !is_macro_name(t); }, diag);
  ASSERT_TRUE(root.has_value());
  EXPECT_TRUE(diag.messages().empty());
  const Element* lowres = nullptr;
  for (const Element& c : root->children) {
    if (c.is_node && c.name() == "LiverFFD-lowres") lowres = &c;
  }
  ASSERT_NE(lowres, nullptr);
  ASSERT_EQ(tags(*lowres), (std::vector<std::string>{"EulerImplicitSolver", "CGLinearSolver", "MechanicalObject",
                                                     "UniformMass", "RegularGridTopology", "BoxROI",
                                                     "FixedProjectiveConstraint", "RegularGridSpringForceField", "Node",
                                                     "Node"}));
  const Element& box = lowres->children[5];
  EXPECT_EQ(box.attributes, (Attrs{{"name", "box_roi"}, {"box", "-8.5 0 -2.5 -5 3 2"}, {"drawBoxes", "0"}}));
  EXPECT_EQ(box.where.file, (data_dir() / "examples/Objects/BoxConstraint.xml").string());
  EXPECT_EQ(attr(lowres->children[6], "indices"), "@[-1].indices");
  EXPECT_EQ(box.base_dir, (data_dir() / "examples/Component/Topology/Container/Grid").string());
}

TEST(XmlTreeData, ChainHybridIncludesGetReplacements) {
  SKIP_WITHOUT_DATA();
  const std::string scene = (data_dir() / "examples/Demos/chainHybrid.scn").string();
  Diagnostics diag;
  const auto root = load_scene_tree(scene, sofa_paths(), [](std::string_view t) { return !is_macro_name(t); }, diag);
  ASSERT_TRUE(root.has_value());
  EXPECT_TRUE(diag.messages().empty());
  const Element* chain = nullptr;
  for (const Element& c : root->children) {
    if (c.name() == "Chain") chain = &c;
  }
  ASSERT_NE(chain, nullptr);
  ASSERT_EQ(chain->children.size(), 5u);
  const Element& fem = chain->children[1];
  EXPECT_EQ(fem.name(), "FEM");
  EXPECT_EQ(fem.where.file, (data_dir() / "examples/Objects/TorusFEM.xml").string());
  EXPECT_EQ(fem.base_dir, (data_dir() / "examples/Objects").string());
  const Element& mo = fem.children.at(4);
  ASSERT_EQ(mo.tag, "MechanicalObject");
  EXPECT_EQ(attr(mo, "dx"), "2.5");
  EXPECT_EQ(attr(mo, "rx"), "0");
  const Element& spring = chain->children[2];
  EXPECT_EQ(spring.name(), "Spring");
}

// Every regression scene loads without errors; before macro expansion its component tags
// are exactly those SCENES.tsv lists (which checks include handling against SOFA's own
// list), and after expansion no macro name is left and every class is one SOFA uses in
// some regression scene.
TEST(XmlTreeData, AllRegressionScenesLoad) {
  SKIP_WITHOUT_DATA();
  const std::vector<SceneRow> rows = read_scenes_tsv();
  ASSERT_GT(rows.size(), 80u);
  // Real class names: every tag SOFA's lists mention, minus the macros, plus the
  // plugin declarations that SCENES.tsv leaves out.
  std::set<std::string> classes{"RequiredPlugin"};
  for (const SceneRow& r : rows) {
    for (const std::string& c : r.components) {
      if (!is_macro_name(c)) classes.insert(c);
    }
  }
  const auto known = [&](std::string_view t) { return classes.count(std::string(t)) > 0; };
  const ResourcePaths paths = sofa_paths();
  for (const SceneRow& row : rows) {
    SCOPED_TRACE(row.scene);
    const std::string scene = (data_dir() / "examples" / row.scene).string();

    Diagnostics raw_diag;
    const auto raw = load_scene_tree(scene, paths, all_known, raw_diag);
    ASSERT_TRUE(raw.has_value());
    EXPECT_FALSE(raw_diag.has_errors()) << Diagnostics::format(*first_of(raw_diag, Severity::error));
    std::set<std::string> raw_tags;
    collect_component_tags(*raw, raw_tags);
    raw_tags.erase("RequiredPlugin");
    EXPECT_EQ(raw_tags, row.components);

    Diagnostics diag;
    const auto root = load_scene_tree(scene, paths, known, diag);
    ASSERT_TRUE(root.has_value());
    for (const Message& m : diag.messages()) {
      EXPECT_NE(m.severity, Severity::error) << Diagnostics::format(m);
    }
    std::set<std::string> expanded;
    collect_component_tags(*root, expanded);
    for (const std::string& t : expanded) {
      EXPECT_FALSE(is_macro_name(t)) << t << " was not expanded";
      EXPECT_TRUE(classes.count(t)) << t << " is not a class used by the regression scenes";
    }
  }
}
