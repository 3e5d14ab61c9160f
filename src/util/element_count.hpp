#pragma once
#include <atomic>
#include <cstddef>
#include <memory>

namespace convray {

// Elements held against one shared budget: the scene parser's count of the elements of live
// arrays, long strings and meshes (sdl/value.hpp, docs/limits.md). Whatever holds an
// ElementCount holds its count while it lives, and a copy holds it again, so a copy of a mesh
// or an array counts as the memory it takes. The parser checks the budget before it makes,
// grows or copies one (sdl::Parser::Impl::check_element_budget); a copy made elsewhere counts
// without a check, and the next check sees it. The count is atomic: a scene's records may be
// copied or dropped on any thread.
class ElementCount {
 public:
  using Live = std::shared_ptr<std::atomic<std::size_t>>;

  ElementCount() = default;
  ElementCount(Live live, std::size_t count) : live_(std::move(live)), count_(count) {
    if (live_) *live_ += count_;
  }
  ElementCount(const ElementCount& other) : ElementCount(other.live_, other.count_) {}
  ElementCount& operator=(const ElementCount& other) {
    if (this != &other) *this = ElementCount(other);
    return *this;
  }
  ElementCount& operator=(ElementCount&& other) noexcept {
    release();
    live_ = std::move(other.live_);
    count_ = other.count_;
    other.count_ = 0;
    return *this;
  }
  ElementCount(ElementCount&& other) noexcept
      : live_(std::move(other.live_)), count_(other.count_) {
    other.count_ = 0;
  }
  ~ElementCount() { release(); }

  std::size_t count() const { return count_; }

 private:
  void release() {
    if (live_) *live_ -= count_;
    count_ = 0;
  }
  Live live_;
  std::size_t count_ = 0;
};

}  // namespace convray
