#pragma once
// Little-endian bytes, LEB128 varints and zigzag signed varints: the building blocks of the
// compact envelope and the team messages' wire forms. The reader never reads past its end;
// any overrun, overlong varint or trailing garbage leaves it failed(), so a malformed frame is
// detected where it is parsed instead of crashing whoever trusted it.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace hexplore::transport {

inline uint64_t zigzag(int64_t v) { return (static_cast<uint64_t>(v) << 1) ^ static_cast<uint64_t>(v >> 63); }
inline int64_t unzigzag(uint64_t v) { return static_cast<int64_t>(v >> 1) ^ -static_cast<int64_t>(v & 1); }

class ByteWriter {
 public:
  explicit ByteWriter(std::string& out) : out_(out) {}

  void u8(uint8_t v) { out_.push_back(static_cast<char>(v)); }
  void u16(uint16_t v) {
    u8(static_cast<uint8_t>(v));
    u8(static_cast<uint8_t>(v >> 8));
  }
  void u32(uint32_t v) {
    for (int i = 0; i < 4; ++i) u8(static_cast<uint8_t>(v >> (8 * i)));
  }
  void f32(float v) {
    uint32_t bits;
    std::memcpy(&bits, &v, 4);
    for (int i = 0; i < 4; ++i) u8(static_cast<uint8_t>(bits >> (8 * i)));
  }
  void varint(uint64_t v) {
    while (v >= 0x80) {
      u8(static_cast<uint8_t>(v | 0x80));
      v >>= 7;
    }
    u8(static_cast<uint8_t>(v));
  }
  void svarint(int64_t v) { varint(zigzag(v)); }
  // Length-prefixed bytes.
  void bytes(std::string_view s) {
    varint(s.size());
    out_.append(s.data(), s.size());
  }
  void raw(std::string_view s) { out_.append(s.data(), s.size()); }
  size_t size() const { return out_.size(); }

 private:
  std::string& out_;
};

class ByteReader {
 public:
  ByteReader(const void* data, size_t size) : p_(static_cast<const uint8_t*>(data)), end_(p_ + size) {}
  explicit ByteReader(std::string_view s) : ByteReader(s.data(), s.size()) {}

  uint8_t u8() {
    if (p_ >= end_) return fail();
    return *p_++;
  }
  uint16_t u16() {
    const uint16_t lo = u8();
    return static_cast<uint16_t>(lo | (static_cast<uint16_t>(u8()) << 8));
  }
  uint32_t u32() {
    uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= static_cast<uint32_t>(u8()) << (8 * i);
    return v;
  }
  float f32() {
    uint32_t bits = 0;
    for (int i = 0; i < 4; ++i) bits |= static_cast<uint32_t>(u8()) << (8 * i);
    float v;
    std::memcpy(&v, &bits, 4);
    return v;
  }
  uint64_t varint() {
    uint64_t v = 0;
    for (int shift = 0; shift < 64; shift += 7) {
      if (p_ >= end_) return fail();
      const uint8_t b = *p_++;
      v |= static_cast<uint64_t>(b & 0x7f) << shift;
      if ((b & 0x80) == 0) return v;
    }
    return fail();  // more than ten bytes: not a varint
  }
  int64_t svarint() { return unzigzag(varint()); }
  // A signed varint of at most `max_abs` either way (a step added to a known value: larger ones
  // are malformed, and would overflow the sum); larger values fail the reader.
  int64_t bounded_svarint(int64_t max_abs) {
    const int64_t v = svarint();
    if (v > max_abs || v < -max_abs) return fail();
    return v;
  }
  // A varint that must fit `max` (counts, indices); larger values fail the reader.
  uint64_t bounded(uint64_t max) {
    const uint64_t v = varint();
    if (v > max) return fail();
    return v;
  }
  // Length-prefixed bytes; the view points into the reader's buffer.
  std::string_view bytes(size_t max_size = SIZE_MAX) {
    const uint64_t n = varint();
    if (failed_ || n > max_size || n > static_cast<uint64_t>(end_ - p_)) {
      fail();
      return {};
    }
    std::string_view s(reinterpret_cast<const char*>(p_), static_cast<size_t>(n));
    p_ += n;
    return s;
  }
  // Bytes not read yet.
  size_t remaining() const { return failed_ ? 0 : static_cast<size_t>(end_ - p_); }
  const uint8_t* position() const { return p_; }
  bool failed() const { return failed_; }
  // True when everything was read and nothing failed.
  bool done() const { return !failed_ && p_ == end_; }
  uint8_t fail() {
    failed_ = true;
    p_ = end_;
    return 0;
  }

 private:
  const uint8_t* p_;
  const uint8_t* end_;
  bool failed_ = false;
};

}  // namespace hexplore::transport
