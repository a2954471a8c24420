// A hash map from 64-bit keys to 32-bit values in one flat array (open
// addressing, linear probing, load at most 1/2).
//
// Why not std::unordered_map: it allocates one node per entry. The cell
// index of a compiled formula holds some thousands of nodes, and fuzzing
// builds and frees one per formula; the simulator's set of candidate pairs
// is filled and cleared every interval. Here an entry costs no allocation,
// and clear() keeps the memory.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace gridlock {

class FlatMap64 {
 public:
  static constexpr uint32_t kAbsent = UINT32_MAX;  // find()'s "no such key"; not a storable value

  // Room for n entries without growing. O(n).
  void reserve(size_t n) {
    size_t cap = 16;
    while (cap < 2 * n) cap <<= 1;
    if (cap > slots_.size()) rehash(cap);
  }
  // The value of key, or kAbsent. O(1) expected.
  uint32_t find(uint64_t key) const {
    if (slots_.empty()) return kAbsent;
    const size_t mask = slots_.size() - 1;
    for (size_t i = hash(key) & mask;; i = (i + 1) & mask) {
      if (slots_[i].value == kAbsent) return kAbsent;
      if (slots_[i].key == key) return slots_[i].value;
    }
  }
  // Adds key -> value unless key is present. Returns the value now stored
  // and whether it was added. Requires value != kAbsent. O(1) amortised.
  std::pair<uint32_t, bool> emplace(uint64_t key, uint32_t value) {
    if (2 * (size_ + 1) > slots_.size()) rehash(slots_.empty() ? 16 : 2 * slots_.size());
    const size_t mask = slots_.size() - 1;
    size_t i = hash(key) & mask;
    for (; slots_[i].value != kAbsent; i = (i + 1) & mask)
      if (slots_[i].key == key) return {slots_[i].value, false};
    slots_[i] = Slot{key, value};
    used_.push_back(static_cast<uint32_t>(i));
    ++size_;
    return {value, true};
  }
  // Removes every entry, keeping the memory. O(size): the simulator clears
  // a large table, grown by one long interval, after each of many short ones.
  void clear() {
    for (uint32_t i : used_) slots_[i].value = kAbsent;
    used_.clear();
    size_ = 0;
  }
  size_t size() const { return size_; }

 private:
  struct Slot {
    uint64_t key = 0;
    uint32_t value = kAbsent;
  };
  static size_t hash(uint64_t key) {  // both halves of the key reach the low bits
    key ^= key >> 33;
    key *= 0xFF51AFD7ED558CCDull;
    key ^= key >> 33;
    return static_cast<size_t>(key);
  }
  void rehash(size_t cap) {
    std::vector<Slot> old(cap);
    old.swap(slots_);
    used_.clear();
    const size_t mask = cap - 1;
    for (const Slot& o : old)
      if (o.value != kAbsent) {
        size_t j = hash(o.key) & mask;
        while (slots_[j].value != kAbsent) j = (j + 1) & mask;
        slots_[j] = o;
        used_.push_back(static_cast<uint32_t>(j));
      }
  }
  std::vector<Slot> slots_;
  std::vector<uint32_t> used_;  // the full slots, for clear()
  size_t size_ = 0;
};

}  // namespace gridlock
