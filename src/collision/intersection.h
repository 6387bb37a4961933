// Intersection: an intersection method (DiscreteIntersection,
// MinProximityIntersection, NewProximityIntersection, ...): the table of
// element tests per pair of model kinds and the cube–cube test the bounding
// trees are traversed with (spec/interaction.md §2.2).
#pragma once

#include <array>
#include <vector>

#include "collision/collision_model.h"
#include "collision/detection_output.h"

namespace sinew {

class Intersection;

// Tests element i1 of m1 against element i2 of m2 (m1, m2 in the orientation
// the pair was registered with); appends the contacts found, returns their count.
using ElementTest = int (*)(const Intersection&, const CollisionModelBase& m1, unsigned i1,
                            const CollisionModelBase& m2, unsigned i2, std::vector<DetectionOutput>& out);

class Intersection : public Component {
 public:
  using Kind = CollisionModelBase::Kind;

  // Distances of the method (0 for DiscreteIntersection) [length].
  virtual double alarm_distance() const = 0;
  virtual double contact_distance() const = 0;

  // Continuous methods (CCD) bound each element's motion over the step.
  virtual CollisionModelBase::Motion continuous_motion() const { return CollisionModelBase::Motion::none; }
  virtual bool use_continuous() const { return false; }
  // Whether the tests read the models' neighbourhood views (LocalMinDistance's filters).
  virtual bool uses_neighbourhoods() const { return false; }

  // Called at the start of every detection (refreshes what the tests read from the fields).
  virtual void begin_detection() {}

  // Cube–cube test of the bounding trees: proximity methods enlarge by
  // alarm + both models' skins; the discrete method by alarm only.
  virtual double cube_margin(const CollisionModelBase& m1, const CollisionModelBase& m2) const {
    return alarm_distance() + m1.contact_distance.value() + m2.contact_distance.value();
  }

  // The test for models of kinds (k1, k2); swap is set when the test was
  // registered the other way round (call it with the models swapped).
  // nullptr: no test (unsupported pair, or ignored on purpose).
  ElementTest find(Kind k1, Kind k2, bool& swap) const;

 protected:
  void add(Kind k1, Kind k2, ElementTest test);
  void ignore(Kind k1, Kind k2) { add(k1, k2, nullptr); }

 private:
  struct Entry {
    bool registered = false;
    ElementTest test = nullptr;
  };
  std::array<std::array<Entry, CollisionModelBase::kKinds>, CollisionModelBase::kKinds> table_{};
};

}  // namespace sinew
