// ProximityIntersection: what the proximity methods (MinProximity,
// NewProximity; later LocalMinDistance) share, SOFA's BaseProximityIntersection:
// the alarm and contact distances and their check.
#pragma once

#include "collision/intersection.h"

namespace sinew {

class ProximityIntersection : public Intersection {
 public:
  Field<double> alarm{this, "alarmDistance", 1.0, "distance below which pairs are reported", "Collision", "length"};
  Field<double> contact{this,        "contactDistance", 0.5, "distance the response keeps between the objects",
                        "Collision", "length"};

  double alarm_distance() const override { return alarm.value(); }
  double contact_distance() const override { return contact.value(); }

 protected:
  // False (and the component invalid, after an error) when a distance is negative or not a number.
  bool check_distances() {
    if (alarm.value() >= 0 && contact.value() >= 0) return true;
    msg_error("alarmDistance and contactDistance must be >= 0");
    set_state(ComponentState::invalid);
    return false;
  }
};

}  // namespace sinew
