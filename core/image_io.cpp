#include "core/image_io.h"

#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <stb_image_write.h>

#include "core/platform.h"

namespace shadowlab {

namespace fs = std::filesystem;

void flip_rows(std::vector<std::uint8_t>& pixels, int width, int height, int bytes_per_pixel) {
  const auto row = static_cast<std::size_t>(width) * static_cast<std::size_t>(bytes_per_pixel);
  std::vector<std::uint8_t> tmp(row);
  for (int y = 0; y < height / 2; ++y) {
    std::uint8_t* a = pixels.data() + static_cast<std::size_t>(y) * row;
    std::uint8_t* b = pixels.data() + static_cast<std::size_t>(height - 1 - y) * row;
    std::memcpy(tmp.data(), a, row);
    std::memcpy(a, b, row);
    std::memcpy(b, tmp.data(), row);
  }
}

namespace {

// Every output goes through one atomic write (platform.h): a unique temporary file created exclusively
// beside the target, then renamed over it. A link planted at the target or at a temporary name is
// replaced or refused, never written through; two runs writing one file never share a temporary one.
void write_output(const fs::path& path, std::string_view bytes, const char* what) {
  try {
    platform::write_file_atomic(path, bytes);
  } catch (const platform::FileError& e) {
    throw std::runtime_error(path.string() + ": cannot write " + what + ": " + e.what());
  }
}

}  // namespace

void write_png(const fs::path& path, int width, int height, const std::vector<std::uint8_t>& rgba) {
  if (rgba.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4)
    throw std::runtime_error(path.string() + ": image data does not match " + std::to_string(width) + "x" +
                             std::to_string(height));
  std::string png;
  const auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
  };
  if (!stbi_write_png_to_func(append, &png, width, height, 4, rgba.data(), width * 4))
    throw std::runtime_error(path.string() + ": cannot encode the PNG");
  write_output(path, png, "the PNG");
}

void write_npy(const fs::path& path, int width, int height, int channels, const std::vector<float>& data) {
  const auto count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * static_cast<std::size_t>(channels);
  if (data.size() != count) throw std::runtime_error(path.string() + ": buffer size does not match its shape");
  std::string header = "{'descr': '<f4', 'fortran_order': False, 'shape': (" + std::to_string(height) + ", " +
                       std::to_string(width) + (channels > 1 ? ", " + std::to_string(channels) : std::string()) + "), }";
  // NPY 1.0: magic, version, little-endian header length; the whole header is padded to 64 bytes.
  const std::size_t preamble = 10;
  const std::size_t padded = ((preamble + header.size() + 1 + 63) / 64) * 64;
  header.append(padded - preamble - header.size() - 1, ' ');
  header.push_back('\n');
  std::string bytes;
  const unsigned char magic[] = {0x93, 'N', 'U', 'M', 'P', 'Y', 1, 0};
  bytes.append(reinterpret_cast<const char*>(magic), sizeof magic);
  const auto len = static_cast<std::uint16_t>(header.size());
  bytes += static_cast<char>(len & 0xff);
  bytes += static_cast<char>(len >> 8);
  bytes += header;
  const std::size_t row = static_cast<std::size_t>(width) * static_cast<std::size_t>(channels);
  for (int y = height - 1; y >= 0; --y)
    bytes.append(reinterpret_cast<const char*>(data.data() + static_cast<std::size_t>(y) * row), row * sizeof(float));
  write_output(path, bytes, "the array");
}

void write_text_atomic(const fs::path& path, const std::string& text) { write_output(path, text, "the file"); }

}  // namespace shadowlab
