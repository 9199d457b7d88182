// Reading and writing images. Every writer goes through a temporary file in the same
// folder and renames it into place, so a failed write never leaves a truncated file.
#pragma once

#include <map>
#include <string>

#include "glint/image/Image.hpp"

namespace glint {

enum class ImageFormat { Pfm, Exr, Png, Ppm };

// What a render was (scene, mode, seed, ...): name -> text, written into EXR headers as
// string attributes "glint:<name>"; other formats carry none.
using ImageAttributes = std::map<std::string, std::string>;

// The format named by the file's extension (.pfm, .exr, .png, .ppm); throws InputError
// for anything else.
ImageFormat FormatFromPath(const std::string& path);

// The bytes of a file of that format: linear radiance (PFM, EXR) or the mapping
// function's output (PNG, PPM).
std::string EncodeImage(const Image& image, ImageFormat format, double exposure,
                        const ImageAttributes& attributes = {});

// Writes linear radiance as PFM or OpenEXR, or the mapping function's output as PNG or PPM.
// Throws std::runtime_error on an I/O failure.
void WriteImage(const Image& image, const std::string& path, double exposure,
                const ImageAttributes& attributes = {});

// PFM: "PF", width height, a negative scale for little-endian, rows bottom to top.
void WritePfm(const Image& image, const std::string& path);
Image ReadPfm(const std::string& path);

// OpenEXR: three 32-bit float channels R, G, B of linear radiance, ZIP-compressed
// (src/image/ExrImage.cpp, through the OpenEXR library).
std::string EncodeExr(const Image& image, const ImageAttributes& attributes = {});
Image ReadExr(const std::string& path);
ImageAttributes ReadExrAttributes(const std::string& path);
// The "glint:" string attributes of an EXR file (without the prefix); none for a PFM or
// an EXR another program wrote. Throws std::runtime_error for a file that cannot be read.
ImageAttributes ReadImageAttributes(const std::string& path);

// Linear radiance from a PFM or OpenEXR file, by its extension; throws std::runtime_error
// for a file that cannot be read and InputError for another extension.
Image ReadImage(const std::string& path);

// Writes `bytes` to `path` through a temporary file and a rename.
void WriteFileAtomically(const std::string& path, const std::string& bytes);

}  // namespace glint
