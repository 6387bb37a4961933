// Allocation checks of sizes read from scenes.
#include <gtest/gtest.h>

#include <string>

#include "core/alloc_check.h"

using namespace sinew;

TEST(AllocCheck, BoundsByPhysicalMemory) {
  EXPECT_GT(physical_memory_bytes(), 1u << 20);
  EXPECT_TRUE(allocation_fits(1000, 64));
  EXPECT_FALSE(allocation_fits(1e9, 1e6));
  EXPECT_FALSE(allocation_fits(-1, 8));
  EXPECT_EQ(format_bytes(96e9), "96 GB");
}
