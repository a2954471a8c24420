// The branching order of the learning precedence search: variables by
// activity, highest first (a binary max-heap that knows each variable's
// slot, so a bumped variable moves up in O(log n)). Activities only steer
// which literal is tried next, never an answer, so they may be doubles.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/assert.hpp"

namespace gridlock {

class ActivityHeap {
 public:
  explicit ActivityHeap(const std::vector<double>& activity) : act_(activity), slot_(activity.size(), kOut) {}

  // Empties the heap for variables 0..n-1 (the activity vector's size).
  void reset(size_t n) {
    heap_.clear();
    slot_.assign(n, kOut);
  }
  bool contains(uint32_t v) const { return slot_[v] != kOut; }
  bool empty() const { return heap_.empty(); }
  void insert(uint32_t v) {
    if (contains(v)) return;
    slot_[v] = static_cast<uint32_t>(heap_.size());
    heap_.push_back(v);
    up(slot_[v]);
  }
  // After v's activity grew.
  void increased(uint32_t v) {
    if (contains(v)) up(slot_[v]);
  }
  // Requires !empty().
  uint32_t pop() {
    GRIDLOCK_ASSERT(!heap_.empty(), "ActivityHeap::pop on an empty heap");
    const uint32_t top = heap_[0];
    heap_[0] = heap_.back();
    slot_[heap_[0]] = 0;
    heap_.pop_back();
    slot_[top] = kOut;
    if (!heap_.empty()) down(0);
    return top;
  }

 private:
  static constexpr uint32_t kOut = UINT32_MAX;
  bool above(uint32_t x, uint32_t y) const { return act_[x] > act_[y]; }
  void up(uint32_t i) {
    const uint32_t v = heap_[i];
    while (i > 0 && above(v, heap_[(i - 1) / 2])) {
      heap_[i] = heap_[(i - 1) / 2];
      slot_[heap_[i]] = i;
      i = (i - 1) / 2;
    }
    heap_[i] = v;
    slot_[v] = i;
  }
  void down(uint32_t i) {
    const uint32_t v = heap_[i];
    const auto n = static_cast<uint32_t>(heap_.size());
    for (;;) {
      uint32_t c = 2 * i + 1;
      if (c >= n) break;
      if (c + 1 < n && above(heap_[c + 1], heap_[c])) ++c;
      if (!above(heap_[c], v)) break;
      heap_[i] = heap_[c];
      slot_[heap_[i]] = i;
      i = c;
    }
    heap_[i] = v;
    slot_[v] = i;
  }

  const std::vector<double>& act_;
  std::vector<uint32_t> heap_;
  std::vector<uint32_t> slot_;
};

}  // namespace gridlock
