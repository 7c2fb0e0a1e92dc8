#pragma once
// An RGB raster and a PNG encoder (zlib), so the station can draw its result pictures
// without a plotting stack.

#include <cstdint>
#include <string>
#include <vector>

namespace hexplore::evaluation {

struct Rgb {
  uint8_t r = 0, g = 0, b = 0;
};

// A width x height RGB image with clipped drawing primitives (pixel coordinates, y down).
class Raster {
 public:
  Raster(int width, int height, Rgb background);

  int width() const { return width_; }
  int height() const { return height_; }
  const std::vector<uint8_t>& pixels() const { return pixels_; }
  Rgb at(int x, int y) const;

  void set(int x, int y, Rgb c);
  void fill_rect(int x0, int y0, int x1, int y1, Rgb c);
  // Bresenham line, `thickness` pixels wide.
  void line(int x0, int y0, int x1, int y1, Rgb c, int thickness = 1);
  // Text in a built-in 5x7 font (digits, upper-case letters, a few symbols), scaled by `scale`.
  void text(int x, int y, const std::string& s, Rgb c, int scale = 1);

 private:
  int width_;
  int height_;
  std::vector<uint8_t> pixels_;
};

// Writes the raster as an 8-bit RGB PNG; throws std::runtime_error naming the path on failure.
void write_png(const Raster& image, const std::string& path);

}  // namespace hexplore::evaluation
