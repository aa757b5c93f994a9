#include "draw/framebuffer.h"

#include <cstdint>
#include <cstring>
#include <vector>

#include "draw/gl.h"

namespace frictionlab::draw {

Image read_framebuffer(int width, int height) {
  Image image(width, height);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  // OpenGL's rows run bottom up; a picture's top down.
  const std::size_t row = static_cast<std::size_t>(width) * 4;
  std::vector<std::uint8_t> swap(row);
  for (int y = 0; y < height / 2; ++y) {
    std::uint8_t* top = image.rgba.data() + static_cast<std::size_t>(y) * row;
    std::uint8_t* bottom = image.rgba.data() + static_cast<std::size_t>(height - 1 - y) * row;
    std::memcpy(swap.data(), top, row);
    std::memcpy(top, bottom, row);
    std::memcpy(bottom, swap.data(), row);
  }
  return image;
}

}  // namespace frictionlab::draw
