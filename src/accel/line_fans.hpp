#pragma once
// Line queries through a common point, answered from short lists instead of a walk of Embree's
// hierarchy. A camera's rays all leave its eye, and the shadow rays of a point light all pass
// through the light: around such a point (an apex), the lines of a tile lie in a narrow cone,
// and the supports' bounding balls that the cone meets are few, listed once and tested by each
// line with the same ball-and-slab test (may_cross) the Embree callbacks apply. On a small
// soup whose supports are wide beside it (scenes/soup.pov), Embree's walk and its callback per
// box crossed were an eighth of a render; a list of a few dozen balls costs a tenth of that.
//
// Apexes are found from the queries themselves: two of the last few lines that pass within
// the tolerance of one another (and are not parallel) meet at a candidate apex, which a third
// line through it confirms (a camera ray and the shadow ray from its hit meet too, once). A
// cone is a double cone: lines through the apex in either direction (shadow rays leave their
// point towards the light). Its half angle keeps its width at the far side of the supports
// within a mean ball radius; its balls are sorted by their distance from the apex, so that a
// line's chunk [tmin, tmax] tests only those at its depths. A line outside every cone of its
// apex builds one around itself, testing groups of balls, then blocks, then balls (the
// triangles come in spatial order). An apex whose builds test many balls for each line its
// cones serve (rays far apart beside the balls) is given up on its thread, and its lines walk
// the hierarchy. An index of more than kFanBalls triangles has fans only where a line through
// its bounds meets at least kFanCandidates balls on average (worth_making): there a walk of
// the hierarchy costs a callback per ball (about 2,300 cycles a query on the dragon at R = 5),
// and a cone, built once for dozens of lines, far less. On the dragon (202,520 triangles,
// Table 1's view) fans made R = 5 0.956 of the time, R = 3.5 0.980, but R = 3 1.010 and R = 2
// 1.050 (a line meets about 194, 115, 92 and 55 balls there): fewer lines per cone, each
// with fewer candidates to save.
//
// The answer is the same set of candidates a walk would pass to the exact spans (every ball
// such a line meets is in its cone's list), so the intervals are the same; the caller orders
// them canonically. The lists are per thread and per index (keyed by a serial number, as
// addresses are reused).
#include <cstdint>
#include <utility>
#include <vector>

#include "accel/support_geometry.hpp"

namespace convray::accel {

class LineFans {
 public:
  // Fans for any index of at most this many triangles, and for larger ones where a line
  // through the bounds meets at least kFanCandidates balls on average (see above).
  static constexpr size_t kFanBalls = 16384;
  static constexpr double kFanCandidates = 100.0;
  // Whether an index over `sources` (all triangles) within `bounds` is given fans.
  static bool worth_making(const std::vector<detail::GeometrySource>& sources,
                           const Box3& bounds);
  // How many of the sources' balls a random line through `bounds` meets on average, by
  // Cauchy's formula.
  static double balls_per_line(const std::vector<detail::GeometrySource>& sources,
                               const Box3& bounds);

  // Over the triangle sources of an index (other kinds make no fans: the caller checks), whose
  // balls must outlive this.
  LineFans(const std::vector<detail::GeometrySource>& sources, const Box3& bounds);

  // Appends the candidates of the line (the balls of its cone that may_cross keeps) and
  // returns true, or returns false where no apex or cone serves it (the caller walks the
  // hierarchy instead).
  bool candidates(const detail::Line& line,
                  std::vector<detail::TriangleCandidate>& out) const;
  // The lists shared by every thread (not the per-thread cones).
  size_t memory_bytes() const;

 private:
  struct Entry {  // a ball and whose it is
    const detail::GeometrySource* source;
    uint32_t primitive;
  };
  struct Cone;
  struct Apex;
  struct State;
  State& state() const;
  Apex* confirm_apex(State& s, const detail::Line& line) const;
  struct Balls {  // bounding balls side by side
    std::vector<double> x, y, z, rho;
  };
  static void enclose(const std::vector<double>& x, const std::vector<double>& y,
                      const std::vector<double>& z, const std::vector<double>& rho, size_t n,
                      Balls& out);
  Cone& cone_for(Apex& apex, const Vec3& direction) const;
  void lay_out(Cone& cone, const Vec3& apex) const;
  std::pair<size_t, size_t> depths(const Cone& cone, const Vec3& apex,
                                   const detail::Line& line) const;
  // Returns how many balls it keeps; `scanned`: how many it tested.
  size_t scan(Cone& cone, const Vec3& apex, const detail::Line& line, size_t& scanned) const;

  std::vector<Entry> entries_;
  std::vector<double> x_, y_, z_, rho_;  // their balls' centres and grown radii, in lanes
  Balls blocks_, groups_;  // around each kBlock balls, and each kBlock blocks
  uint64_t serial_;
  Vec3 center_;          // of the supports' bounds
  double reach_;         // the bounds' half diagonal
  double mean_radius_;   // of the balls
  double tolerance_;     // how near an apex a line must pass
};

}  // namespace convray::accel
