// ParticleSource and ParticleSink: particle counts while the simulation runs,
// with and without a dynamic point topology; the mass follows (count × mass).
#include <gtest/gtest.h>

#include <string>

#include "core/roles.h"
#include "core/simulation.h"
#include "sph/particle_sink.h"
#include "sph/particle_source.h"
#include "test_scene.h"

namespace sinew {
namespace {

// Three emission points, one layer every 0.25 s from t = 0 (dt = 0.125: exact binary times).
std::string scene(bool topology, double sink_d1, const std::string& source_extra = "") {
  return std::string("<Node dt='0.125' gravity='0 -10 0'><DefaultAnimationLoop/>"
                     "<Node name='p'><EulerExplicitSolver symplectic='1'/><MechanicalObject name='dofs'/>") +
         (topology ? "<PointSetTopologyContainer name='con'/><PointSetTopologyModifier name='mod'/>" : "") +
         "<ParticleSource name='src' center='0 0 0  1 0 0  0 0 1' translation='0 5 0' velocity='0 -1 0' "
         "delay='0.25' start='0' stop='100' addNoise='0' " + source_extra + "/>"
         "<UniformMass name='mass' vertexMass='2'/>"
         "<ParticleSink name='sink' normal='0 1 0' d0='" + std::to_string(sink_d1 + 0.5) + "' d1='" +
         std::to_string(sink_d1) + "'/></Node></Node>";
}

TEST(ParticleSource, EmitsOneLayerPerDelay) {
  auto s = test::load(scene(true, -1000));
  ASSERT_TRUE(s.root);
  Node* p = s.root->find_child_named("p");
  auto* src = test::get<ParticleSource>(*p, "src");
  MechanicalState& st = *p->mechanical_state;
  for (int step = 1; step <= 20; ++step) {
    animate(*s.root);
    // Steps begin at t = (step-1)·0.125; a layer is due each 0.25 s after t = 0.
    const std::size_t layers = static_cast<std::size_t>((step - 1) / 2);
    ASSERT_EQ(src->emitted(), 3 * layers) << "step " << step;
    if (layers > 0) {
      EXPECT_EQ(st.size(), 3 * layers) << "step " << step;  // the MechanicalObject's default DoF is reused
      EXPECT_DOUBLE_EQ(p->mass->total(), 2.0 * static_cast<double>(st.size()));
    }
  }
  // The newest layer is driven along its emission velocity: it sits on the emission line.
  const std::vector<double>& x = st.read(kPosition);
  const std::vector<double>& v = st.read(kVelocity);
  const std::size_t last = st.size() - 1;
  EXPECT_DOUBLE_EQ(v[3 * last + 1], -1.0);
  EXPECT_DOUBLE_EQ(x[3 * last + 2], 1.0);
  EXPECT_LE(x[3 * last + 1], 5.0);
  EXPECT_GT(x[3 * last + 1], 5.0 - 0.25 - 1e-12);
}

TEST(ParticleSource, WithoutTopologyTheStateIsResized) {
  auto s = test::load(scene(false, -1000));
  ASSERT_TRUE(s.root);
  Node* p = s.root->find_child_named("p");
  for (int step = 0; step < 9; ++step) animate(*s.root);
  EXPECT_EQ(p->mechanical_state->size(), 12u);  // layers at t = 0.25, 0.5, 0.75, 1.0
}

TEST(ParticleSink, RemovesWhatCrossesThePlane) {
  for (bool topology : {true, false}) {
    // Particles start at y = 5 with v = -1 and fall under gravity: they cross y = -1 after ≈ 1 s.
    auto s = test::load(scene(topology, -1.0));
    ASSERT_TRUE(s.root);
    Node* p = s.root->find_child_named("p");
    auto* src = test::get<ParticleSource>(*p, "src");
    auto* sink = test::get<ParticleSink>(*p, "sink");
    MechanicalState& st = *p->mechanical_state;
    std::size_t max_removed = 0;
    for (int step = 0; step < 60; ++step) {
      animate(*s.root);
      // Every particle ever emitted is either still here or was removed (the MechanicalObject's
      // default DoF, above the plane, was reused by the first layer).
      const std::size_t expected = src->emitted() == 0 ? 1 : src->emitted();
      ASSERT_EQ(st.size() + sink->removed(), expected) << "step " << step << " topology " << topology;
      const std::vector<double>& x = st.read(kPosition);
      max_removed = sink->removed();
      // Whatever is below d0 at the end of a step was stopped there (zero velocity).
      const std::vector<double>& vel = st.read(kVelocity);
      for (std::size_t i = 0; i < st.size(); ++i)
        if (x[3 * i + 1] < -0.5) {
          EXPECT_EQ(vel[3 * i + 1], 0.0);
        }
    }
    // Without a topology UniformMass keeps the DoF list of its init (SOFA's indices: the single
    // default DoF), so the later particles keep their emission velocity (-1) and need 6 s to fall.
    EXPECT_GT(max_removed, topology ? 20u : 5u) << "topology " << topology;
    if (topology) {
      EXPECT_DOUBLE_EQ(p->mass->total(), 2.0 * static_cast<double>(st.size()));
    }
  }
}

TEST(ParticleSink, StopsParticlesBelowD0) {
  auto s = test::load(scene(true, -1000));
  ASSERT_TRUE(s.root);
  Node* p = s.root->find_child_named("p");
  auto* sink = test::get<ParticleSink>(*p, "sink");
  sink->d0.set(4.0);
  for (int step = 0; step < 24; ++step) animate(*s.root);
  const std::vector<double>& x = p->mechanical_state->read(kPosition);
  const std::vector<double>& v = p->mechanical_state->read(kVelocity);
  std::size_t stopped = 0;
  for (unsigned i : sink->fixed.value()) {
    EXPECT_LT(x[3 * i + 1], 4.0);
    EXPECT_EQ(v[3 * i + 1], 0.0);
    ++stopped;
  }
  EXPECT_GT(stopped, 0u);
}

TEST(ParticleSink, StaticTopologyIsRefused) {
  auto s = test::build(
      "<Node dt='0.01'><DefaultAnimationLoop/><Node name='p'><EulerExplicitSolver/>"
      "<MechanicalObject position='0 0 0 1 0 0'/><MeshTopology position='0 0 0 1 0 0'/><UniformMass/>"
      "<ParticleSink name='sink' d1='-1'/></Node></Node>");
  ASSERT_TRUE(s.root);
  init_root(*s.root);
  auto* sink = test::get<ParticleSink>(*s.root->find_child_named("p"), "sink");
  ASSERT_NE(sink, nullptr);
  EXPECT_EQ(sink->state(), ComponentState::invalid);
}

}  // namespace
}  // namespace sinew
