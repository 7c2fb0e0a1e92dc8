#include "common/radio/key_steps.h"

#include "common/highlevel/supervoxel.h"

namespace hexplore::radio {
namespace {

constexpr int64_t kCellLimit = int64_t{1} << 20;  // core::seed_key: 21 bits per axis

}  // namespace

void write_key(transport::ByteWriter& w, uint64_t key, core::GridCell& previous) {
  const core::GridCell c = highlevel::seed_cell_of(key);
  const uint64_t facade = (key & highlevel::kFacadeKeyBit) != 0 ? 1 : 0;
  w.varint(transport::zigzag(int64_t{c.x} - previous.x) << 1 | facade);
  w.svarint(int64_t{c.y} - previous.y);
  w.svarint(int64_t{c.z} - previous.z);
  previous = c;
}

bool read_key(transport::ByteReader& r, uint64_t& key, core::GridCell& previous) {
  const uint64_t first = r.varint();
  const int64_t x = previous.x + transport::unzigzag(first >> 1);
  const int64_t y = previous.y + r.svarint();
  const int64_t z = previous.z + r.svarint();
  if (r.failed()) return false;
  for (int64_t v : {x, y, z})
    if (v < -kCellLimit || v >= kCellLimit) return r.fail(), false;
  previous = {static_cast<int32_t>(x), static_cast<int32_t>(y), static_cast<int32_t>(z)};
  key = core::seed_key(previous) | ((first & 1) != 0 ? highlevel::kFacadeKeyBit : 0);
  return true;
}

}  // namespace hexplore::radio
