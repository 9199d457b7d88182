// OpenEXR: linear float RGB, through the OpenEXR library (libopenexr-dev). The image is
// encoded in memory so that WriteImage's temporary file and rename serve EXR too.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "glint/image/ImageIO.hpp"

namespace glint {

namespace {

constexpr const char* kPrefix = "glint:";

// An Imf::OStream that appends to a string.
class StringOStream final : public Imf::OStream {
 public:
  explicit StringOStream(std::string& bytes) : Imf::OStream("memory"), bytes_(bytes) {}
  void write(const char c[], int n) override {
    const std::size_t count = static_cast<std::size_t>(n);
    if (bytes_.size() < position_ + count) bytes_.resize(position_ + count);
    std::memcpy(bytes_.data() + position_, c, count);
    position_ += count;
  }
  std::uint64_t tellp() override { return position_; }
  void seekp(std::uint64_t pos) override { position_ = static_cast<std::size_t>(pos); }

 private:
  std::string& bytes_;
  std::size_t position_ = 0;
};

// The image as three planes of floats, row 0 at the top (EXR's increasing y).
std::vector<float> Planes(const Image& image) {
  const std::size_t n = image.Pixels().size();
  std::vector<float> planes(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < 3; ++k) {
      planes[k * n + i] = static_cast<float>(image.Pixels()[i][static_cast<int>(k)]);
    }
  }
  return planes;
}

}  // namespace

std::string EncodeExr(const Image& image, const ImageAttributes& attributes) {
  const int w = image.Width();
  const int h = image.Height();
  Imf::Header header(w, h);
  header.compression() = Imf::ZIP_COMPRESSION;
  header.insert("software", Imf::StringAttribute("glint"));
  for (const auto& [name, value] : attributes) {
    header.insert(kPrefix + name, Imf::StringAttribute(value));
  }
  const char* names[3] = {"R", "G", "B"};
  std::vector<float> planes = Planes(image);
  const std::size_t n = image.Pixels().size();
  Imf::FrameBuffer frame;
  for (std::size_t k = 0; k < 3; ++k) {
    header.channels().insert(names[k], Imf::Channel(Imf::FLOAT));
    frame.insert(names[k], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(&planes[k * n]),
                                      sizeof(float), sizeof(float) * static_cast<std::size_t>(w)));
  }
  std::string bytes;
  StringOStream stream(bytes);
  Imf::OutputFile file(stream, header);
  file.setFrameBuffer(frame);
  file.writePixels(h);
  return bytes;
}

Image ReadExr(const std::string& path) {
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    const int w = window.max.x - window.min.x + 1;
    const int h = window.max.y - window.min.y + 1;
    const char* names[3] = {"R", "G", "B"};
    for (const char* name : names) {
      if (file.header().channels().findChannel(name) == nullptr) {
        throw std::runtime_error(path + ": an OpenEXR file without an " + name +
                                 " channel (expected linear RGB)");
      }
    }
    const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
    std::vector<float> planes(3 * n);
    Imf::FrameBuffer frame;
    const std::size_t xStride = sizeof(float);
    const std::size_t yStride = sizeof(float) * static_cast<std::size_t>(w);
    for (std::size_t k = 0; k < 3; ++k) {
      // The slice's base is where pixel (0, 0) would be, for a data window that may not
      // start there.
      char* base =
          reinterpret_cast<char*>(&planes[k * n]) -
          static_cast<std::ptrdiff_t>(window.min.x) * static_cast<std::ptrdiff_t>(xStride) -
          static_cast<std::ptrdiff_t>(window.min.y) * static_cast<std::ptrdiff_t>(yStride);
      frame.insert(names[k], Imf::Slice(Imf::FLOAT, base, xStride, yStride));
    }
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    Image image(w, h);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const std::size_t i =
            static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x);
        image.At(x, y) = Colour(planes[i], planes[n + i], planes[2 * n + i]);
      }
    }
    return image;
  } catch (const std::runtime_error&) {
    throw;
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": not a readable OpenEXR file: " + e.what());
  }
}

ImageAttributes ReadExrAttributes(const std::string& path) {
  try {
    const Imf::InputFile file(path.c_str());
    ImageAttributes out;
    const std::string prefix = kPrefix;
    for (auto it = file.header().begin(); it != file.header().end(); ++it) {
      const std::string name = it.name();
      const auto* text = dynamic_cast<const Imf::StringAttribute*>(&it.attribute());
      if (text != nullptr && name.compare(0, prefix.size(), prefix) == 0) {
        out[name.substr(prefix.size())] = text->value();
      }
    }
    return out;
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": not a readable OpenEXR file: " + e.what());
  }
}

}  // namespace glint
