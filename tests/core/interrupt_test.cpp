// The user-interrupt flag (Ctrl-C in `sinew run`).
#include <gtest/gtest.h>

#include <string>

#include "core/interrupt.h"

using namespace sinew;

TEST(Interrupt, FlagSetAndCleared) {
  clear_interrupt();
  EXPECT_FALSE(interrupt_requested());
  request_interrupt();
  EXPECT_TRUE(interrupt_requested());
  clear_interrupt();
  EXPECT_FALSE(interrupt_requested());
}
