// Pictures as data: the tolerant picture comparison the golden snapshots use, and PNG files
// written whole (draw/image.h).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "draw/image.h"

namespace frictionlab::draw {
namespace {

namespace fs = std::filesystem;

Image flat(int width, int height, std::uint8_t grey) {
  Image image(width, height);
  for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = (i % 4 == 3) ? 255 : grey;
  return image;
}

TEST(Images, ComparisonAllowsEightPerChannelOnAnyPixelAndAnyChangeOnOnePixelInAThousand) {
  const Image expected = flat(100, 100, 128);
  Image within = expected;
  for (int x = 0; x < 100; ++x) within.pixel(x, 50)[1] = 136;  // +8 on a whole row
  ImageComparison result = compare_images(within, expected, 8);
  EXPECT_TRUE(result.same_size);
  EXPECT_EQ(result.differing_pixels, 0);
  EXPECT_EQ(result.largest_channel_difference, 8);

  Image ten_pixels = expected;  // 0.1 % of 10 000 pixels: the most that passes
  for (int x = 0; x < 10; ++x) ten_pixels.pixel(x, 0)[0] = 200;
  result = compare_images(ten_pixels, expected, 8);
  EXPECT_EQ(result.differing_pixels, 10);
  EXPECT_LE(result.differing_fraction(), 0.001);
  ten_pixels.pixel(10, 0)[2] = 137;  // one more, by 9
  result = compare_images(ten_pixels, expected, 8);
  EXPECT_EQ(result.differing_pixels, 11);
  EXPECT_GT(result.differing_fraction(), 0.001);
  // The diff marks the differing pixels red and leaves the rest grey.
  EXPECT_EQ(result.diff.pixel(10, 0)[0], 255);
  EXPECT_EQ(result.diff.pixel(10, 0)[1], 0);
  EXPECT_EQ(result.diff.pixel(50, 50)[0], result.diff.pixel(50, 50)[1]);

  EXPECT_FALSE(compare_images(flat(100, 99, 128), expected, 8).same_size);
}

TEST(Images, PngRoundTripsAndAFailedWriteLeavesNothing) {
  const fs::path folder = fs::temp_directory_path() / ("frictionlab_png_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  Image image = flat(37, 23, 40);
  image.pixel(3, 4)[0] = 250;
  const std::string path = (folder / "round.png").string();
  write_png(image, path);
  const Image back = read_png(path);
  EXPECT_EQ(back.width, 37);
  EXPECT_EQ(back.height, 23);
  EXPECT_EQ(back.rgba, image.rgba);
  EXPECT_FALSE(fs::exists(path + ".partial"));

  const std::string nowhere = (folder / "missing" / "frame.png").string();
  EXPECT_THROW(write_png(image, nowhere), std::runtime_error);
  EXPECT_FALSE(fs::exists(nowhere + ".partial"));
  EXPECT_THROW(read_png((folder / "absent.png").string()), std::runtime_error);
  fs::remove_all(folder);
}

}  // namespace
}  // namespace frictionlab::draw
