#include "roomscout/sim/builtin_worlds.hpp"

#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "../support/temp_dir.hpp"
#include "roomscout/core/errors.hpp"

namespace roomscout::sim {
namespace {

using roomscout::test::Contains;

TEST(BuiltinWorlds, NamesMatchTheEmbeddedFilesAndAreSorted) {
  const std::vector<std::string> names = builtinWorldNames();
  ASSERT_EQ(names.size(), embeddedWorlds().size());
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
  for (const std::string& name : names) EXPECT_TRUE(isBuiltinWorld(name)) << name;
  EXPECT_FALSE(isBuiltinWorld("no_such_world"));
  EXPECT_FALSE(isBuiltinWorld(""));
}

TEST(BuiltinWorlds, EveryEmbeddedWorldParses) {
  for (const std::string& name : builtinWorldNames()) {
    SCOPED_TRACE(name);
    try {
      const sim::World world = loadBuiltinWorld(name);
      EXPECT_EQ(world.source, "builtin:" + name);
      EXPECT_TRUE(world.start_given);
    } catch (const InputError& e) {
      ADD_FAILURE() << e.what();
    }
  }
}

TEST(BuiltinWorlds, UnknownNameListsTheKnownOnes) {
  try {
    loadBuiltinWorld("atlantis");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "builtin:atlantis");
    EXPECT_TRUE(Contains(e.what(), "builtin:atlantis: no such built-in world (known: "));
    for (const std::string& name : builtinWorldNames()) EXPECT_TRUE(Contains(e.what(), name));
  }
}

}  // namespace
}  // namespace roomscout::sim
