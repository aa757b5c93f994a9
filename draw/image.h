// Pictures in memory, PNG files written whole or not at all, and the tolerant comparison the
// snapshot tests use.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace frictionlab::draw {

// RGBA, 8 bits a channel, top row first.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4, 0) {}
  const std::uint8_t* pixel(int x, int y) const { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
  std::uint8_t* pixel(int x, int y) { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
};

// Encodes to PNG in memory and writes it whole or not at all, never over anything but a
// regular file (files/output_file.h): a reader never sees half a picture, and a failure leaves
// nothing behind. Throws std::runtime_error.
void write_png(const Image& image, const std::string& path);
// FOLDER/STEM.EXTENSION, or STEM_2, STEM_3... when taken: a new file never replaces one made
// before. Throws std::runtime_error when the folder cannot be looked into.
std::string unused_path(const std::string& folder, const std::string& stem, const std::string& extension);
// The encoded PNG bytes, for timing the encoder apart from the disk.
std::vector<std::uint8_t> encode_png(const Image& image);
// Throws std::runtime_error naming the path when it cannot be read as a PNG.
Image read_png(const std::string& path);

// How two pictures of the same moment differ. A channel that differs by more than the
// tolerance makes its pixel count as different; the diff image shows those pixels in red over
// a faded copy of the expected picture.
struct ImageComparison {
  bool same_size = false;
  long differing_pixels = 0;
  int largest_channel_difference = 0;
  double differing_fraction() const;
  Image diff;
};
ImageComparison compare_images(const Image& actual, const Image& expected, int channel_tolerance);

}  // namespace frictionlab::draw
