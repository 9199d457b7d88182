#include "glint/image/ImageIO.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <stb_image_write.h>

#include "glint/core/JsonReader.hpp"

namespace glint {

namespace {

std::string Extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return ext;
}

std::string EncodePfm(const Image& image) {
  std::ostringstream out;
  out << "PF\n" << image.Width() << ' ' << image.Height() << "\n-1.0\n";
  std::string bytes = out.str();
  // Little-endian floats (negative scale), scanlines from the bottom row up.
  for (int y = image.Height() - 1; y >= 0; --y) {
    for (int x = 0; x < image.Width(); ++x) {
      const Colour c = image.At(x, y);
      for (int k = 0; k < 3; ++k) {
        const auto f = static_cast<float>(c[k]);
        char raw[sizeof(float)];
        std::memcpy(raw, &f, sizeof f);
        bytes.append(raw, sizeof raw);
      }
    }
  }
  return bytes;
}

std::string EncodePpm(const Image& image, double exposure) {
  const std::vector<std::uint8_t> display = image.ToDisplay(exposure);
  std::string bytes =
      "P6\n" + std::to_string(image.Width()) + ' ' + std::to_string(image.Height()) + "\n255\n";
  bytes.append(display.begin(), display.end());
  return bytes;
}

void AppendToString(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                             static_cast<std::size_t>(size));
}

std::string EncodePng(const Image& image, double exposure) {
  const std::vector<std::uint8_t> display = image.ToDisplay(exposure);
  std::string bytes;
  if (stbi_write_png_to_func(AppendToString, &bytes, image.Width(), image.Height(), 3,
                             display.data(), image.Width() * 3) == 0) {
    throw std::runtime_error("PNG encoding failed");
  }
  return bytes;
}

}  // namespace

ImageFormat FormatFromPath(const std::string& path) {
  const std::string ext = Extension(path);
  if (ext == ".pfm") return ImageFormat::Pfm;
  if (ext == ".exr") return ImageFormat::Exr;
  if (ext == ".png") return ImageFormat::Png;
  if (ext == ".ppm") return ImageFormat::Ppm;
  throw InputError(path + ": unknown output format '" + ext +
                   "': expected a file name ending in .png, .ppm, .pfm or .exr");
}

void WriteFileAtomically(const std::string& path, const std::string& bytes) {
  const std::filesystem::path target(path);
  const std::filesystem::path dir =
      target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  std::string pattern = (dir / ("." + target.filename().string() + ".tmp-XXXXXX")).string();
  const int fd = mkstemp(pattern.data());
  if (fd < 0) {
    throw std::runtime_error(path + ": cannot create a file in '" + dir.string() +
                             "': " + std::strerror(errno));
  }
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      const std::string why = std::strerror(errno);
      ::close(fd);
      std::remove(pattern.c_str());
      throw std::runtime_error(path + ": write failed: " + why);
    }
    written += static_cast<std::size_t>(n);
  }
  // mkstemp makes the file 0600; an image should be as readable as any other file.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, static_cast<mode_t>(0666) & ~mask);
  if (::close(fd) != 0 || std::rename(pattern.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(pattern.c_str());
    throw std::runtime_error(path + ": cannot write: " + why);
  }
}

std::string EncodeImage(const Image& image, ImageFormat format, double exposure,
                        const ImageAttributes& attributes) {
  switch (format) {
    case ImageFormat::Pfm:
      return EncodePfm(image);
    case ImageFormat::Exr:
      return EncodeExr(image, attributes);
    case ImageFormat::Png:
      return EncodePng(image, exposure);
    case ImageFormat::Ppm:
      return EncodePpm(image, exposure);
  }
  return {};
}

void WriteImage(const Image& image, const std::string& path, double exposure,
                const ImageAttributes& attributes) {
  WriteFileAtomically(path, EncodeImage(image, FormatFromPath(path), exposure, attributes));
}

void WritePfm(const Image& image, const std::string& path) {
  WriteFileAtomically(path, EncodePfm(image));
}

Image ReadPfm(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::string magic;
  int width = 0;
  int height = 0;
  double scale = 0.0;
  in >> magic >> width >> height >> scale;
  in.get();  // the single whitespace after the header
  if (!in || magic != "PF" || width <= 0 || height <= 0 || scale >= 0.0) {
    throw std::runtime_error(path + ": not a little-endian RGB PFM file");
  }
  Image image(width, height);
  for (int y = height - 1; y >= 0; --y) {
    for (int x = 0; x < width; ++x) {
      float rgb[3];
      in.read(reinterpret_cast<char*>(rgb), sizeof rgb);
      image.At(x, y) = Colour(rgb[0], rgb[1], rgb[2]);
    }
  }
  if (!in) throw std::runtime_error(path + ": truncated PFM file");
  return image;
}

ImageAttributes ReadImageAttributes(const std::string& path) {
  if (Extension(path) == ".exr") return ReadExrAttributes(path);
  return {};
}

Image ReadImage(const std::string& path) {
  const std::string ext = Extension(path);
  if (ext == ".pfm") return ReadPfm(path);
  if (ext == ".exr") return ReadExr(path);
  throw InputError(path + ": expected an image of linear radiance, a .pfm or .exr file");
}

}  // namespace glint
