// Link paths on a hand-built graph (spec/framework.md §2.3, trap T14).
#include "core/path.h"

#include <gtest/gtest.h>

#include <memory>

#include "core/component.h"
#include "core/node.h"

using namespace sinew;

namespace {

class Foo final : public Component {
 public:
  Field<std::vector<double>> position{this, "position", {}, "some data"};
};
class Bar final : public Component {};

template <class T>
T* add(Node& n, const std::string& name) {
  auto c = std::make_unique<T>();
  c->name.set(name);
  return static_cast<T*>(n.add_object(std::move(c)));
}

Node* child(Node& parent, const std::string& name) { return parent.add_child(std::make_unique<Node>(name)); }

bool any(Base*) { return true; }
bool is_foo(Base* b) { return dynamic_cast<Foo*>(b) != nullptr; }
bool is_bar(Base* b) { return dynamic_cast<Bar*>(b) != nullptr; }

// root
//   objects: rootFoo (Foo), dup (Bar)
//   dup/      (child node with the same name as an object)
//     dupFoo (Foo)
//   body/
//     a (Foo), b (Bar), c (Foo)
//     leaf/
//       l0 (Bar)
struct Graph {
  Node root{"root"};
  Foo* root_foo;
  Bar* dup_obj;
  Node* dup;
  Foo* dup_foo;
  Node* body;
  Foo* a;
  Bar* b;
  Foo* c;
  Node* leaf;
  Bar* l0;
  Graph() {
    root_foo = add<Foo>(root, "rootFoo");
    dup_obj = add<Bar>(root, "dup");
    dup = child(root, "dup");
    dup_foo = add<Foo>(*dup, "dupFoo");
    body = child(root, "body");
    a = add<Foo>(*body, "a");
    b = add<Bar>(*body, "b");
    c = add<Foo>(*body, "c");
    leaf = child(*body, "leaf");
    l0 = add<Bar>(*leaf, "l0");
  }
};

}  // namespace

// §2.3 rule 5: a child node with the name wins over an object with the same name.
TEST(PathResolution, ChildNodeShadowsObjectOfTheSameName) {
  Graph g;
  EXPECT_EQ(resolve_object_path(g.root, nullptr, "@dup", any), static_cast<Base*>(g.dup));
}

TEST(PathResolution, PlainNameFindsAnObjectInTheCurrentNode) {
  Graph g;
  EXPECT_EQ(resolve_object_path(*g.body, g.a, "@b", any), static_cast<Base*>(g.b));
}

// §2.3 rule 5: the first element searches upward through the ancestors.
TEST(PathResolution, FirstElementSearchesUpward) {
  Graph g;
  EXPECT_EQ(resolve_object_path(*g.leaf, g.l0, "@rootFoo", any), static_cast<Base*>(g.root_foo));
  EXPECT_EQ(resolve_object_path(*g.leaf, g.l0, "@a", any), static_cast<Base*>(g.a));
}

// §2.3 rule 5: a path starting with ./ is anchored: no upward search.
TEST(PathResolution, AnchoredPathDoesNotSearchUpward) {
  Graph g;
  std::string why;
  EXPECT_EQ(resolve_object_path(*g.leaf, g.l0, "@./rootFoo", any, &why), nullptr);
  EXPECT_NE(why.find("rootFoo"), std::string::npos);
}

// §2.3 rule 5: only the first element searches upward; later ones must be exactly there.
TEST(PathResolution, LaterElementsDoNotSearchUpward) {
  Graph g;
  std::string why;
  EXPECT_EQ(resolve_object_path(*g.leaf, g.l0, "@body/rootFoo", any, &why), nullptr);
  EXPECT_FALSE(why.empty());
  EXPECT_EQ(resolve_object_path(*g.leaf, g.l0, "@body/leaf/l0", any), static_cast<Base*>(g.l0));
}

// §2.3 rule 2: [k] is relative to the owner's position in its node.
TEST(PathResolution, RelativeIndexCountsFromTheOwner) {
  Graph g;
  EXPECT_EQ(resolve_object_path(*g.body, g.c, "@[-1]", any), static_cast<Base*>(g.b));
  EXPECT_EQ(resolve_object_path(*g.body, g.c, "@[-2]", any), static_cast<Base*>(g.a));
  EXPECT_EQ(resolve_object_path(*g.body, g.c, "@[0]", any), static_cast<Base*>(g.c));
  std::string why;
  EXPECT_EQ(resolve_object_path(*g.body, g.c, "@[-3]", any, &why), nullptr);
  EXPECT_FALSE(why.empty());
}

// §2.3 rule 1: "@" alone is the owner.
TEST(PathResolution, EmptyPathIsTheOwner) {
  Graph g;
  EXPECT_EQ(resolve_object_path(*g.body, g.b, "@", any), static_cast<Base*>(g.b));
}

// Found by fuzz_link_paths: "@" and "@[k]" returned an object the predicate refuses
// (a multi-link then dropped it without a word); they are checked like every path.
TEST(PathResolution, OwnerAndRelativeIndexAreCheckedAgainstTheType) {
  Graph g;
  std::string why;
  EXPECT_EQ(resolve_object_path(*g.body, g.b, "@", is_foo, &why), nullptr);
  EXPECT_NE(why.find("wrong type"), std::string::npos) << why;
  why.clear();
  EXPECT_EQ(resolve_object_path(*g.body, g.c, "@[-1]", is_foo, &why), nullptr);  // b is a Bar
  EXPECT_NE(why.find("wrong type"), std::string::npos) << why;
  EXPECT_EQ(resolve_object_path(*g.body, g.c, "@[-2]", is_foo), static_cast<Base*>(g.a));
}

// §2.3 rule 3: a leading / starts from the root.
TEST(PathResolution, AbsolutePathStartsAtTheRoot) {
  Graph g;
  EXPECT_EQ(resolve_object_path(*g.leaf, g.l0, "@/body/c", any), static_cast<Base*>(g.c));
  EXPECT_EQ(resolve_object_path(*g.leaf, g.l0, "@/dup/dupFoo", any), static_cast<Base*>(g.dup_foo));
  EXPECT_EQ(resolve_object_path(*g.leaf, g.l0, "@/rootFoo", any), static_cast<Base*>(g.root_foo));
}

// §2.3 rule 4: ../ goes to the parent node.
TEST(PathResolution, DotDotGoesToTheParent) {
  Graph g;
  EXPECT_EQ(resolve_object_path(*g.leaf, g.l0, "@../a", any), static_cast<Base*>(g.a));
  EXPECT_EQ(resolve_object_path(*g.leaf, g.l0, "@../../rootFoo", any), static_cast<Base*>(g.root_foo));
  std::string why;
  // Anchored by ../: the object of the grandparent is not found in the parent.
  EXPECT_EQ(resolve_object_path(*g.leaf, g.l0, "@../rootFoo", any, &why), nullptr);
}

// §2.3 rule 6: ending on a node takes the unique object of the requested type.
TEST(PathResolution, EndingOnANodeTakesTheUniqueObjectOfTheType) {
  Graph g;
  EXPECT_EQ(resolve_object_path(*g.leaf, g.l0, "@..", is_bar), static_cast<Base*>(g.b));
  EXPECT_EQ(resolve_object_path(g.root, nullptr, "@dup", is_foo), static_cast<Base*>(g.dup_foo));
  EXPECT_EQ(resolve_object_path(*g.leaf, g.l0, "@/body", is_bar), static_cast<Base*>(g.b));
}

// §2.3 rule 6: two candidates are ambiguous → failure.
TEST(PathResolution, EndingOnANodeWithSeveralCandidatesFails) {
  Graph g;
  std::string why;
  EXPECT_EQ(resolve_object_path(*g.leaf, g.l0, "@..", is_foo, &why), nullptr);
  EXPECT_NE(why.find("several"), std::string::npos);
}

TEST(PathResolution, ObjectOfTheWrongTypeFails) {
  Graph g;
  std::string why;
  EXPECT_EQ(resolve_object_path(*g.body, g.a, "@b", is_foo, &why), nullptr);
  EXPECT_NE(why.find("wrong type"), std::string::npos);
}

TEST(PathResolution, MissingNameGivesNullAndAReason) {
  Graph g;
  std::string why;
  EXPECT_EQ(resolve_object_path(*g.body, g.a, "@nowhere", any, &why), nullptr);
  EXPECT_NE(why.find("nowhere"), std::string::npos);
  why.clear();
  EXPECT_EQ(resolve_object_path(*g.body, g.a, "@leaf/missing", any, &why), nullptr);
  EXPECT_NE(why.find("missing"), std::string::npos);
}

// §2.3: "@[-1].position" is the data link used by scenes.
TEST(FieldLinkResolution, RelativeIndexDataLink) {
  Graph g;
  // c is after b (a Bar without 'position'), so use [-2] to reach a.
  EXPECT_EQ(resolve_field_link(*g.body, g.c, "@[-2].position"), &g.a->position);
  std::string why;
  EXPECT_EQ(resolve_field_link(*g.body, g.c, "@[-1].position", &why), nullptr);
  EXPECT_NE(why.find("position"), std::string::npos);
}

TEST(FieldLinkResolution, PathAndFieldName) {
  Graph g;
  EXPECT_EQ(resolve_field_link(*g.leaf, g.l0, "@/body/c.position"), &g.c->position);
  EXPECT_EQ(resolve_field_link(*g.leaf, g.l0, "@../a.position"), &g.a->position);
  EXPECT_EQ(resolve_field_link(*g.leaf, g.l0, "@rootFoo.name"), &g.root_foo->name);
}

// §2.3: "@.foo" is the field foo of the owner itself.
TEST(FieldLinkResolution, DotFieldIsTheOwnersField) {
  Graph g;
  EXPECT_EQ(resolve_field_link(*g.body, g.a, "@.position"), &g.a->position);
}

// §2.3: the last '.' after the last '/' separates the field name.
TEST(FieldLinkResolution, LinkWithoutFieldNameFails) {
  Graph g;
  std::string why;
  EXPECT_EQ(resolve_field_link(*g.body, g.a, "@../body", &why), nullptr);
  EXPECT_FALSE(why.empty());
}

TEST(FieldLinkResolution, MissingObjectGivesNullAndAReason) {
  Graph g;
  std::string why;
  EXPECT_EQ(resolve_field_link(*g.body, g.a, "@ghost.position", &why), nullptr);
  EXPECT_NE(why.find("ghost"), std::string::npos);
}

// Nodes have fields too: "@/.dt" style links reach node data.
TEST(FieldLinkResolution, NodeFieldThroughAbsolutePath) {
  Graph g;
  EXPECT_EQ(resolve_field_link(*g.leaf, g.l0, "@/body.name"), &g.body->name);
}
