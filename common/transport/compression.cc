#include "common/transport/compression.h"

#include <zstd.h>

namespace hexplore::transport {

void compress(std::string_view in, int level, std::string& out) {
  const size_t start = out.size();
  out.resize(start + ZSTD_compressBound(in.size()));
  const size_t n = ZSTD_compress(out.data() + start, out.size() - start, in.data(), in.size(), level);
  // The bound above always suffices, so an error here is a zstd bug; send nothing odd.
  out.resize(ZSTD_isError(n) ? start : start + n);
}

bool decompress(std::string_view in, size_t max_size, std::string& out) {
  out.clear();
  const unsigned long long claimed = ZSTD_getFrameContentSize(in.data(), in.size());
  if (claimed == ZSTD_CONTENTSIZE_ERROR || claimed == ZSTD_CONTENTSIZE_UNKNOWN || claimed > max_size) return false;
  // One frame, nothing after it.
  if (ZSTD_findFrameCompressedSize(in.data(), in.size()) != in.size()) return false;
  out.resize(static_cast<size_t>(claimed));
  const size_t n = ZSTD_decompress(out.data(), out.size(), in.data(), in.size());
  if (ZSTD_isError(n) || n != claimed) {
    out.clear();
    return false;
  }
  return true;
}

}  // namespace hexplore::transport
