// Reading instances in tests: from a string, or from examples/instances/.
// A reader error fails the current test (EXPECT) and returns what was read.
#pragma once

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "lattice/grid_format.hpp"

namespace gridlock::test {

inline Instance parse_instance(const std::string& text) {
  Instance inst;
  std::istringstream in(text);
  auto err = read_instance(in, "test.grid", inst);
  EXPECT_FALSE(err) << err->str();
  return inst;
}

inline Instance load_example(const std::string& name) {
  Instance inst;
  auto err = read_instance_file(std::string(GRIDLOCK_SOURCE_DIR) + "/examples/instances/" + name, inst);
  EXPECT_FALSE(err) << err->str();
  return inst;
}

}  // namespace gridlock::test
