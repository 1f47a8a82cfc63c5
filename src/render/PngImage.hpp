#pragma once
/// The pixels of a PNG file (renderCase's frames), for checking pictures in tests. VTK stays in PngImage.cpp.

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace poro {

struct PngImage {
  int width = 0, height = 0;
  std::vector<std::array<std::uint8_t, 3>> rgb; ///< rgb[y width + x], y = 0 the top row

  /// Reads an 8-bit RGB or RGBA PNG. Throws InputError naming the file if it cannot.
  static PngImage read(const std::filesystem::path& file);
  const std::array<std::uint8_t, 3>& at(int x, int y) const {
    return rgb[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
  }
};

} // namespace poro
