// Writing pictures and buffers: PNG (stb_image_write) for people, NumPy .npy for analysis in Python.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace shadowlab {

// RGBA8 pixels, top row first. Throws std::runtime_error naming the file when it cannot be written.
void write_png(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& rgba);

// Flips rows in place (OpenGL reads bottom row first; images are stored top row first).
void flip_rows(std::vector<std::uint8_t>& pixels, int width, int height, int bytes_per_pixel);

// float32 array of shape (height, width, channels) or (height, width) when channels == 1, little-endian,
// rows top first as in the PNGs. `data` is bottom row first (OpenGL order) and is flipped on write.
void write_npy(const std::filesystem::path& path, int width, int height, int channels, const std::vector<float>& data);

// Writes text atomically: to a temporary file beside the target, then renamed over it, so a reader never
// sees a half-written file and a failure leaves the old one intact.
void write_text_atomic(const std::filesystem::path& path, const std::string& text);

}  // namespace shadowlab
