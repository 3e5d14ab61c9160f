#include "implicit/support_cache.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <vector>

#include "accel/support_index.hpp"
#include "accel/triangle_supports.hpp"

namespace convray::implicit {
namespace {

// A kept hierarchy may be this many times roomier than needed: a larger margin only costs
// traversal time, a rebuild costs a whole build.
constexpr double kMaxMarginSlack = 4.0;

// What identifies a hierarchy, but for its margin.
struct Key {
  const std::vector<field::Triangle>* local = nullptr;  // identity of the loaded file
  double radius = 0.0;
  bool rigid = false;
  Mat4 placement{1.0};  // only for non-rigid ones: their triangles are the placed ones

  bool operator==(const Key& other) const {
    return local == other.local && radius == other.radius && rigid == other.rigid &&
           (rigid || placement == other.placement);
  }
};

struct Entry {
  Key key;
  std::shared_ptr<const std::vector<field::Triangle>> local;  // keeps `key.local` unique
  std::shared_ptr<const accel::TriangleSupports> supports;
  bool used = true;  // since the last next_frame()
};

// Margins come in powers of two, so that a scene whose size drifts from frame to frame keeps
// asking for the same one.
double bucket(double margin) {
  return margin > 0.0 ? std::exp2(std::ceil(std::log2(margin))) : 0.0;
}

}  // namespace

struct SupportCache::Impl {
  mutable std::mutex mutex;
  std::vector<Entry> entries;
  Counts counts;

  // The bounds of the key's supports in the hierarchy's own space, from a sibling when one
  // is kept (they differ only in margin).
  Box3 own_bounds(const Key& key, std::span<const field::Triangle> placed) const {
    for (const Entry& e : entries) {
      if (e.key == key) return e.supports->bounds();
    }
    return accel::triangle_supports_bounds(
        key.rigid ? std::span<const field::Triangle>(*key.local) : placed, key.radius);
  }
};

SupportCache::SupportCache() : impl_(std::make_unique<Impl>()) {}
SupportCache::~SupportCache() = default;

SupportCache::Counts SupportCache::counts() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->counts;
}

size_t SupportCache::size() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->entries.size();
}

size_t SupportCache::memory_bytes() const {
  std::lock_guard lock(impl_->mutex);
  size_t bytes = 0;
  for (const Entry& e : impl_->entries) bytes += e.supports->memory_bytes();
  return bytes;
}

void SupportCache::next_frame() {
  std::lock_guard lock(impl_->mutex);
  std::erase_if(impl_->entries, [](const Entry& e) { return !e.used; });
  for (Entry& e : impl_->entries) e.used = false;
}

SupportCache::Placed SupportCache::acquire(const scene::MeshSource& source,
                                           std::span<const field::Triangle> triangles,
                                           double radius, const Box3& index_bounds) {
  Key key{source.local.get(), radius, is_rigid(source.placement), source.placement};
  if (key.rigid) key.placement = Mat4(1.0);
  // A rigid hierarchy lies in the file's space and is placed; the others lie where they are.
  const Mat4 placement = key.rigid ? source.placement : Mat4(1.0);
  std::lock_guard lock(impl_->mutex);
  Impl& m = *impl_;
  const double needed = accel::required_instance_margin(index_bounds, m.own_bounds(key, triangles));
  for (Entry& e : m.entries) {
    const double margin = e.supports->margin();
    if (e.key == key && margin >= needed && margin <= kMaxMarginSlack * needed) {
      e.used = true;
      ++m.counts.reuses;
      return {e.supports, placement};
    }
  }
  auto own = key.rigid ? source.local
                       : std::make_shared<const std::vector<field::Triangle>>(triangles.begin(),
                                                                              triangles.end());
  auto supports = std::make_shared<const accel::TriangleSupports>(own, radius, bucket(needed));
  m.entries.push_back({key, source.local, supports, true});
  ++m.counts.builds;
  return {supports, placement};
}

}  // namespace convray::implicit
