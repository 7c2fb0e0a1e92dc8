#pragma once
// Open-addressing hash map from a packed 48-bit voxel key to a small value, used as a
// scan-local memo (octree lookups cost a 16-level descent; one scan repeats each many times).
// Cleared per scan while keeping its capacity.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace hexplore::perception {

template <typename V>
class FlatKeyMap {
 public:
  static constexpr uint64_t kEmpty = ~uint64_t{0};

  void clear(size_t expected) {
    size_t cap = 64;
    while (cap < expected * 2) cap <<= 1;
    if (keys_.size() < cap) {
      keys_.assign(cap, kEmpty);
      values_.resize(cap);
    } else {
      std::fill(keys_.begin(), keys_.end(), kEmpty);
    }
    mask_ = keys_.size() - 1;
    size_ = 0;
  }

  V* find(uint64_t key) {
    size_t i = slot(key);
    while (keys_[i] != kEmpty) {
      if (keys_[i] == key) return &values_[i];
      i = (i + 1) & mask_;
    }
    return nullptr;
  }

  // The value stored under `key`; `inserted` says whether it was just added with `init`.
  V& find_or_insert(uint64_t key, const V& init, bool& inserted) {
    if ((size_ + 1) * 2 > keys_.size()) grow();
    size_t i = slot(key);
    while (keys_[i] != kEmpty) {
      if (keys_[i] == key) {
        inserted = false;
        return values_[i];
      }
      i = (i + 1) & mask_;
    }
    keys_[i] = key;
    values_[i] = init;
    ++size_;
    inserted = true;
    return values_[i];
  }

  size_t size() const { return size_; }

 private:
  size_t slot(uint64_t key) const { return static_cast<size_t>((key * 0x9E3779B97F4A7C15ull) >> 20) & mask_; }

  void grow() {
    std::vector<uint64_t> old_keys = std::move(keys_);
    std::vector<V> old_values = std::move(values_);
    const size_t cap = old_keys.empty() ? 64 : old_keys.size() * 2;
    keys_.assign(cap, kEmpty);
    values_.assign(cap, V{});
    mask_ = cap - 1;
    size_ = 0;
    for (size_t i = 0; i < old_keys.size(); ++i) {
      if (old_keys[i] == kEmpty) continue;
      bool inserted = false;
      find_or_insert(old_keys[i], old_values[i], inserted);
    }
  }

  std::vector<uint64_t> keys_;
  std::vector<V> values_;
  size_t mask_ = 0;
  size_t size_ = 0;
};

}  // namespace hexplore::perception
