#include "common/transport/compression.h"

#include <stdexcept>

#include <zstd.h>

namespace hexplore::transport {
namespace {

// The content size `in` claims when it is one complete frame within `max_size`; else -1.
long long checked_content_size(std::string_view in, size_t max_size) {
  const unsigned long long claimed = ZSTD_getFrameContentSize(in.data(), in.size());
  if (claimed == ZSTD_CONTENTSIZE_ERROR || claimed == ZSTD_CONTENTSIZE_UNKNOWN || claimed > max_size) return -1;
  // One frame, nothing after it.
  if (ZSTD_findFrameCompressedSize(in.data(), in.size()) != in.size()) return -1;
  return static_cast<long long>(claimed);
}

// Runs `decompress_into(dst, capacity)` into `out` sized for the frame's claimed content.
template <typename Decompress>
bool bounded_decompress(std::string_view in, size_t max_size, std::string& out, Decompress decompress_into) {
  out.clear();
  const long long claimed = checked_content_size(in, max_size);
  if (claimed < 0) return false;
  out.resize(static_cast<size_t>(claimed));
  const size_t n = decompress_into(out.data(), out.size());
  if (ZSTD_isError(n) || n != static_cast<size_t>(claimed)) {
    out.clear();
    return false;
  }
  return true;
}

// Appends what `compress_into(dst, capacity)` writes to `out`; a zstd error appends nothing.
template <typename Compress>
void append_compressed(size_t in_size, std::string& out, Compress compress_into) {
  const size_t start = out.size();
  out.resize(start + ZSTD_compressBound(in_size));
  const size_t n = compress_into(out.data() + start, out.size() - start);
  // The bound above always suffices, so an error here is a zstd bug; send nothing odd.
  out.resize(ZSTD_isError(n) ? start : start + n);
}

}  // namespace

void compress(std::string_view in, int level, std::string& out) {
  append_compressed(in.size(), out, [&](char* dst, size_t capacity) {
    return ZSTD_compress(dst, capacity, in.data(), in.size(), level);
  });
}

bool decompress(std::string_view in, size_t max_size, std::string& out) {
  return bounded_decompress(in, max_size, out, [&](char* dst, size_t capacity) {
    return ZSTD_decompress(dst, capacity, in.data(), in.size());
  });
}

uint32_t frame_dictionary_id(std::string_view frame) {
  return ZSTD_getDictID_fromFrame(frame.data(), frame.size());
}

CompressionDictionary::CompressionDictionary(std::string_view bytes, int level)
    : bytes_(bytes), level_(level), id_(ZSTD_getDictID_fromDict(bytes_.data(), bytes_.size())) {
  if (id_ == 0) throw std::invalid_argument("not a zstd dictionary with an id (train one with zstd --train)");
  compress_tables_ = ZSTD_createCDict(bytes_.data(), bytes_.size(), level_);
  decompress_tables_ = ZSTD_createDDict(bytes_.data(), bytes_.size());
  if (compress_tables_ == nullptr || decompress_tables_ == nullptr) {
    ZSTD_freeCDict(compress_tables_);
    ZSTD_freeDDict(decompress_tables_);
    throw std::invalid_argument("zstd could not load the dictionary");
  }
}

CompressionDictionary::~CompressionDictionary() {
  ZSTD_freeCDict(compress_tables_);
  ZSTD_freeDDict(decompress_tables_);
}

void CompressionDictionary::compress(std::string_view in, int level, std::string& out) const {
  // A context per call: sockets of several threads share one dictionary (the tables are
  // read-only), and a payload of a kilobyte costs far more to compress than to set up for.
  ZSTD_CCtx* context = ZSTD_createCCtx();
  append_compressed(in.size(), out, [&](char* dst, size_t capacity) {
    if (level == level_) return ZSTD_compress_usingCDict(context, dst, capacity, in.data(), in.size(), compress_tables_);
    return ZSTD_compress_usingDict(context, dst, capacity, in.data(), in.size(), bytes_.data(), bytes_.size(), level);
  });
  ZSTD_freeCCtx(context);
}

bool CompressionDictionary::decompress(std::string_view in, size_t max_size, std::string& out) const {
  if (frame_dictionary_id(in) != id_) {
    out.clear();
    return false;
  }
  ZSTD_DCtx* context = ZSTD_createDCtx();
  const bool ok = bounded_decompress(in, max_size, out, [&](char* dst, size_t capacity) {
    return ZSTD_decompress_usingDDict(context, dst, capacity, in.data(), in.size(), decompress_tables_);
  });
  ZSTD_freeDCtx(context);
  return ok;
}

}  // namespace hexplore::transport
