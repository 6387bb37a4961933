#include "collision/intersection.h"

namespace sinew {

void Intersection::add(Kind k1, Kind k2, ElementTest test) {
  Entry& e = table_[static_cast<int>(k1)][static_cast<int>(k2)];
  e.registered = true;
  e.test = test;
}

ElementTest Intersection::find(Kind k1, Kind k2, bool& swap) const {
  swap = false;
  const Entry& direct = table_[static_cast<int>(k1)][static_cast<int>(k2)];
  if (direct.registered) return direct.test;
  const Entry& reverse = table_[static_cast<int>(k2)][static_cast<int>(k1)];
  if (reverse.registered && reverse.test) {
    swap = true;
    return reverse.test;
  }
  return nullptr;
}

}  // namespace sinew
