#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "glint/image/ImageIO.hpp"
#include "support/TestScenes.hpp"

namespace glint {
namespace {

namespace fs = std::filesystem;

std::string ReadAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

fs::path FreshDir(const std::string& name) {
  const fs::path dir = testing::BinaryPath(name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(ImageIO, PfmRoundTripAndBottomRowFirst) {
  Image image(3, 2);
  image.At(0, 0) = Colour(1.0, 0.0, 0.0);   // top left
  image.At(0, 1) = Colour(0.0, 0.25, 0.0);  // bottom left
  image.At(2, 1) = Colour(0.5, 1e-3, 7.0);
  const std::string path = (FreshDir("pfm") / "a.pfm").string();
  WriteImage(image, path, 1.0);
  const std::string bytes = ReadAll(path);
  ASSERT_EQ(bytes.rfind("PF\n3 2\n-1.0\n", 0), 0u);
  float first[3];
  std::memcpy(first, bytes.data() + std::strlen("PF\n3 2\n-1.0\n"), sizeof first);
  EXPECT_EQ(first[1], 0.25f);  // the file starts with the bottom scanline
  const Image back = ReadPfm(path);
  ASSERT_EQ(back.Width(), 3);
  ASSERT_EQ(back.Height(), 2);
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 3; ++x) {
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(static_cast<double>(static_cast<float>(image.At(x, y)[k])), back.At(x, y)[k]);
      }
    }
  }
}

TEST(ImageIO, ExrRoundTripIsFloatExactAndRowZeroIsTheTop) {
  Image image(5, 3);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 5; ++x) image.At(x, y) = Colour(0.1 * x + y, 1e-4 * (x + 1), 50.0 * y);
  }
  const std::string exr = (FreshDir("exr") / "a.exr").string();
  const std::string pfm = (FreshDir("exr") / "a.pfm").string();
  WriteImage(image, exr, 1.0);
  WriteImage(image, pfm, 1.0);
  ASSERT_EQ(ReadAll(exr).rfind("\x76\x2f\x31\x01", 0), 0u);  // OpenEXR's magic number
  const Image back = ReadImage(exr);
  const Image fromPfm = ReadImage(pfm);
  ASSERT_EQ(back.Width(), 5);
  ASSERT_EQ(back.Height(), 3);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 5; ++x) {
      EXPECT_EQ(back.At(x, y), fromPfm.At(x, y)) << x << "," << y;
    }
  }
  EXPECT_EQ(back.At(4, 2).z, 100.0);  // the bottom row stays the bottom row
  EXPECT_THROW(ReadImage((FreshDir("exr") / "missing.exr").string()), std::runtime_error);
  EXPECT_THROW(ReadImage(pfm + ".txt"), InputError);
}

TEST(ImageIO, MappingFunction) {
  Image image(4, 1);
  image.At(0, 0) = Colour(0.0);
  image.At(1, 0) = Colour(1.0);
  image.At(2, 0) = Colour(0.25);   // 0.5 after exposure 2
  image.At(3, 0) = Colour(100.0);  // clamped
  const std::vector<std::uint8_t> d = image.ToDisplay(2.0);
  EXPECT_EQ(d[0], 0);
  EXPECT_EQ(d[3], 255);
  EXPECT_EQ(d[6], 188);  // sRGB(0.5) = 0.7354
  EXPECT_EQ(d[9], 255);
}

TEST(ImageIO, PngAndPpmAreWritten) {
  Image image(5, 4);
  const fs::path dir = FreshDir("png");
  WriteImage(image, (dir / "a.png").string(), 1.0);
  WriteImage(image, (dir / "a.PPM").string(), 1.0);
  EXPECT_EQ(ReadAll((dir / "a.png").string()).substr(1, 3), "PNG");
  EXPECT_EQ(ReadAll((dir / "a.PPM").string()).rfind("P6\n5 4\n255\n", 0), 0u);
}

TEST(ImageIO, UnknownExtensionIsRejected) {
  EXPECT_THROW(FormatFromPath("a.jpg"), InputError);
  EXPECT_THROW(FormatFromPath("noextension"), InputError);
}

TEST(ImageIO, WritesReplaceAtomicallyAndLeaveNoTemporaryFiles) {
  const fs::path dir = FreshDir("atomic");
  const std::string path = (dir / "out.pfm").string();
  WriteFileAtomically(path, "old contents");
  WriteFileAtomically(path, "new");
  EXPECT_EQ(ReadAll(path), "new");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  // A failed write leaves the old file as it was.
  EXPECT_THROW(WriteFileAtomically((dir / "missing" / "x.pfm").string(), "x"), std::runtime_error);
  EXPECT_EQ(ReadAll(path), "new");
}

}  // namespace
}  // namespace glint
