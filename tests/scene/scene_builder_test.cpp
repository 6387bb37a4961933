// Scene building: factory errors, attribute checks, links, src=, includes, default names
// (spec/framework.md §1.2, §1.3, §1.9, §2.3–§2.5, traps T15, T17).
#include "scene/builder.h"

#include <gtest/gtest.h>

#include "engine/box_roi.h"
#include "mass/uniform_mass.h"
#include "projective/fixed_projective_constraint.h"
#include "runner/session.h"
#include "solver/linear/cg_linear_solver.h"
#include "solver/ode/euler_implicit_solver.h"
#include "state/mechanical_object.h"
#include "test_scene.h"
#include "topology/grid/regular_grid_topology.h"

using namespace sinew;
using sinew::test::any_contains;
using sinew::test::build;
using sinew::test::get;
using sinew::test::load;
using sinew::test::messages;

namespace {

const Message* first(const Diagnostics& d, Severity s) {
  for (const Message& m : d.messages())
    if (m.severity == s) return &m;
  return nullptr;
}

}  // namespace

// ---------------------------------------------------------------- unknown components (§1.3, T15)

// §1.3 step 8: unknown class → error at file:line with suggestions; loading goes on; the scene
// is refused as a whole.
TEST(SceneBuilder, UnknownComponentIsAnErrorWithLineAndSuggestion) {
  sinew::test::TempDir dir;
  const std::string path = dir.write("bad.scn",
                                     "<Node name=\"root\">\n"
                                     "  <MechanicalObject name=\"dofs\"/>\n"
                                     "  <UniformMas name=\"m\" vertexMass=\"1\"/>\n"
                                     "  <UniformMass name=\"mass\" vertexMass=\"1\"/>\n"
                                     "</Node>\n");
  runner::Session session(path, {});
  ASSERT_TRUE(session.loaded());
  EXPECT_FALSE(session.ok());
  EXPECT_FALSE(session.step());
  const Message* err = first(session.diagnostics(), Severity::error);
  ASSERT_NE(err, nullptr);
  EXPECT_EQ(err->where.line, 3);
  EXPECT_NE(err->where.file.find("bad.scn"), std::string::npos);
  const std::string text = Diagnostics::format(*err);
  EXPECT_NE(text.find("bad.scn:3:"), std::string::npos) << text;
  EXPECT_NE(text.find("UniformMas"), std::string::npos) << text;
  EXPECT_NE(text.find("did you mean 'UniformMass'"), std::string::npos) << text;
  // Loading continued after the bad element.
  EXPECT_NE(get<UniformMass>(session.root(), "mass"), nullptr);
  EXPECT_EQ(get<UniformMass>(session.root(), "m"), nullptr);
  ASSERT_EQ(session.missing().size(), 1u);
  EXPECT_EQ(session.missing()[0].type, "UniformMas");
  EXPECT_EQ(session.missing()[0].where.line, 3);
}

// §1.5 / T15: renamed classes are created silently under the new name (default name from the new class).
TEST(SceneBuilder, RenamedClassIsCreatedSilently) {
  auto s = build(R"(<Node>
    <MechanicalObject/>
    <FixedConstraint/>
  </Node>)");
  auto* fix = get<FixedProjectiveConstraint>(*s.root, "FixedProjectiveConstraint1");
  ASSERT_NE(fix, nullptr);
  EXPECT_EQ(fix->class_name(), "FixedProjectiveConstraint");
  EXPECT_EQ(s.root->diagnostics().error_count(), 0);
  EXPECT_EQ(s.root->diagnostics().warning_count(), 0);
}

// §1.3 step 7: UniformMass without template in a Rigid3d node becomes UniformMass<Rigid3d>.
TEST(SceneBuilder, TemplateIsDeducedFromTheNodesState) {
  auto s = build(R"(<Node>
    <MechanicalObject template="Rigid3d"/>
    <UniformMass name="mass"/>
  </Node>)");
  auto* m = get<UniformMass>(*s.root, "mass");
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->template_name(), "Rigid3d");
  EXPECT_EQ(s.root->diagnostics().error_count(), 0);
}

// §1.4: template aliases (Vec3 silently, Rigid with a deprecation warning).
TEST(SceneBuilder, TemplateAliases) {
  auto s = build(R"(<Node>
    <MechanicalObject name="a" template="Vec3"/>
    <Node name="c"><MechanicalObject name="b" template="Rigid"/></Node>
  </Node>)");
  EXPECT_EQ(get<MechanicalObject>(*s.root, "a")->state_type(), StateType::vec3);
  auto* b = get<MechanicalObject>(*s.root->find_child_named("c"), "b");
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->state_type(), StateType::rigid3);
  EXPECT_EQ(b->template_name(), "Rigid3d");
  const auto w = messages(s.root->diagnostics(), Severity::warning);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("deprecated"), std::string::npos);
  EXPECT_EQ(s.root->diagnostics().error_count(), 0);
}

// §1.3 step 8: an explicit template incompatible with the context is an error, but the
// component is created with a compatible one.
TEST(SceneBuilder, WrongExplicitTemplateIsAnErrorButTheComponentExists) {
  auto s = build(R"(<Node>
    <MechanicalObject template="Rigid3d"/>
    <UniformMass name="mass" template="Vec3d" vertexMass="1"/>
  </Node>)");
  auto* m = get<UniformMass>(*s.root, "mass");
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->template_name(), "Rigid3d");
  EXPECT_TRUE(any_contains(messages(s.root->diagnostics(), Severity::error), "Vec3d"));
  EXPECT_FALSE(s.ok());
}

// ---------------------------------------------------------------- attributes (§1.9)

// §1.2 step 3.5: unknown attributes → "unused attribute" warning with a suggestion.
TEST(SceneBuilder, UnknownAttributeIsAWarningWithSuggestion) {
  auto s = build("<Node>\n  <MechanicalObject name=\"dofs\" positon=\"1 2 3\"/>\n</Node>");
  const auto w = messages(s.root->diagnostics(), Severity::warning);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("test.scn:2:"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("'positon'"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("did you mean 'position'"), std::string::npos) << w[0];
  EXPECT_EQ(s.root->diagnostics().error_count(), 0);
  EXPECT_TRUE(s.ok());
}

// §1.2: attributes starting with '_' or 'NO' are ignored silently.
TEST(SceneBuilder, UnderscoreAndNOAttributesAreIgnoredSilently) {
  auto s = build(R"(<Node>
    <MechanicalObject name="dofs" _comment="anything" NOtranslation="1 2 3" position="1 2 3"/>
  </Node>)");
  EXPECT_EQ(s.root->diagnostics().warning_count(), 0);
  EXPECT_EQ(s.root->diagnostics().error_count(), 0);
  EXPECT_EQ(get<MechanicalObject>(*s.root, "dofs")->translation.value(), Vec3::Zero());
}

TEST(SceneBuilder, UnknownNodeAttributeIsAWarningWithSuggestion) {
  auto s = build(R"(<Node gravty="0 0 0"><Node name="c" _x="1"/></Node>)");
  const auto w = messages(s.root->diagnostics(), Severity::warning);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("did you mean 'gravity'"), std::string::npos) << w[0];
}

// §1.9 step 4: a value that cannot be read is a warning; loading continues.
TEST(SceneBuilder, UnreadableValueIsAWarning) {
  auto s = build(R"(<Node><MechanicalObject name="dofs" showObject="yes"/></Node>)");
  EXPECT_TRUE(any_contains(messages(s.root->diagnostics(), Severity::warning), "showObject"));
  EXPECT_TRUE(s.ok());
}

// §1.8: node attributes are node fields.
TEST(SceneBuilder, NodeAttributesSetTheContext) {
  auto s = build(R"(<Node dt="0.005" gravity="0 0 -1"><Node name="c" activated="0"/></Node>)");
  EXPECT_EQ(s.root->dt.value(), 0.005);
  EXPECT_EQ(s.root->gravity.value(), Vec3(0, 0, -1));
  EXPECT_FALSE(s.root->find_child_named("c")->activated.value());
}

// ---------------------------------------------------------------- default names (T17)

// T17: unnamed objects are ClassName1, ClassName2, ... counted per node and per class.
TEST(SceneBuilder, DefaultNamesAreCountedPerNodeAndClass) {
  auto s = build(R"(<Node>
    <MechanicalObject/>
    <UniformMass vertexMass="1"/>
    <MechanicalObject/>
    <Node name="child"><MechanicalObject/></Node>
  </Node>)");
  const auto& objs = s.root->objects();
  ASSERT_EQ(objs.size(), 3u);
  EXPECT_EQ(objs[0]->name.value(), "MechanicalObject1");
  EXPECT_EQ(objs[1]->name.value(), "UniformMass1");
  EXPECT_EQ(objs[2]->name.value(), "MechanicalObject2");
  Node* child = s.root->find_child_named("child");
  ASSERT_NE(child, nullptr);
  EXPECT_EQ(child->objects()[0]->name.value(), "MechanicalObject1");
}

// ---------------------------------------------------------------- links (§2.3, §2.5)

// §2.5: a data link to an object declared later is resolved after loading.
TEST(SceneBuilder, DataLinkToALaterObjectResolves) {
  auto s = load(R"(<Node dt="0.01">
    <EulerImplicitSolver/>
    <CGLinearSolver iterations="25" tolerance="1e-9" threshold="1e-20"/>
    <MechanicalObject name="dofs" position="0 0 0  1 1 1  5 5 5"/>
    <UniformMass vertexMass="1"/>
    <FixedProjectiveConstraint name="fix" indices="@roi.indices"/>
    <BoxROI name="roi" box="0 0 0 1 1 1"/>
  </Node>)");
  auto* fix = get<FixedProjectiveConstraint>(*s.root, "fix");
  auto* roi = get<BoxROI>(*s.root, "roi");
  ASSERT_NE(fix, nullptr);
  ASSERT_NE(roi, nullptr);
  EXPECT_EQ(fix->indices.parent(), &roi->indices);
  EXPECT_EQ(fix->indices.get(), (std::vector<unsigned>{0, 1}));
  animate(*s.root);
  const auto& x = get<MechanicalObject>(*s.root, "dofs")->position.get().data;
  EXPECT_EQ(x[1], 0.0);
  EXPECT_EQ(x[4], 1.0);
  EXPECT_LT(x[7], 5.0);
}

// A data link that resolves to nothing is warned about and the field is left as if not
// given (SOFA goes on too; some of its examples hold such links, e.g. BoxROI
// position="@../Volume.position" in TriangularForceFieldComparison.scn).
TEST(SceneBuilder, UnresolvableDataLinkWarnsAndLeavesTheFieldUnset) {
  auto s = build(R"(<Node>
    <MechanicalObject name="dofs"/>
    <FixedProjectiveConstraint name="fix" indices="@ghost.indices"/>
  </Node>)");
  EXPECT_TRUE(any_contains(messages(s.root->diagnostics(), Severity::warning), "cannot resolve link indices=\"@ghost.indices\""));
  EXPECT_EQ(s.root->diagnostics().error_count(), 0);
  auto* fix = get<FixedProjectiveConstraint>(*s.root, "fix");
  ASSERT_NE(fix, nullptr);
  EXPECT_FALSE(fix->indices.is_set());
  EXPECT_EQ(fix->indices.value(), fix->indices.default_value());
}

// §2.5: object links are resolved for every object after loading (forward links work).
TEST(SceneBuilder, ForwardObjectLinkResolves) {
  auto s = build(R"(<Node>
    <EulerImplicitSolver name="ode" linearSolver="@cg"/>
    <CGLinearSolver name="cg"/>
  </Node>)");
  auto* ode = get<EulerImplicitSolver>(*s.root, "ode");
  ASSERT_NE(ode, nullptr);
  EXPECT_EQ(ode->linear_solver.get(), get<CGLinearSolver>(*s.root, "cg"));
  EXPECT_EQ(s.root->diagnostics().error_count(), 0);
}

TEST(SceneBuilder, UnresolvableObjectLinkIsAnError) {
  auto s = build(R"(<Node><EulerImplicitSolver name="ode" linearSolver="@nothing"/></Node>)");
  EXPECT_TRUE(any_contains(messages(s.root->diagnostics(), Severity::error), "linearSolver"));
}

// ---------------------------------------------------------------- src= (§2.4)

// §2.4: src="@grid" links same-named fields (here `position`) of the source.
TEST(SceneBuilder, SrcLinksSameNamedFields) {
  auto s = load(R"(<Node>
    <RegularGridTopology name="grid" n="2 2 2" min="0 0 0" max="1 1 1"/>
    <MechanicalObject name="dofs" src="@grid"/>
  </Node>)");
  auto* grid = get<RegularGridTopology>(*s.root, "grid");
  auto* mo = get<MechanicalObject>(*s.root, "dofs");
  ASSERT_NE(mo, nullptr);
  EXPECT_EQ(mo->position.parent(), &grid->position);
  ASSERT_EQ(mo->size(), 8u);
  EXPECT_EQ(mo->position.get().data[21], 1.0);  // point 7 = (1,1,1)
  EXPECT_EQ(mo->name.value(), "dofs");
}

// §2.4 step 4: name, printLog, tags, listening never propagate through src.
TEST(SceneBuilder, SrcDoesNotLinkNonAutolinkFields) {
  auto s = build(R"(<Node>
    <RegularGridTopology name="grid" printLog="1" tags="a"/>
    <MechanicalObject name="dofs" src="@grid"/>
  </Node>)");
  auto* mo = get<MechanicalObject>(*s.root, "dofs");
  ASSERT_NE(mo, nullptr);
  EXPECT_EQ(mo->name.parent(), nullptr);
  EXPECT_EQ(mo->print_log.parent(), nullptr);
  EXPECT_EQ(mo->tags.parent(), nullptr);
  EXPECT_EQ(mo->listening.parent(), nullptr);
  EXPECT_FALSE(mo->print_log.get());
}

// §2.4 step 3: attributes given explicitly on the element are not linked.
TEST(SceneBuilder, SrcSkipsExplicitAttributes) {
  auto s = load(R"(<Node>
    <RegularGridTopology name="grid" n="2 2 2"/>
    <MechanicalObject name="dofs" src="@grid" position="5 5 5  6 6 6"/>
  </Node>)");
  auto* mo = get<MechanicalObject>(*s.root, "dofs");
  ASSERT_NE(mo, nullptr);
  EXPECT_EQ(mo->position.parent(), nullptr);
  EXPECT_EQ(mo->position.get().data, (std::vector<double>{5, 5, 5, 6, 6, 6}));
}

// §2.4 step 2: a missing source object is an error.
TEST(SceneBuilder, SrcToAMissingObjectIsAnError) {
  auto s = build(R"(<Node><MechanicalObject name="dofs" src="@loader"/></Node>)");
  EXPECT_TRUE(any_contains(messages(s.root->diagnostics(), Severity::error), "loader"));
}

// ---------------------------------------------------------------- include (§1.6)

// §1.6: a missing include file is an error at the include's line; the scene is refused.
TEST(SceneBuilder, MissingIncludeIsAnErrorAtItsLine) {
  sinew::test::TempDir dir;
  const std::string path = dir.write("inc.scn",
                                     "<Node>\n"
                                     "  <MechanicalObject/>\n"
                                     "  <include href=\"nope.xml\"/>\n"
                                     "  <UniformMass vertexMass=\"1\"/>\n"
                                     "</Node>\n");
  runner::Session session(path, {});
  EXPECT_FALSE(session.ok());
  const Message* err = first(session.diagnostics(), Severity::error);
  ASSERT_NE(err, nullptr);
  EXPECT_EQ(err->where.line, 3);
  EXPECT_NE(err->where.file.find("inc.scn"), std::string::npos);
  EXPECT_NE(err->text.find("nope.xml"), std::string::npos);
}

TEST(SceneBuilder, IncludedFileIsExpandedInPlace) {
  sinew::test::TempDir dir;
  dir.write("part.xml", "<Node name=\"Group\">\n  <UniformMass name=\"mass\" vertexMass=\"2\"/>\n</Node>\n");
  const std::string path = dir.write("main.scn",
                                     "<Node>\n"
                                     "  <MechanicalObject name=\"dofs\" position=\"0 0 0\"/>\n"
                                     "  <include href=\"part.xml\"/>\n"
                                     "</Node>\n");
  runner::Session session(path, {});
  EXPECT_TRUE(session.ok());
  auto* m = get<UniformMass>(session.root(), "mass");
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->mass(), 2.0);
}

// Two animation loops in one node (SOFA's DeformableOnRigidFrameMappingConstraints.scn):
// the last one is kept, as SOFA's single link does, and the warning names both
// and points at the second's line (the newcomer is named before insertion).
TEST(SceneBuilder, SecondAnimationLoopReplacesTheFirstWithBothNamed) {
  scene::LoadedScene s =
      build("<Node name='root'>\n<FreeMotionAnimationLoop/>\n<FreeMotionAnimationLoop name='last'/>\n</Node>");
  ASSERT_TRUE(s.root);
  const auto warnings = messages(s.root->diagnostics(), Severity::warning);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find(":3: warning: only one animation loop is permitted in node 'root': component "
                             "'FreeMotionAnimationLoop1' (FreeMotionAnimationLoop) replaced by component 'last' "
                             "(FreeMotionAnimationLoop)"),
            std::string::npos)
      << warnings[0];
  ASSERT_NE(s.root->animation_loop, nullptr);
  EXPECT_EQ(static_cast<Component*>(s.root->animation_loop)->name.value(), "last");
}
