#pragma once
// Sparse voxel storage of the segmenter: 8x8x8 bricks of slot indices in a hash map (one
// octree level in effect), records in a dense vector. Neighbour lookups of a voxel mostly land
// in the same brick, so wavefront propagation costs about one hash probe per voxel instead of
// one per neighbour.

#include <array>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "common/core/seed_key.h"

namespace hexplore::highlevel {

template <typename Record>
class VoxelIndex {
 public:
  // Keys are core::seed_key packings (core::kSeedKeyAxisBits per axis, offset-coded, x lowest).
  Record* find(uint64_t key) {
    Brick* b = brick(brick_key(key));
    if (b == nullptr) return nullptr;
    const int32_t slot = b->slots[local(key)];
    return slot < 0 ? nullptr : &records_[slot].record;
  }
  const Record* find(uint64_t key) const { return const_cast<VoxelIndex*>(this)->find(key); }

  // Inserts a default record (or returns the existing one). Invalidates record pointers.
  Record& insert(uint64_t key) {
    const uint64_t bk = brick_key(key);
    Brick* b = brick(bk);
    if (b == nullptr) {
      auto [it, inserted] = bricks_.emplace(bk, std::make_unique<Brick>());
      it->second->slots.fill(-1);
      b = it->second.get();
      last_key_ = bk;
      last_ = b;
    }
    int32_t& slot = b->slots[local(key)];
    if (slot >= 0) return records_[slot].record;
    if (!free_.empty()) {
      slot = free_.back();
      free_.pop_back();
      records_[slot] = Entry{key, Record{}, true};
    } else {
      slot = static_cast<int32_t>(records_.size());
      records_.push_back(Entry{key, Record{}, true});
    }
    ++b->count;
    ++size_;
    return records_[slot].record;
  }

  void erase(uint64_t key) {
    const uint64_t bk = brick_key(key);
    Brick* b = brick(bk);
    if (b == nullptr) return;
    int32_t& slot = b->slots[local(key)];
    if (slot < 0) return;
    records_[slot] = Entry{};
    free_.push_back(slot);
    slot = -1;
    --size_;
    if (--b->count == 0) {
      if (last_ == b) last_ = nullptr;
      bricks_.erase(bk);
    }
  }

  size_t size() const { return size_; }

  // Calls f(key, record) for every stored voxel (storage order).
  template <typename F>
  void for_each(F&& f) const {
    for (const Entry& e : records_)
      if (e.used) f(e.key, e.record);
  }

 private:
  struct Brick {
    std::array<int32_t, 512> slots;
    int count = 0;
  };
  struct Entry {
    uint64_t key = 0;
    Record record{};
    bool used = false;
  };
  static uint64_t brick_key(uint64_t key) {
    constexpr int kBits = core::kSeedKeyAxisBits;
    constexpr uint64_t kMask = (uint64_t{1} << kBits) - 1;
    return (((key >> 2 * kBits) & kMask) >> 3) << 2 * kBits | (((key >> kBits) & kMask) >> 3) << kBits |
           ((key & kMask) >> 3);
  }
  static int local(uint64_t key) {
    constexpr int kBits = core::kSeedKeyAxisBits;
    return static_cast<int>(((key >> 2 * kBits) & 7) << 6 | ((key >> kBits) & 7) << 3 | (key & 7));
  }
  Brick* brick(uint64_t bk) const {
    if (last_ != nullptr && last_key_ == bk) return last_;
    auto it = bricks_.find(bk);
    if (it == bricks_.end()) return nullptr;
    last_key_ = bk;
    last_ = it->second.get();
    return last_;
  }

  std::unordered_map<uint64_t, std::unique_ptr<Brick>> bricks_;
  std::vector<Entry> records_;
  std::vector<int32_t> free_;
  size_t size_ = 0;
  mutable uint64_t last_key_ = 0;
  mutable Brick* last_ = nullptr;  // most recent brick: neighbours of one voxel share it
};

}  // namespace hexplore::highlevel
