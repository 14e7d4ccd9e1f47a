// Writing pictures and buffers: PNG (stb_image_write) for people, NumPy .npy for analysis in Python.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace shadowlab {

// RGBA8 pixels, top row first, written atomically. Throws std::runtime_error naming the file when it
// cannot be written.
void write_png(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& rgba);

// Flips rows in place (OpenGL reads bottom row first; images are stored top row first).
void flip_rows(std::vector<std::uint8_t>& pixels, int width, int height, int bytes_per_pixel);

// float32 array of shape (height, width, channels) or (height, width) when channels == 1, little-endian,
// rows top first as in the PNGs. `data` is bottom row first (OpenGL order) and is flipped on write.
void write_npy(const std::filesystem::path& path, int width, int height, int channels, const std::vector<float>& data);

// Every write here is atomic (platform::write_file_atomic): to a temporary file with a unique name,
// created exclusively beside the target, then renamed over it. A reader never sees a half-written file,
// a failure leaves the old one intact, two runs never share a temporary file, and a symbolic link
// planted in the folder (at the target's name or a temporary one) is never written through.

// Writes text atomically (see above).
void write_text_atomic(const std::filesystem::path& path, const std::string& text);

}  // namespace shadowlab
