// Registry: renamed classes, template aliases, template deduction and fallbacks
// (spec/framework.md §1.3–§1.5, trap T15). Uses a local Registry filled with
// test classes; the real components are exercised in the tests of their
// modules (tests/forcefield, tests/mass, ...).
#include "core/registry.h"

#include <gtest/gtest.h>

#include <memory>

#include "core/node.h"
#include "core/roles.h"
#include "fake_roles.h"

using namespace sinew;
using sinew::fakes::TestState;

namespace {


// A "mass" whose template must match the state's type.
class FakeMass final : public Component {
 public:
  explicit FakeMass(std::string t) : tmpl(std::move(t)) {}
  std::string tmpl;
};

class Plain final : public Component {};

bool contains(const std::vector<std::string>& v, std::string_view needle) {
  for (const auto& s : v)
    if (s.find(needle) != std::string::npos) return true;
  return false;
}

// Local registry: UniformMass-like class (state requirement), a plain class with an
// alias, and the new names of two renamed classes.
struct LocalRegistry {
  Registry reg;
  LocalRegistry() {
    ComponentInfo mass;
    mass.name = "UniformMass";
    mass.templates = {"Vec1d", "Vec3d", "Rigid3d"};
    mass.default_template = "Vec3d";
    mass.requirement = Requirement::state;
    mass.create = [](const std::string& t) { return std::make_unique<FakeMass>(t); };
    reg.add(std::move(mass));

    ComponentInfo plain;
    plain.name = "PlainThing";
    plain.aliases = {"OldPlainThing"};
    plain.create = creator<Plain>();
    reg.add(std::move(plain));

    for (const char* n : {"FixedProjectiveConstraint", "SpringForceField"}) {
      ComponentInfo i;
      i.name = n;
      i.create = creator<Plain>();
      reg.add(std::move(i));
    }
  }
};

void add_state(Node& n, StateType t) { n.add_object(std::make_unique<TestState>(t)); }

}  // namespace

// ---------------------------------------------------------------- tables

// §1.5: renamed classes are mapped silently.
TEST(RegistryNames, RenamedComponents) {
  EXPECT_EQ(renamed_component("FixedConstraint"), "FixedProjectiveConstraint");
  EXPECT_EQ(renamed_component("StiffSpringForceField"), "SpringForceField");
  EXPECT_EQ(renamed_component("ShewchukPCGLinearSolver"), "PCGLinearSolver");
  EXPECT_EQ(renamed_component("MechanicalObject"), "MechanicalObject");
}

// §1.4: Vec3 → Vec3d silently.
TEST(RegistryTemplates, ShortAliasesResolveWithoutDeprecation) {
  std::vector<std::string> dep;
  EXPECT_EQ(resolve_template_alias("Vec3", &dep), "Vec3d");
  EXPECT_EQ(resolve_template_alias("Rigid3", &dep), "Rigid3d");
  EXPECT_EQ(resolve_template_alias("Vec3d", &dep), "Vec3d");
  EXPECT_TRUE(dep.empty());
}

// §1.4: Vec3f → Vec3d and Rigid → Rigid3d are deprecated.
TEST(RegistryTemplates, FloatAndRigidAliasesAreDeprecated) {
  std::vector<std::string> dep;
  EXPECT_EQ(resolve_template_alias("Vec3f", &dep), "Vec3d");
  ASSERT_EQ(dep.size(), 1u);
  EXPECT_NE(dep[0].find("Vec3f"), std::string::npos);
  dep.clear();
  EXPECT_EQ(resolve_template_alias("Rigid", &dep), "Rigid3d");
  ASSERT_EQ(dep.size(), 1u);
  EXPECT_NE(dep[0].find("Rigid3d"), std::string::npos);
}

// §1.3 step 2: comma-separated templates are resolved token by token; unknown tokens kept.
TEST(RegistryTemplates, CommaSeparatedTokensResolveEach) {
  EXPECT_EQ(resolve_template_alias("Rigid3,Vec3"), "Rigid3d,Vec3d");
  EXPECT_EQ(resolve_template_alias("Vec3,Banana"), "Vec3d,Banana");
  EXPECT_EQ(resolve_template_alias(""), "");
}

// ---------------------------------------------------------------- lookup

TEST(Registry, FindByNameOrAlias) {
  LocalRegistry r;
  ASSERT_NE(r.reg.find("PlainThing"), nullptr);
  EXPECT_EQ(r.reg.find("OldPlainThing"), r.reg.find("PlainThing"));
  EXPECT_EQ(r.reg.find("Nope"), nullptr);
  EXPECT_EQ(r.reg.names(), (std::vector<std::string>{"FixedProjectiveConstraint", "PlainThing",
                                                      "SpringForceField", "UniformMass"}));
}

// §1.3 step 3: a renamed class is created under its new name without any message.
TEST(Registry, RenamedClassIsCreatedSilently) {
  LocalRegistry r;
  Node node("root");
  auto fixed = r.reg.create("FixedConstraint", "", node, {});
  ASSERT_NE(fixed.component, nullptr);
  EXPECT_TRUE(fixed.errors.empty());
  EXPECT_TRUE(fixed.warnings.empty());
  auto spring = r.reg.create("StiffSpringForceField", "", node, {});
  EXPECT_NE(spring.component, nullptr);
}

// §1.3 step 8: an unknown class produces no component and an error.
TEST(Registry, UnknownClassProducesNoComponent) {
  LocalRegistry r;
  Node node("root");
  auto c = r.reg.create("UniformMas", "", node, {});
  EXPECT_EQ(c.component, nullptr);
  ASSERT_FALSE(c.errors.empty());
  EXPECT_TRUE(contains(c.errors, "cannot be found in the factory"));
}

// §1.3 step 7: without `template`, a single-state component takes the node's state type
// (UniformMass in a Rigid3d node becomes UniformMass<Rigid3d>), with no message.
TEST(Registry, TemplateDeducedFromTheNodesState) {
  LocalRegistry r;
  Node node("root");
  add_state(node, StateType::rigid3);
  auto c = r.reg.create("UniformMass", "", node, {});
  ASSERT_NE(c.component, nullptr);
  EXPECT_EQ(c.used_template, "Rigid3d");
  EXPECT_EQ(static_cast<FakeMass*>(c.component.get())->tmpl, "Rigid3d");
  EXPECT_TRUE(c.errors.empty());
  EXPECT_TRUE(c.warnings.empty());
}

// §3.3: the state may come from an ancestor.
TEST(Registry, TemplateDeducedFromAnAncestorsState) {
  LocalRegistry r;
  Node root("root");
  add_state(root, StateType::vec1);
  Node* c = root.add_child(std::make_unique<Node>("child"));
  auto made = r.reg.create("UniformMass", "", *c, {});
  ASSERT_NE(made.component, nullptr);
  EXPECT_EQ(made.used_template, "Vec1d");
}

TEST(Registry, DefaultTemplateWhenItFits) {
  LocalRegistry r;
  Node node("root");
  add_state(node, StateType::vec3);
  auto c = r.reg.create("UniformMass", "", node, {});
  EXPECT_EQ(c.used_template, "Vec3d");
  EXPECT_TRUE(c.errors.empty());
}

// §1.3 step 8: an explicit template that does not fit the context gives an error, but the
// component is still created with the first compatible template.
TEST(Registry, ExplicitWrongTemplateIsAnErrorButStillCreates) {
  LocalRegistry r;
  Node node("root");
  add_state(node, StateType::rigid3);
  auto c = r.reg.create("UniformMass", "Vec3d", node, {});
  ASSERT_NE(c.component, nullptr);
  EXPECT_EQ(c.used_template, "Rigid3d");
  ASSERT_FALSE(c.errors.empty());
  EXPECT_TRUE(contains(c.errors, "Vec3d"));
}

TEST(Registry, UnknownTemplateIsAnErrorButStillCreates) {
  LocalRegistry r;
  Node node("root");
  add_state(node, StateType::vec3);
  auto c = r.reg.create("UniformMass", "Banana", node, {});
  ASSERT_NE(c.component, nullptr);
  EXPECT_EQ(c.used_template, "Vec3d");
  ASSERT_FALSE(c.errors.empty());
  EXPECT_TRUE(contains(c.errors, "Banana"));
}

// §1.4: a deprecated alias is resolved and reported as a warning.
TEST(Registry, DeprecatedTemplateAliasIsAWarning) {
  LocalRegistry r;
  Node node("root");
  add_state(node, StateType::rigid3);
  auto c = r.reg.create("UniformMass", "Rigid", node, {});
  ASSERT_NE(c.component, nullptr);
  EXPECT_EQ(c.used_template, "Rigid3d");
  EXPECT_TRUE(c.errors.empty());
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_TRUE(contains(c.warnings, "deprecated"));

  Node vnode("v");
  add_state(vnode, StateType::vec3);
  auto v = r.reg.create("UniformMass", "Vec3f", vnode, {});
  EXPECT_EQ(v.used_template, "Vec3d");
  EXPECT_EQ(v.warnings.size(), 1u);
  EXPECT_TRUE(v.errors.empty());
}

// §1.3 step 8: a state-dependent component without any state cannot be created.
TEST(Registry, NoStateMeansNoComponent) {
  LocalRegistry r;
  Node node("root");
  auto c = r.reg.create("UniformMass", "", node, {});
  EXPECT_EQ(c.component, nullptr);
  EXPECT_TRUE(contains(c.errors, "cannot be created"));
}

// §1.3 step 7: with mstate="@path" the linked state decides the template.
TEST(Registry, MstateAttributeChoosesTheState) {
  LocalRegistry r;
  Node root("root");
  add_state(root, StateType::vec3);
  Node* other = root.add_child(std::make_unique<Node>("other"));
  auto rigid = std::make_unique<TestState>(StateType::rigid3);
  rigid->name.set("rigidDofs");
  other->add_object(std::move(rigid));
  AttributeMap attrs;
  attrs.set("mstate", "@other/rigidDofs");
  auto c = r.reg.create("UniformMass", "", root, attrs);
  ASSERT_NE(c.component, nullptr);
  EXPECT_EQ(c.used_template, "Rigid3d");
}
