#include "renderer/image_io.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include <stb_image_write.h>

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

void write_png(const fs::path& path, int width, int height, const std::vector<std::uint8_t>& rgba) {
  if (rgba.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4)
    throw std::runtime_error(path.string() + ": image data does not match " + std::to_string(width) + "x" +
                             std::to_string(height));
  const fs::path tmp = path.string() + ".tmp";
  if (!stbi_write_png(tmp.c_str(), width, height, 4, rgba.data(), width * 4))
    throw std::runtime_error(path.string() + ": cannot write PNG (is the folder writable?)");
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) throw std::runtime_error(path.string() + ": cannot write PNG: " + ec.message());
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
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error(path.string() + ": cannot open for writing");
  const unsigned char magic[] = {0x93, 'N', 'U', 'M', 'P', 'Y', 1, 0};
  out.write(reinterpret_cast<const char*>(magic), sizeof magic);
  const auto len = static_cast<std::uint16_t>(header.size());
  const unsigned char len_bytes[] = {static_cast<unsigned char>(len & 0xff), static_cast<unsigned char>(len >> 8)};
  out.write(reinterpret_cast<const char*>(len_bytes), 2);
  out.write(header.data(), static_cast<std::streamsize>(header.size()));
  const std::size_t row = static_cast<std::size_t>(width) * static_cast<std::size_t>(channels);
  for (int y = height - 1; y >= 0; --y)
    out.write(reinterpret_cast<const char*>(data.data() + static_cast<std::size_t>(y) * row),
              static_cast<std::streamsize>(row * sizeof(float)));
  if (!out) throw std::runtime_error(path.string() + ": write failed");
}

void write_text_atomic(const fs::path& path, const std::string& text) {
  const fs::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(path.string() + ": cannot write (is the folder writable?)");
    out << text;
    out.flush();
    if (!out) throw std::runtime_error(path.string() + ": write failed");
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) throw std::runtime_error(path.string() + ": cannot replace: " + ec.message());
}

}  // namespace shadowlab
