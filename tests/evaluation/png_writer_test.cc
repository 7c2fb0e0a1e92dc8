#include <gtest/gtest.h>
#include <zlib.h>

#include <fstream>
#include <iterator>

#include "common/evaluation/png_writer.h"
#include "tests/support/scratch_dir.h"

namespace hexplore::evaluation {
namespace {

uint32_t be32(const std::vector<uint8_t>& b, size_t at) {
  return (uint32_t{b[at]} << 24) | (uint32_t{b[at + 1]} << 16) | (uint32_t{b[at + 2]} << 8) | b[at + 3];
}

// Decodes the PNG we wrote (filter 0 only) back into RGB rows, checking every chunk CRC.
std::vector<uint8_t> decode(const std::string& path, int& width, int& height) {
  std::ifstream in(path, std::ios::binary);
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(std::vector<uint8_t>(bytes.begin(), bytes.begin() + 8),
            (std::vector<uint8_t>{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'}));
  std::vector<uint8_t> idat;
  for (size_t at = 8; at + 12 <= bytes.size();) {
    const uint32_t length = be32(bytes, at);
    const std::string type(bytes.begin() + at + 4, bytes.begin() + at + 8);
    const uint32_t crc = be32(bytes, at + 8 + length);
    EXPECT_EQ(crc, crc32(0L, bytes.data() + at + 4, length + 4)) << type;
    if (type == "IHDR") {
      width = static_cast<int>(be32(bytes, at + 8));
      height = static_cast<int>(be32(bytes, at + 12));
    } else if (type == "IDAT") {
      idat.insert(idat.end(), bytes.begin() + at + 8, bytes.begin() + at + 8 + length);
    }
    at += 12 + length;
  }
  std::vector<uint8_t> raw(static_cast<size_t>(height) * (1 + width * 3));
  uLongf raw_size = raw.size();
  EXPECT_EQ(uncompress(raw.data(), &raw_size, idat.data(), idat.size()), Z_OK);
  EXPECT_EQ(raw_size, raw.size());
  return raw;
}

TEST(PngWriter, RoundTripsPixels) {
  Raster r(7, 5, {255, 255, 255});
  r.set(3, 2, {10, 20, 30});
  r.line(0, 4, 6, 4, {1, 2, 3});
  const hexplore::testing::ScratchDir scratch("png_writer_test");
  const auto path = scratch.file("round_trip.png");
  write_png(r, path);
  int w = 0, h = 0;
  const auto raw = decode(path, w, h);
  ASSERT_EQ(w, 7);
  ASSERT_EQ(h, 5);
  const size_t stride = 1 + 7 * 3;
  EXPECT_EQ(raw[2 * stride], 0);  // filter byte
  EXPECT_EQ(raw[2 * stride + 1 + 3 * 3], 10);
  EXPECT_EQ(raw[2 * stride + 1 + 3 * 3 + 2], 30);
  EXPECT_EQ(raw[4 * stride + 1 + 6 * 3 + 1], 2);
  EXPECT_EQ(raw[0 * stride + 1], 255);
}

TEST(PngWriter, DrawingIsClipped) {
  Raster r(4, 4, {0, 0, 0});
  r.line(-10, -10, 20, 20, {9, 9, 9}, 3);
  r.text(-3, 2, "A1%", {5, 5, 5}, 2);
  EXPECT_EQ(r.at(1, 1).r, 9);
  EXPECT_EQ(r.at(99, 99).r, 0);  // out of range reads as black, no crash
}

TEST(PngWriter, UnwritablePathIsNamed) {
  Raster r(2, 2, {0, 0, 0});
  try {
    write_png(r, "/nonexistent-dir/x.png");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/x.png"), std::string::npos);
  }
}

}  // namespace
}  // namespace hexplore::evaluation
