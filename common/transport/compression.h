#pragma once
// zstd for team payloads that are large enough to gain (map increments, repair snapshots).
// Decompression is bounded: a frame that claims or produces more than the limit is refused,
// so a hostile or corrupt frame cannot make a receiver allocate without bound.

#include <cstddef>
#include <string>
#include <string_view>

namespace hexplore::transport {

// Appends the zstd frame of `in` to `out` (level 1..19).
void compress(std::string_view in, int level, std::string& out);
// Replaces `out` with the decompressed `in`; false when `in` is not one complete zstd frame
// or its content exceeds `max_size` bytes.
bool decompress(std::string_view in, size_t max_size, std::string& out);

}  // namespace hexplore::transport
