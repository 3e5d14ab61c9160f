#include "accel/line_fans.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>

#include "util/bucket_sort.hpp"
#include "util/simd_width.hpp"

namespace convray::accel {
namespace {

// A cone's width at the far side of the supports, in mean ball radii: its list at one depth
// is then about twice one line's candidates there (the balls within a radius of a line), and
// a camera's tile of rays shares a few cones. (Half a radius: the same on scenes/soup.pov,
// and a bunny of 14,696 triangles at half a mean edge 1.25 times slower than without fans,
// from the builds; two radii: the soup 1.02 times a radius's time.)
constexpr double kConeWidth = 1.0;
// The cones of an apex, and the apexes, kept per index and thread (a camera's eye and a light
// or two; the cones of the tile being traced and its neighbours).
constexpr size_t kCones = 4;
constexpr size_t kApexes = 2;
// An apex is given up (its lines walk the hierarchy) once, after kTrialBuilds builds, what its
// cones cost exceeds what their lines save, counted in cone tests (a test of a ball, block or
// group against a cone, about 5 ns): laying out a member costs about two tests, scanning ten
// balls for a line one; a line served saves a walk of Embree's hierarchy, about 30 tests plus
// 4 for each candidate it lists (its callback). Fitted to the dragon's renders, fans against
// none: at R = 5 (202,520 triangles) 0.94 and on a 47,000-triangle version at R = 10 0.90,
// where the saving is twice the cost; the 871,000-triangle one at R = 2.5 1.06, where the
// cost is twice the saving (narrow cones, each serving 19 lines but holding 870 balls): where
// the balls are narrow beside the spacing of the lines, cones serve few lines each.
constexpr uint64_t kTestsPerLine = 30;
constexpr uint64_t kTestsPerCandidate = 4;
constexpr uint64_t kTestsPerMember = 2;
constexpr uint64_t kScannedPerTest = 10;
constexpr uint64_t kTrialBuilds = 8;
// Balls are grouped in blocks of kBlock consecutive ones (a mesh's triangles come in spatial
// order: scene/mesh_skeleton.cpp), blocks in groups of kBlock; a cone's build tests the
// groups' and blocks' bounding balls before their members'.
constexpr size_t kBlock = 32;
// Meeting points waiting for a third line (State::candidates), and the lines through no apex
// kept to meet the next ones (State::history).
constexpr size_t kCandidates = 4;
constexpr size_t kHistory = 3;

std::atomic<uint64_t> fans_made{0};

// Whether a ball (centre, rho) meets some line through `apex` within the cone's angle of
// `axis` (LineFans::cone_for says why); false for a NaN centre.
struct ConeTest {
  Vec3 apex, axis;
  double cos_angle, sin_angle;
  bool operator()(double x, double y, double z, double rho) const {
    const double vx = x - apex.x, vy = y - apex.y, vz = z - apex.z;
    const double d2 = vx * vx + vy * vy + vz * vz, r2 = rho * rho;
    const double along = std::abs(vx * axis.x + vy * axis.y + vz * axis.z);
    const double bound = cos_angle * std::sqrt(std::max(d2 - r2, 0.0)) - sin_angle * rho;
    return (d2 <= r2) | (along >= bound);
  }
};

}  // namespace

struct LineFans::Cone {
  Vec3 axis{0.0};
  double cos_angle = 2.0;  // |d.axis| >= cos_angle holds no line: an empty slot
  std::vector<uint32_t> members;  // into entries_
  // Their balls side by side for the scan, in whole SIMD widths (the padding's NaN centres
  // fail every test).
  std::vector<double> x, y, z, radius, nx, ny, nz, slab;
  // Sorted by the distance of their centres from the apex (`distance`), so that a line's
  // chunk [tmin, tmax] scans only the balls at its depths; the largest radius.
  std::vector<double> distance;
  double largest = 0.0;
  std::vector<double> pass;    // the scan's room: 1 where may_cross keeps the ball
  std::vector<uint32_t> kept;  // and their indices
};

struct LineFans::Apex {
  bool valid = false;
  bool off = false;  // given up (kTrialBuilds)
  Vec3 point{0.0};
  double angle = 0.0;  // its cones' half angle
  // Lines served, cones built, tests made, balls laid out, scanned and listed.
  uint64_t lines = 0, builds = 0, tests = 0, members = 0, scanned = 0, kept = 0;
  std::array<Cone, kCones> cones;
  unsigned next_cone = 0;
};

struct LineFans::State {
  uint64_t serial = 0;
  std::array<Apex, kApexes> apexes;
  unsigned next_apex = 0;
  // The last few lines through no apex, where new apexes are looked for.
  struct Seen {
    Vec3 origin, direction;
  };
  std::array<Seen, kHistory> history{};
  unsigned next_history = 0, history_count = 0;
  // Points where two lines met, waiting for a third line through them before they become
  // apexes: a camera ray and the shadow ray from its hit meet there, and nothing else does.
  std::array<Vec3, kCandidates> candidates{};
  unsigned next_candidate = 0, candidate_count = 0;
};

// Cauchy's formula: a convex body's mean shadow is a quarter of its surface area, so a random
// line through the bounds meets about (the balls' cross-sections, pi rho^2) / (area / 4).
double LineFans::balls_per_line(const std::vector<detail::GeometrySource>& sources,
                                const Box3& bounds) {
  double sections = 0.0;
  for (const detail::GeometrySource& s : sources) {
    for (uint32_t i = 0; i < s.count; ++i) {
      const double rho = s.balls[i].radius;
      sections += kPi * rho * rho;
    }
  }
  const Vec3 e = bounds.extent();
  const double area = 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
  return area > 0.0 ? 4.0 * sections / area : 0.0;
}

bool LineFans::worth_making(const std::vector<detail::GeometrySource>& sources,
                            const Box3& bounds) {
  size_t count = 0;
  for (const detail::GeometrySource& s : sources) count += s.count;
  if (count <= kFanBalls) return count > 0;
  return balls_per_line(sources, bounds) >= kFanCandidates;
}

size_t LineFans::memory_bytes() const {
  size_t bytes = entries_.capacity() * sizeof(Entry);
  for (const auto* v : {&x_, &y_, &z_, &rho_, &blocks_.x, &blocks_.y, &blocks_.z, &blocks_.rho,
                        &groups_.x, &groups_.y, &groups_.z, &groups_.rho}) {
    bytes += v->capacity() * sizeof(double);
  }
  return bytes;
}

LineFans::LineFans(const std::vector<detail::GeometrySource>& sources, const Box3& bounds)
    : serial_(++fans_made) {
  double radii = 0.0;
  for (const detail::GeometrySource& s : sources) {
    if (s.kind != detail::GeometrySource::Kind::triangle) continue;
    for (uint32_t i = 0; i < s.count; ++i) {
      entries_.push_back({&s, i});
      radii += s.balls[i].radius;
    }
  }
  center_ = 0.5 * (bounds.lo + bounds.hi);
  reach_ = 0.5 * glm::length(bounds.hi - bounds.lo);
  mean_radius_ = entries_.empty() ? 0.0 : radii / double(entries_.size());
  // Lines through an apex miss it by their rounding, and an apex found where two lines at a
  // small angle meet is off by that rounding over the angle (a light found from the shadow
  // rays of neighbouring pixels: 2e-7 of the scene's size): lists are made for lines within
  // this of the apex, their balls grown by as much, which adds no ball to speak of.
  tolerance_ = 1e-5 * mean_radius_;
  // Every ball side by side, for the cones' builds; rho grown by the tolerance (a line
  // passing that near the apex meets a ball only where its parallel through the apex meets
  // the grown ball) and by rounding.
  const size_t n = (entries_.size() + kBlock - 1) / kBlock * kBlock;  // whole blocks
  for (auto* v : {&x_, &y_, &z_, &rho_}) v->assign(n, std::numeric_limits<double>::quiet_NaN());
  for (size_t k = 0; k < entries_.size(); ++k) {
    const BoundingBall& ball = entries_[k].source->balls[entries_[k].primitive];
    x_[k] = ball.center[0];
    y_[k] = ball.center[1];
    z_[k] = ball.center[2];
    rho_[k] = (double(ball.radius) + tolerance_) * (1.0 + 1e-9);
  }
  enclose(x_, y_, z_, rho_, entries_.size(), blocks_);
  enclose(blocks_.x, blocks_.y, blocks_.z, blocks_.rho, blocks_.x.size(), groups_);
}

// The bounding balls of each run of kBlock balls (padding's NaN centres left out).
void LineFans::enclose(const std::vector<double>& x, const std::vector<double>& y,
                       const std::vector<double>& z, const std::vector<double>& rho, size_t n,
                       Balls& out) {
  for (size_t begin = 0; begin < n; begin += kBlock) {
    const size_t end = std::min(n, begin + kBlock);
    Box3 box;
    for (size_t k = begin; k < end; ++k) box.extend(Vec3(x[k], y[k], z[k]));
    const Vec3 c = 0.5 * (box.lo + box.hi);
    double radius = 0.0;
    for (size_t k = begin; k < end; ++k) {
      radius = std::max(radius, glm::length(Vec3(x[k], y[k], z[k]) - c) + rho[k]);
    }
    out.x.push_back(c.x);
    out.y.push_back(c.y);
    out.z.push_back(c.z);
    out.rho.push_back(radius * (1.0 + 1e-12));
  }
}

LineFans::State& LineFans::state() const {
  thread_local std::array<State, 4> states;
  thread_local unsigned next = 0;
  for (State& s : states) {
    if (s.serial == serial_) return s;
  }
  State& s = states[next++ % states.size()];
  s = State{};
  s.serial = serial_;
  return s;
}

namespace {

double distance2_to_line(const Vec3& p, const Vec3& origin, const Vec3& direction) {
  const Vec3 w = p - origin;
  const double along = glm::dot(w, direction);
  return std::max(0.0, glm::dot(w, w) - along * along);
}

// Where two lines (unit directions) come nearest each other, and how near: false for
// parallel lines.
bool nearest_points(const Vec3& o1, const Vec3& d1, const Vec3& o2, const Vec3& d2, Vec3& p1,
                    Vec3& p2) {
  const Vec3 w = o1 - o2;
  const double b = glm::dot(d1, d2), d = glm::dot(d1, w), e = glm::dot(d2, w);
  const double denominator = 1.0 - b * b;
  if (!(denominator > 1e-14)) return false;
  p1 = o1 + ((b * e - d) / denominator) * d1;
  p2 = o2 + ((e - b * d) / denominator) * d2;
  return true;
}

}  // namespace

void LineFans::lay_out(Cone& cone, const Vec3& apex) const {
  thread_local std::vector<std::pair<double, uint32_t>> order;
  order.clear();
  for (uint32_t k : cone.members) {
    order.push_back({glm::length(Vec3(x_[k], y_[k], z_[k]) - apex), k});
  }
  // The members come in the blocks' spatial order, their distances spread: O(n).
  bucket_sort(
      std::span(order), [](const std::pair<double, uint32_t>& e) { return e.first; },
      std::less<std::pair<double, uint32_t>>());
  // Whole SIMD widths past the last, from wherever a scan starts.
  const size_t n = cone.members.size() + kSimdWidth;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (auto* v : {&cone.x, &cone.y, &cone.z, &cone.radius, &cone.nx, &cone.ny, &cone.nz,
                  &cone.slab, &cone.distance}) {
    v->assign(n, nan);
  }
  cone.kept.resize(n);
  cone.pass.resize(n);
  cone.largest = 0.0;
  for (size_t k = 0; k < order.size(); ++k) {
    cone.members[k] = order[k].second;
    const Entry& e = entries_[order[k].second];
    const BoundingBall& ball = e.source->balls[e.primitive];
    cone.distance[k] = order[k].first;
    cone.x[k] = ball.center[0];
    cone.y[k] = ball.center[1];
    cone.z[k] = ball.center[2];
    cone.radius[k] = ball.radius;
    cone.nx[k] = ball.normal[0];
    cone.ny[k] = ball.normal[1];
    cone.nz[k] = ball.normal[2];
    cone.slab[k] = ball.slab;
    cone.largest = std::max(cone.largest, double(ball.radius));
  }
}

// The cone's balls whose centres lie at the depths of the line's [tmin, tmax] from the apex,
// give or take the largest radius and the apex's tolerance (a ball further in or out cannot
// meet it): [first, end) of the cone's order.
std::pair<size_t, size_t> LineFans::depths(const Cone& cone, const Vec3& apex,
                                           const detail::Line& line) const {
  const double at = glm::dot(apex - line.origin, line.direction);  // the apex's t
  double near = 0.0, far = std::max(at - line.tmin, line.tmax - at);
  if (at < line.tmin) near = line.tmin - at;
  if (at > line.tmax) near = at - line.tmax;
  const double slack = cone.largest + 2.0 * tolerance_;
  const size_t count = cone.members.size();
  const auto begin = cone.distance.begin(), end = begin + ptrdiff_t(count);
  const size_t first = size_t(std::lower_bound(begin, end, near - slack) - begin);
  const size_t last = far + slack < kInfinity
                          ? size_t(std::upper_bound(begin, end, far + slack) - begin)
                          : count;
  return {first, std::max(first, last)};
}

// may_cross (support_shapes.hpp) on every ball of the cone at once, its conditions as
// selects; the indices of those it keeps, in order, into cone.kept. Returns how many.
size_t LineFans::scan(Cone& cone, const Vec3& apex, const detail::Line& line,
                      size_t& scanned) const {
  const auto [first, end] = depths(cone, apex, line);
  scanned = end - first;
  const double ox = line.origin.x, oy = line.origin.y, oz = line.origin.z;
  const double dx = line.direction.x, dy = line.direction.y, dz = line.direction.z;
  const double tmin = line.tmin, tmax = line.tmax;
  const double *x = cone.x.data(), *y = cone.y.data(), *z = cone.z.data();
  const double *radius = cone.radius.data(), *slab = cone.slab.data();
  const double *nx = cone.nx.data(), *ny = cone.ny.data(), *nz = cone.nz.data();
  uint32_t* kept = cone.kept.data();
  double* pass = cone.pass.data();
  const size_t n = first + whole_simd_widths(end - first);  // the arrays have room
#pragma omp simd
  for (size_t k = first; k < n; ++k) {
    const double wx = x[k] - ox, wy = y[k] - oy, wz = z[k] - oz;
    const double ww = wx * wx + wy * wy + wz * wz, along = wx * dx + wy * dy + wz * dz;
    const double r2 = radius[k] * radius[k];
    const double half2 = r2 + 1e-12 * (ww + r2) - (ww - along * along);
    const double before = tmin - along, past = along - tmax;
    const double slope = dx * nx[k] + dy * ny[k] + dz * nz[k];
    const double height = along * slope - (wx * nx[k] + wy * ny[k] + wz * nz[k]);
    const double excess = std::abs(height) - slab[k] - 1e-12 * (std::abs(along) + radius[k]);
    const bool beside = ((before > 0.0) & (before * before > half2)) |
                        ((past > 0.0) & (past * past > half2)) |
                        ((excess > 0.0) & (excess * excess > slope * slope * half2));
    pass[k] = (half2 >= 0.0) & !beside ? 1.0 : 0.0;
  }
  // The indices apart: the vectorizer takes no store at a moving index.
  size_t count = 0;
  for (size_t k = first; k < end; ++k) {
    kept[count] = uint32_t(k);
    count += pass[k] != 0.0;
  }
  return count;
}

LineFans::Cone& LineFans::cone_for(Apex& apex, const Vec3& direction) const {
  for (Cone& c : apex.cones) {
    if (std::abs(glm::dot(direction, c.axis)) >= c.cos_angle) return c;
  }
  Cone& cone = apex.cones[apex.next_cone++ % kCones];
  ++apex.builds;
  cone.axis = direction;
  cone.cos_angle = std::cos(apex.angle);
  cone.members.clear();
  // A ball (c, rho) at distance D > rho from the apex subtends the angle asin(rho / D), so it
  // meets a line through the apex within the cone's angle of the axis where the angle between
  // the axis's line and the apex's line to c is at most the cone's plus that (angles between
  // lines obey the triangle inequality): where |v.axis| >= cos(angle) sqrt(D^2 - rho^2) -
  // sin(angle) rho, v = c - apex (the cosine of the sum, times D; no trigonometry per ball).
  // A hair of angle for rounding. Groups of blocks, then blocks, then their balls.
  const double angle = apex.angle + 1e-9;
  const ConeTest test{apex.point, direction, std::cos(angle), std::sin(angle)};
  thread_local std::vector<double> meets;
  meets.resize(kBlock);
  for (size_t g = 0; g < groups_.x.size(); ++g) {
    ++apex.tests;
    if (!test(groups_.x[g], groups_.y[g], groups_.z[g], groups_.rho[g])) continue;
    const size_t block_end = std::min(blocks_.x.size(), (g + 1) * kBlock);
    for (size_t b = g * kBlock; b < block_end; ++b) {
      ++apex.tests;
      if (!test(blocks_.x[b], blocks_.y[b], blocks_.z[b], blocks_.rho[b])) continue;
      const size_t first = b * kBlock;  // x_ is padded to whole blocks
      apex.tests += kBlock;
      double* m = meets.data();
      const double *x = x_.data() + first, *y = y_.data() + first, *z = z_.data() + first;
      const double* rho = rho_.data() + first;
#pragma omp simd
      for (size_t k = 0; k < kBlock; ++k) m[k] = test(x[k], y[k], z[k], rho[k]) ? 1.0 : 0.0;
      const size_t end = std::min(entries_.size(), first + kBlock);
      for (size_t k = first; k < end; ++k) {
        if (meets[k - first] != 0.0) cone.members.push_back(uint32_t(k));
      }
    }
  }
  lay_out(cone, apex.point);
  apex.members += cone.members.size();
  const uint64_t cost =
      apex.tests + kTestsPerMember * apex.members + apex.scanned / kScannedPerTest;
  const uint64_t saving = kTestsPerLine * apex.lines + kTestsPerCandidate * apex.kept;
  if (apex.builds >= kTrialBuilds && cost > saving) apex.off = true;
  return cone;
}

// A line through no apex: a meeting point it passes through becomes an apex (returned); where
// it meets one of the last few such lines, the point waits for a third. (A renderer asks a
// camera ray, then the shadow ray from its hit: the eye's lines come every other query.)
LineFans::Apex* LineFans::confirm_apex(State& s, const detail::Line& line) const {
  // The same line again (the next chunk of its search) passes through the points it met.
  for (unsigned k = 0; k < s.history_count; ++k) {
    if (line.origin == s.history[k].origin && line.direction == s.history[k].direction) {
      return nullptr;
    }
  }
  const double tolerance2 = tolerance_ * tolerance_;
  for (unsigned k = 0; k < s.candidate_count; ++k) {
    const Vec3 point = s.candidates[k];
    if (!(distance2_to_line(point, line.origin, line.direction) <= tolerance2)) continue;
    Apex& a = s.apexes[s.next_apex++ % kApexes];
    a = Apex{};
    a.valid = true;
    a.point = point;
    a.angle = kConeWidth * mean_radius_ / (glm::length(point - center_) + reach_);
    s.candidates[k] = s.candidates[--s.candidate_count];
    return &a;
  }
  for (unsigned k = 0; k < s.history_count; ++k) {
    Vec3 p1, p2;
    if (nearest_points(line.origin, line.direction, s.history[k].origin,
                       s.history[k].direction, p1, p2) &&
        glm::dot(p1 - p2, p1 - p2) <= tolerance2) {
      if (s.candidate_count < kCandidates) {
        s.candidates[s.candidate_count++] = 0.5 * (p1 + p2);
      } else {
        s.candidates[s.next_candidate++ % kCandidates] = 0.5 * (p1 + p2);
      }
    }
  }
  s.history[s.next_history++ % kHistory] = {line.origin, line.direction};
  s.history_count = std::min<unsigned>(s.history_count + 1, kHistory);
  return nullptr;
}

bool LineFans::candidates(const detail::Line& line,
                          std::vector<detail::TriangleCandidate>& out) const {
  if (!std::isfinite(line.tmin) || entries_.empty()) return false;
  State& s = state();
  Apex* apex = nullptr;
  for (Apex& a : s.apexes) {
    if (a.valid &&
        distance2_to_line(a.point, line.origin, line.direction) <= tolerance_ * tolerance_) {
      apex = &a;
      break;
    }
  }
  if (!apex) {
    apex = confirm_apex(s, line);
    if (!apex) return false;
  }
  if (apex->off) return false;
  ++apex->lines;
  Cone& cone = cone_for(*apex, line.direction);
  size_t scanned = 0;
  const size_t kept = scan(cone, apex->point, line, scanned);
  apex->scanned += scanned;
  apex->kept += kept;
  for (size_t k = 0; k < kept; ++k) {
    const Entry& e = entries_[cone.members[cone.kept[k]]];
    out.push_back({e.source, e.primitive});
  }
  return true;
}

}  // namespace convray::accel
