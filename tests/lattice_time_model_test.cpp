// TimeModel and TimeModels (lattice/time_model.hpp): names and parsing are
// inverse to each other, every selection has the models it says, and
// nothing else parses.
#include <gtest/gtest.h>

#include "lattice/time_model.hpp"

namespace gridlock {
namespace {

TEST(TimeModel, NamesAndParsingAreInverse) {
  for (TimeModel m : {TimeModel::Discrete, TimeModel::Continuous}) {
    ASSERT_TRUE(parse_time_model(time_model_name(m)).has_value());
    EXPECT_EQ(*parse_time_model(time_model_name(m)), m);
    const TimeModels only = TimeModels::only(m);
    EXPECT_TRUE(only.has(m));
    EXPECT_FALSE(only.has(m == TimeModel::Discrete ? TimeModel::Continuous : TimeModel::Discrete));
    EXPECT_STREQ(only.name(), time_model_name(m));
  }
  for (const char* name : {"discrete", "continuous", "both"}) {
    ASSERT_TRUE(TimeModels::parse(name).has_value()) << name;
    EXPECT_STREQ(TimeModels::parse(name)->name(), name);
  }
  EXPECT_TRUE(TimeModels::both().has(TimeModel::Discrete));
  EXPECT_TRUE(TimeModels::both().has(TimeModel::Continuous));
  for (const char* bad : {"", "Discrete", "both ", "none", "discrete,continuous"}) {
    EXPECT_FALSE(parse_time_model(bad).has_value()) << bad;
    EXPECT_FALSE(TimeModels::parse(bad).has_value()) << bad;
  }
  EXPECT_EQ(TimeModels{}, TimeModels::only(TimeModel::Discrete));  // verify's default
}

}  // namespace
}  // namespace gridlock
