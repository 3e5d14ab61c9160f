// Box3: empty when any axis is (a box cut down by an overlap can lose any one of them), and
// its extent then zero.
#include <gtest/gtest.h>

#include "util/math.hpp"

namespace convray {
namespace {

TEST(Box3, EmptyWhenAnyAxisIsEmpty) {
  EXPECT_TRUE(Box3{}.empty());
  EXPECT_FALSE((Box3{Vec3(0.0), Vec3(1.0)}.empty()));
  EXPECT_FALSE((Box3{Vec3(1.0), Vec3(1.0)}.empty()));  // a point is a box
  for (int axis = 0; axis < 3; ++axis) {
    Box3 box{Vec3(0.0), Vec3(1.0)};
    box.lo[axis] = 2.0;
    EXPECT_TRUE(box.empty()) << axis;
    EXPECT_EQ(box.extent(), Vec3(0.0)) << axis;
  }
}

TEST(Box3, ExtendFromEmptyHoldsExactlyThePoints) {
  Box3 box;
  box.extend(Vec3(1, -2, 3));
  box.extend(Vec3(-1, 4, 0));
  EXPECT_FALSE(box.empty());
  EXPECT_EQ(box.lo, Vec3(-1, -2, 0));
  EXPECT_EQ(box.hi, Vec3(1, 4, 3));
  EXPECT_EQ(box.extent(), Vec3(2, 6, 3));
}

}  // namespace
}  // namespace convray
