#include "commands/CompareCommand.hpp"

#include <cstdio>
#include <optional>
#include <stdexcept>

#include "glint/core/JsonReader.hpp"
#include "glint/image/BiasTest.hpp"
#include "glint/image/ImageIO.hpp"
#include "job/ExitCode.hpp"

namespace glint {

namespace {

// An image that cannot be read is bad input here, not a failed output.
Image ReadInput(const std::string& path) {
  try {
    return ReadImage(path);
  } catch (const std::runtime_error& e) {
    throw InputError(e.what());
  }
}

Image Scaled(Image image, double scale) {
  if (scale == 1.0) return image;
  for (int y = 0; y < image.Height(); ++y) {
    for (int x = 0; x < image.Width(); ++x) image.At(x, y) *= scale;
  }
  return image;
}

}  // namespace

int RunCompare(const CompareArgs& args) {
  const Image a = Scaled(ReadInput(args.a), args.scale);
  const Image b = Scaled(ReadInput(args.b), args.scale);
  const Image ref = ReadInput(args.reference);
  std::optional<Image> ref2;
  if (!args.reference2.empty()) ref2 = ReadInput(args.reference2);
  const auto size = [](const Image& i) {
    return std::to_string(i.Width()) + "x" + std::to_string(i.Height());
  };
  for (const auto* p : {&a, &b, ref2 ? &*ref2 : &ref}) {
    if (p->Width() != ref.Width() || p->Height() != ref.Height()) {
      throw InputError("the images differ in size: expected " + size(ref) + " as " +
                       args.reference + ", found " + size(*p));
    }
  }
  BiasTestOptions options;
  options.block = args.block;
  options.meanSigma = args.meanSigma;
  options.familyAlpha = args.familyAlpha;
  const BiasVerdict v = TestBias(a, b, ref, ref2 ? &*ref2 : nullptr, options);
  std::printf(
      "glint compare: %s: mean ratio %.5f (z %+.2f, limit %.1f); %d block tests of %dx%d: "
      "max |z| %.2f, %d beyond 4 sigma, %d beyond the limit %.2f; reference %s\n",
      v.agree ? "agree" : "DISAGREE", v.meanRatio, v.meanZ, args.meanSigma, v.blockTests,
      args.block, args.block, v.maxBlockZ, v.beyond4, v.failedBlocks, v.blockLimit,
      ref2 ? "noise from REF - REF2" : "taken as exact");
  return v.agree ? kExitOk : kExitDisagree;
}

}  // namespace glint
