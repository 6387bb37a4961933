// Link cycles: the bound on BaseField::update() and the cycle finder the scene
// builder uses (fields linked in a ring, engines feeding their own inputs).
#include <gtest/gtest.h>

#include <string>

#include "core/base.h"
#include "core/engine.h"
#include "core/field.h"

using namespace sinew;

namespace {

class Owner final : public Base {
 public:
  explicit Owner(std::string n) : n_(std::move(n)) {}
  std::string describe() const override { return "owner '" + n_ + "'"; }

 private:
  std::string n_;
};

class Copy final : public Engine {
 public:
  Field<int> in{this, "in", 1, "input"};
  Field<int> out{this, "out", 0, "output"};
  Copy() {
    add_input(&in);
    add_output(&out);
  }

 protected:
  void do_update() override { out.raw() = in.value(); }
};

}  // namespace

TEST(LinkCycle, UpdateOfACycleMadeByCodeReturnsInsteadOfOverflowingTheStack) {
  Owner a("a"), b("b"), c("c");
  Field<int> fa(&a, "x", 1, ""), fb(&b, "x", 2, ""), fc(&c, "x", 3, "");
  fa.set_parent(&fb);
  fb.set_parent(&fc);
  fc.set_parent(&fa);
  (void)fa.get();  // was: unbounded recursion, SIGSEGV
  (void)fb.get();
  SUCCEED();
}

TEST(LinkCycle, FinderListsEachCycleOnceInDependencyOrder) {
  Owner a("a"), b("b"), c("c"), d("d");
  Field<int> fa(&a, "x", 1, ""), fb(&b, "y", 2, ""), fc(&c, "z", 3, ""), fd(&d, "w", 4, "");
  fa.set_parent(&fb);
  fb.set_parent(&fc);
  fc.set_parent(&fa);
  fd.set_parent(&fa);  // depends on the cycle, not part of it
  a.where = {"s.scn", 3};
  const auto cycles = find_field_cycles({&fd, &fa, &fb, &fc});
  ASSERT_EQ(cycles.size(), 1u);
  ASSERT_EQ(cycles[0].size(), 3u);
  EXPECT_EQ(cycles[0][0], &fa);
  EXPECT_EQ(cycles[0][1], &fb);
  EXPECT_EQ(cycles[0][2], &fc);
  EXPECT_EQ(describe_field_cycle(cycles[0]),
            "owner 'a'.x (s.scn:3) → owner 'b'.y → owner 'c'.z → owner 'a'.x");
}

TEST(LinkCycle, FinderFollowsEngines) {
  Copy e;
  e.in.set_parent(&e.out);
  const auto cycles = find_field_cycles({&e.in, &e.out});
  ASSERT_EQ(cycles.size(), 1u);
  EXPECT_EQ(cycles[0].size(), 2u);
}

TEST(LinkCycle, ChainsAndSharedParentsAreNoCycle) {
  Owner a("a");
  Field<int> f1(&a, "1", 1, ""), f2(&a, "2", 1, ""), f3(&a, "3", 1, "");
  f2.set_parent(&f1);
  f3.set_parent(&f1);
  EXPECT_TRUE(find_field_cycles({&f1, &f2, &f3}).empty());
}
