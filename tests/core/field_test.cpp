// Fields: versions, lazy links, cross-type copies and lazy engines
// (spec/framework.md §2.1, §2.5, §2.6).
#include "core/field.h"

#include <gtest/gtest.h>

#include "core/base.h"
#include "core/engine.h"

using namespace sinew;

namespace {

// A minimal owner of fields.
class Owner final : public Base {
 public:
  std::string describe() const override { return "owner"; }
};

// Counts do_update() calls: out = 2·in + offset.
class Doubler final : public Engine {
 public:
  Field<int> in{this, "in", 1, "input"};
  Field<int> offset{this, "offset", 0, "second input"};
  Field<int> out{this, "out", 0, "output"};
  int runs = 0;
  Doubler() {
    add_input(&in);
    add_input(&offset);
    add_output(&out);
  }

 protected:
  void do_update() override {
    ++runs;
    out.set(2 * in.get() + offset.get());
  }
};

}  // namespace

// ---------------------------------------------------------------- versions and isSet

TEST(Field, DefaultValueAndNotSet) {
  Owner o;
  Field<double> f{&o, "stiffness", 2.5, "help"};
  EXPECT_EQ(f.get(), 2.5);
  EXPECT_EQ(f.default_value(), 2.5);
  EXPECT_FALSE(f.is_set());
  EXPECT_EQ(f.default_text(), "2.5");
  EXPECT_EQ(f.type_name(), "double");
}

TEST(Field, RegistersWithItsOwnerAndIsFoundByNameOrAlias) {
  Owner o;
  Field<std::vector<Vec3>> f{&o, "position", {}, "points"};
  f.add_alias("points");
  EXPECT_EQ(o.fields().size(), 1u);
  EXPECT_EQ(o.find_field("position"), &f);
  EXPECT_EQ(o.find_field("points"), &f);
  EXPECT_EQ(o.find_field("positions"), nullptr);
}

// §2.1: every write bumps the version and marks the field set; reading does not.
TEST(Field, EditBumpsVersionAndMarksSet) {
  Owner o;
  Field<int> f{&o, "n", 3, ""};
  const auto v0 = f.version();
  f.edit() = 4;
  EXPECT_EQ(f.version(), v0 + 1);
  EXPECT_TRUE(f.is_set());
  EXPECT_EQ(f.get(), 4);
  EXPECT_EQ(f.version(), v0 + 1);  // get() is not a write
}

TEST(Field, SetBumpsVersionAndMarksSet) {
  Owner o;
  Field<int> f{&o, "n", 3, ""};
  const auto v0 = f.version();
  f.set(8);
  EXPECT_EQ(f.version(), v0 + 1);
  EXPECT_TRUE(f.is_set());
  EXPECT_EQ(f.value(), 8);
}

TEST(Field, ReadBumpsVersionMarksSetAndReportsFailure) {
  Owner o;
  Field<double> f{&o, "x", 3, ""};
  const auto v0 = f.version();
  EXPECT_TRUE(f.read("1.25"));
  EXPECT_EQ(f.value(), 1.25);
  EXPECT_EQ(f.version(), v0 + 1);
  EXPECT_TRUE(f.is_set());
  EXPECT_FALSE(f.read("nope"));  // SOFA keeps whatever the parser left: 0
  EXPECT_EQ(f.value(), 0.0);
  EXPECT_EQ(f.version(), v0 + 2);
  EXPECT_EQ(f.text(), "0");
}

TEST(Field, FlatVecReadsInGroupsOfItsWidth) {
  Owner o;
  Field<FlatVec> f{&o, "position", FlatVec{7, {}}, ""};
  EXPECT_TRUE(f.read("1 2 3 0 0 0 1  4 5 6 0 0 0 1  9"));
  EXPECT_EQ(f.value().size(), 2u);
  EXPECT_EQ(f.value().data[7], 4.0);
  EXPECT_EQ(f.row_width(), 7);
}

// ---------------------------------------------------------------- links

// §2.5: a linked field copies its parent's value when read (lazily).
TEST(FieldLink, ChildFollowsParentLazily) {
  Owner o;
  Field<double> parent{&o, "a", 1.0, ""};
  Field<double> child{&o, "b", 5.0, ""};
  child.set_parent(&parent);
  EXPECT_TRUE(child.is_set());  // linking marks the field set
  EXPECT_EQ(child.parent(), &parent);
  EXPECT_EQ(child.get(), 1.0);

  parent.set(2.0);
  EXPECT_EQ(child.value(), 1.0);  // nothing pushed eagerly
  EXPECT_EQ(child.get(), 2.0);    // pulled on read
}

TEST(FieldLink, ChildVersionBumpsOnlyWhenParentChanged) {
  Owner o;
  Field<int> parent{&o, "a", 1, ""};
  Field<int> child{&o, "b", 0, ""};
  child.set_parent(&parent);
  child.get();
  const auto v1 = child.version();
  child.get();
  EXPECT_EQ(child.version(), v1);  // parent unchanged: no copy
  parent.set(3);
  child.get();
  EXPECT_EQ(child.version(), v1 + 1);
}

// §2.5: local edits survive until the parent changes, then are overwritten.
TEST(FieldLink, LocalEditIsOverwrittenWhenParentChanges) {
  Owner o;
  Field<int> parent{&o, "a", 1, ""};
  Field<int> child{&o, "b", 0, ""};
  child.set_parent(&parent);
  EXPECT_EQ(child.get(), 1);
  child.edit() = 42;
  EXPECT_EQ(child.get(), 42);
  parent.set(7);
  EXPECT_EQ(child.get(), 7);
}

// A write before the first read stands too (the sparse grid writes its src-linked cells at
// init, before anyone reads them); the next change of the parent still wins.
TEST(FieldLink, WriteBeforeTheFirstReadStandsUntilTheParentChanges) {
  Owner o;
  Field<int> parent{&o, "a", 1, ""};
  Field<int> child{&o, "b", 0, ""};
  child.set_parent(&parent);
  child.set(42);
  EXPECT_EQ(child.get(), 42);
  EXPECT_EQ(child.get(), 42);
  parent.set(7);
  EXPECT_EQ(child.get(), 7);

  Field<int> read_child{&o, "c", 0, ""};
  read_child.set_parent(&parent);
  EXPECT_TRUE(read_child.read("5"));
  EXPECT_EQ(read_child.get(), 5);
}

TEST(FieldLink, ChainsOfLinksPropagate) {
  Owner o;
  Field<int> a{&o, "a", 1, ""};
  Field<int> b{&o, "b", 0, ""};
  Field<int> c{&o, "c", 0, ""};
  b.set_parent(&a);
  c.set_parent(&b);
  EXPECT_EQ(c.get(), 1);
  a.set(9);
  EXPECT_EQ(c.get(), 9);
}

// §2.6: vector<Vec3> ← Rigid3 positions (width 7) receives the first 3 scalars (centres).
TEST(FieldLink, Vec3ListFromWidth7StateTakesTheCentres) {
  Owner o;
  Field<FlatVec> rigid{&o, "position", FlatVec{7, {1, 2, 3, 0, 0, 0, 1, 4, 5, 6, 0.5, 0.5, 0.5, 0.5}}, ""};
  Field<std::vector<Vec3>> points{&o, "points", {}, ""};
  points.set_parent(&rigid);
  ASSERT_EQ(points.get().size(), 2u);
  EXPECT_EQ(points.get()[0], Vec3(1, 2, 3));
  EXPECT_EQ(points.get()[1], Vec3(4, 5, 6));
}

// §2.6: Vec3 state ← vector<Vec3> copies rows; Vec3 state ← width 7 state takes the centres.
TEST(FieldLink, FlatVecOfDifferentWidthCopiesTheFirstScalars) {
  Owner o;
  Field<FlatVec> rigid{&o, "rigid", FlatVec{7, {1, 2, 3, 0, 0, 0, 1}}, ""};
  Field<FlatVec> vec3{&o, "vec3", FlatVec{3, {}}, ""};
  vec3.set_parent(&rigid);
  EXPECT_EQ(vec3.get().width, 3);
  EXPECT_EQ(vec3.get().data, (std::vector<double>{1, 2, 3}));

  Field<std::vector<Vec3>> pts{&o, "pts", {Vec3(7, 8, 9), Vec3(1, 1, 1)}, ""};
  Field<FlatVec> state{&o, "state", FlatVec{3, {}}, ""};
  state.set_parent(&pts);
  EXPECT_EQ(state.get().data, (std::vector<double>{7, 8, 9, 1, 1, 1}));
}

// §2.6 / framework §5.2: Rigid3d coordinates (width 7) linked to points receive the centres and
// the identity orientation (a resized SOFA RigidCoord vector), never the quaternion 0 0 0 0.
TEST(FieldLink, Width7StateFromPointsGetsIdentityOrientations) {
  Owner o;
  Field<std::vector<Vec3>> pts{&o, "pts", {Vec3(1, 2, 3), Vec3(4, 5, 6)}, ""};
  Field<FlatVec> rigid{&o, "rigid", FlatVec{7, {0, 0, 0, 0, 0, 0, 1}}, ""};
  rigid.set_parent(&pts);
  EXPECT_EQ(rigid.get().data, (std::vector<double>{1, 2, 3, 0, 0, 0, 1, 4, 5, 6, 0, 0, 0, 1}));
}

// SOFA copies a fixed-size parent into a list element by element: a Rigid3d position linked to
// a Vec3 (GeomagicDriver's positionBase) is one frame at that centre with the identity rotation.
TEST(FieldLink, Width7StateFromOneVec3IsOneFrame) {
  Owner o;
  Field<Vec3> base{&o, "positionBase", Vec3(1, 2, 3), ""};
  Field<FlatVec> rigid{&o, "position", FlatVec{7, {}}, ""};
  rigid.set_parent(&base);
  EXPECT_EQ(rigid.get().data, (std::vector<double>{1, 2, 3, 0, 0, 0, 1}));
  // A Vec1d state takes the first value only (SOFA: one element of min(1, 3) values).
  Field<FlatVec> vec1{&o, "x", FlatVec{1, {}}, ""};
  vec1.set_parent(&base);
  EXPECT_EQ(vec1.get().data, (std::vector<double>{1}));
}

// §2.6: types without rows go through text.
TEST(FieldLink, ScalarToStringGoesThroughText) {
  Owner o;
  Field<double> num{&o, "num", 0.25, ""};
  Field<std::string> str{&o, "str", "", ""};
  str.set_parent(&num);
  EXPECT_EQ(str.get(), "0.25");
  Field<int> integer{&o, "int", 0, ""};
  Field<std::string> txt{&o, "txt", "12", ""};
  integer.set_parent(&txt);
  EXPECT_EQ(integer.get(), 12);
}

// ---------------------------------------------------------------- engines

// §2.5: an engine runs when an output is read and an input changed, never otherwise.
TEST(Engine, RecomputesOnlyWhenAnInputChanged) {
  Doubler e;
  EXPECT_EQ(e.runs, 0);            // nothing eager
  EXPECT_EQ(e.out.get(), 2);       // first read runs it
  EXPECT_EQ(e.runs, 1);
  EXPECT_EQ(e.out.get(), 2);
  EXPECT_EQ(e.runs, 1);            // inputs unchanged
  e.in.set(5);
  EXPECT_EQ(e.runs, 1);            // still lazy
  EXPECT_EQ(e.out.get(), 10);
  EXPECT_EQ(e.runs, 2);
  e.offset.set(1);
  EXPECT_EQ(e.out.get(), 11);
  EXPECT_EQ(e.runs, 3);
}

TEST(Engine, OutputVersionBumpsOnEachRecompute) {
  Doubler e;
  e.out.get();
  const auto v = e.out.version();
  e.out.get();
  EXPECT_EQ(e.out.version(), v);
  e.in.set(2);
  e.out.get();
  EXPECT_GT(e.out.version(), v);
  EXPECT_TRUE(e.out.is_set());
}

TEST(Engine, SetDirtyForcesOneRecompute) {
  Doubler e;
  e.out.get();
  e.set_dirty();
  e.out.get();
  EXPECT_EQ(e.runs, 2);
  e.out.get();
  EXPECT_EQ(e.runs, 2);
}

// §2.5: an engine fed by a linked input re-evaluates after the upstream field changed.
TEST(Engine, LinkedInputChangeTriggersRecompute) {
  Owner o;
  Field<int> source{&o, "source", 4, ""};
  Doubler e;
  e.in.set_parent(&source);
  EXPECT_EQ(e.out.get(), 8);
  EXPECT_EQ(e.runs, 1);
  source.set(6);
  EXPECT_EQ(e.out.get(), 12);
  EXPECT_EQ(e.runs, 2);
  EXPECT_EQ(e.out.get(), 12);
  EXPECT_EQ(e.runs, 2);
}

// A field linked to an engine output pulls through the engine.
TEST(Engine, FieldLinkedToAnOutputRunsTheEngine) {
  Owner o;
  Doubler e;
  Field<int> consumer{&o, "consumer", 0, ""};
  consumer.set_parent(&e.out);
  EXPECT_EQ(consumer.get(), 2);
  e.in.set(21);
  EXPECT_EQ(consumer.get(), 42);
  EXPECT_EQ(e.runs, 2);
}

TEST(Field, UnitSlotDefaultsToNone) {
  Owner o;
  Field<double> k{&o, "stiffness", 1.0, "spring stiffness", "Spring", "force/length"};
  Field<int> n{&o, "iterations", 25, "maximum iterations"};
  EXPECT_STREQ(k.unit(), "force/length");
  EXPECT_STREQ(n.unit(), "");
  EXPECT_STREQ(o.find_field("stiffness")->unit(), "force/length");
}

// The change hook sees every write, and only writes.
TEST(Field, ChangeHookFollowsWritesNotReads) {
  Owner o;
  static int calls;
  calls = 0;
  Field<int> a{&o, "a", 1, "watched"};
  a.set_change_hook([](BaseField&) { ++calls; });
  (void)a.get();
  (void)a.value();
  EXPECT_EQ(calls, 0);
  a.set(2);
  a.edit() = 3;
  a.read("4");
  a.touch();
  EXPECT_EQ(calls, 4);
  EXPECT_EQ(a.value(), 4);
}
