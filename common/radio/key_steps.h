#pragma once
// Supervoxel keys (core::seed_key of the seed cell, class bits 60-63: highlevel::supervoxel_key)
// as seed-cell steps from the previous key: sorted keys and keys along a route are neighbours,
// so a key takes three bytes or less where fixed64 took eight. The class bits ride in the x step.

#include <cstdint>

#include "common/core/seed_key.h"
#include "common/transport/byte_codec.h"

namespace hexplore::radio {

// Writes `key` relative to `previous` and sets `previous` to its cell.
void write_key(transport::ByteWriter& w, uint64_t key, core::GridCell& previous);
// Reads a key relative to `previous` (updated); false for a cell outside the key's range.
bool read_key(transport::ByteReader& r, uint64_t& key, core::GridCell& previous);

}  // namespace hexplore::radio
