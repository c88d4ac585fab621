// SPDX-License-Identifier: MIT
#include <tutti/components/instrument.hpp>

#include <gtest/gtest.h>

TEST(InstrumentComponent, DefaultsToNoInstrumentAndNoPlayer) {
  const tutti::components::Instrument i;
  EXPECT_TRUE(i.id.empty());
  EXPECT_TRUE(i.performer.is_null());
}
