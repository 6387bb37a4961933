// A unit mass on a unit spring to its rest position, no gravity, started at
// x = 1, v = 0 along x: the exact motion is x(t) = cos t, v(t) = −sin t.
// Shared by the ODE solver tests (orders of convergence, energy, first steps).
#pragma once

#include <cmath>
#include <string>

#include "state/mechanical_object.h"
#include "test_scene.h"

namespace sinew::test {

inline std::string oscillator_scene(const std::string& solver, double dt, double stiffness = 1.0) {
  return "<Node dt=\"" + std::to_string(dt) + "\" gravity=\"0 0 0\"><DefaultAnimationLoop/>" + solver +
         "<MechanicalObject name=\"dofs\" position=\"0 0 0\" rest_position=\"0 0 0\"/>"
         "<UniformMass totalMass=\"1\"/><RestShapeSpringsForceField stiffness=\"" +
         std::to_string(stiffness) + "\"/></Node>";
}

struct Oscillator {
  scene::LoadedScene s;
  MechanicalObject* mo = nullptr;
  explicit Oscillator(const std::string& solver, double dt, double stiffness = 1.0)
      : s(load(oscillator_scene(solver, dt, stiffness))) {
    mo = get<MechanicalObject>(*s.root, "dofs");
    mo->write(kPosition)[0] = 1.0;
  }
  double x() const { return mo->read(kPosition)[0]; }
  double v() const { return mo->read(kVelocity)[0]; }
  void step(int n = 1) {
    for (int i = 0; i < n; ++i) animate(*s.root);
  }
  // Energy ½v² + ½k x² with k = 1.
  double energy() const { return 0.5 * v() * v() + 0.5 * x() * x(); }
};

// Position error at t = T after T/dt steps.
inline double oscillator_error(const std::string& solver, double dt, double T = 1.0) {
  Oscillator o(solver, dt);
  o.step(static_cast<int>(std::lround(T / dt)));
  return std::abs(o.x() - std::cos(T));
}

}  // namespace sinew::test
