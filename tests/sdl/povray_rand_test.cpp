// seed() and rand() against POV-Ray 3.7's own numbers: the same scene is read by the installed
// povray and by our parser, and every number is printed with 20 decimals by both (`str(V, 0,
// 20)`), so the texts must agree character for character.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "povray_debug.hpp"

namespace convray::sdl {
namespace {

using povray_testing::convray_debug;
using povray_testing::povray_run;

// `draws` numbers of each seed, one stream after the other.
std::string draws_of_seeds(const std::string& seeds, int draws) {
  const auto count = 1 + std::count(seeds.begin(), seeds.end(), ',');
  return "#declare Seeds = array[" + std::to_string(count) + "] { " + seeds +
         " }\n"
         "#for (J, 0, dimension_size(Seeds, 1) - 1)\n"
         "  #declare S = seed(Seeds[J]);\n"
         "  #for (I, 1, " +
         std::to_string(draws) +
         ")\n"
         "    #debug concat(str(rand(S), 0, 20), \"\\n\")\n"
         "  #end\n"
         "#end\n";
}

TEST(PovRayRand, TheDocumentedFirstNumbersOfSeed7) {
  // The example of issue 16, as POV-Ray 3.7 prints it (and without povray installed).
  EXPECT_EQ(convray_debug(draws_of_seeds("7", 3)),
            "0.95393288064606784893\n0.61046628039573935798\n0.16685213571573889735\n");
}

TEST(PovRayRand, ManySeedsAndDrawsAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  // Small, large and negative seeds, fractions (truncated), and seeds past 32 bits.
  const std::string scene =
      draws_of_seeds("0, 1, 2, 7, 42, 123, 12345, 65535, 99999, -1, -2, -7.5, 1.7, 0.999, -0.5, "
                     "2147483647, 2147483647.5, 2147483648, 4294967295, 4294967299, "
                     "-2147483648, -2147483649, 1e12, -1e12, 1e30",
                     40) +
      "#for (K, 1000, 1100) #declare S = seed(K); #debug concat(str(rand(S), 0, 20), \" \", "
      "str(rand(S), 0, 20), \"\\n\") #end\n";
  const auto pov = povray_run(scene);
  ASSERT_EQ(pov.exit_code, 0) << pov.messages;
  ASSERT_FALSE(pov.debug.empty()) << pov.messages;
  EXPECT_EQ(convray_debug(scene), pov.debug);
}

TEST(PovRayRand, StreamsAreIndependentAndSharedThroughCopiesAsPovRay) {
  SKIP_WITHOUT_POVRAY();
  // Two streams drawn in turn; a copy of a stream's handle draws from the same stream.
  const std::string scene =
      "#declare A = seed(3);\n#declare B = seed(3);\n#declare C = A;\n"
      "#for (I, 1, 20)\n"
      "  #debug concat(str(rand(A), 0, 20), \" \", str(rand(B), 0, 20), \" \", "
      "str(rand(C), 0, 20), \"\\n\")\n"
      "#end\n";
  const auto pov = povray_run(scene);
  ASSERT_EQ(pov.exit_code, 0) << pov.messages;
  EXPECT_EQ(convray_debug(scene), pov.debug);
}

}  // namespace
}  // namespace convray::sdl
