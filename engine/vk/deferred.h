// Deferred destruction: an object still referenced by recorded command buffers is handed over here and
// destroyed only after the fence of the frame that used it has been waited on (Granite's PerFrame idea).
#pragma once
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace lagoon::vk {

class DeferredDestroyer {
 public:
  explicit DeferredDestroyer(uint32_t frame_slots = 1) : slots_(frame_slots) {}

  // Takes ownership of any movable owner (Unique<T>, Buffer, Image...) until its frame slot comes round
  // again.
  template <typename T>
  void defer(T&& owner) {
    slots_[current_].push_back(std::make_unique<Holder<std::decay_t<T>>>(std::forward<T>(owner)));
  }

  // Call right after waiting on the fence of `slot`: destroys what was deferred while that slot was current,
  // then makes it current.
  void begin_frame(uint32_t slot) {
    current_ = slot % static_cast<uint32_t>(slots_.size());
    slots_[current_].clear();
  }
  void flush_all() {
    for (auto& s : slots_) s.clear();
  }
  uint32_t slots() const { return static_cast<uint32_t>(slots_.size()); }
  size_t pending() const {
    size_t n = 0;
    for (const auto& s : slots_) n += s.size();
    return n;
  }

 private:
  struct Base {
    virtual ~Base() = default;
  };
  template <typename T>
  struct Holder : Base {
    explicit Holder(T&& v) : value(std::move(v)) {}
    T value;
  };
  std::vector<std::vector<std::unique_ptr<Base>>> slots_;
  uint32_t current_ = 0;
};

}  // namespace lagoon::vk
