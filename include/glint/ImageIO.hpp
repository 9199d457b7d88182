// Reading and writing images. Every writer goes through a temporary file in the same
// folder and renames it into place, so a failed write never leaves a truncated file.
#pragma once

#include <string>

#include "glint/Image.hpp"

namespace glint {

enum class ImageFormat { Pfm, Png, Ppm };

// The format named by the file's extension (.pfm, .png, .ppm); throws InputError for
// anything else.
ImageFormat FormatFromPath(const std::string& path);

// Writes linear radiance as PFM, or the mapping function's output as PNG or PPM.
// Throws std::runtime_error on an I/O failure.
void WriteImage(const Image& image, const std::string& path, double exposure);

// PFM: "PF", width height, a negative scale for little-endian, rows bottom to top.
void WritePfm(const Image& image, const std::string& path);
Image ReadPfm(const std::string& path);

// Writes `bytes` to `path` through a temporary file and a rename.
void WriteFileAtomically(const std::string& path, const std::string& bytes);

}  // namespace glint
