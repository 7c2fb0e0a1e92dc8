#include "common/radio/key_steps.h"

#include "common/highlevel/supervoxel.h"

namespace hexplore::radio {
namespace {

constexpr int64_t kCellLimit = core::kSeedKeyAxisLimit;
constexpr int kClassBits = 64 - core::kSeedKeyCellBits;  // facade bit and facing (supervoxel.h)

}  // namespace

void write_key(transport::ByteWriter& w, uint64_t key, core::GridCell& previous) {
  const core::GridCell c = highlevel::seed_cell_of(key);
  const uint64_t cls = key >> core::kSeedKeyCellBits;
  w.varint(transport::zigzag(int64_t{c.x} - previous.x) << kClassBits | cls);
  w.svarint(int64_t{c.y} - previous.y);
  w.svarint(int64_t{c.z} - previous.z);
  previous = c;
}

bool read_key(transport::ByteReader& r, uint64_t& key, core::GridCell& previous) {
  const uint64_t first = r.varint();
  const int64_t x = previous.x + transport::unzigzag(first >> kClassBits);
  const int64_t y = previous.y + r.bounded_svarint(2 * kCellLimit);
  const int64_t z = previous.z + r.bounded_svarint(2 * kCellLimit);
  if (r.failed()) return false;
  for (int64_t v : {x, y, z})
    if (v < -kCellLimit || v >= kCellLimit) return r.fail(), false;
  previous = {static_cast<int32_t>(x), static_cast<int32_t>(y), static_cast<int32_t>(z)};
  key = core::seed_key(previous) | (first & ((uint64_t{1} << kClassBits) - 1)) << core::kSeedKeyCellBits;
  return true;
}

}  // namespace hexplore::radio
