#include "commands/CompareCommand.hpp"

#include <cstdio>
#include <optional>
#include <stdexcept>
#include <tuple>

#include "glint/core/JsonReader.hpp"
#include "glint/image/BiasTest.hpp"
#include "glint/image/ImageIO.hpp"
#include "job/ExitCode.hpp"
#include "job/RenderAttributes.hpp"

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

ImageAttributes ReadAttributes(const std::string& path) {
  try {
    return ReadImageAttributes(path);
  } catch (const std::runtime_error& e) {
    throw InputError(e.what());
  }
}

bool SamePixels(const Image& x, const Image& y) {
  return x.Width() == y.Width() && x.Height() == y.Height() && x.Pixels() == y.Pixels();
}

}  // namespace

int RunCompare(const CompareArgs& args) {
  const Image a = ReadInput(args.a).Scaled(Colour(args.scale));
  const Image b = ReadInput(args.b).Scaled(Colour(args.scale));
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
  // The noise comes from A - B (and REF - REF2): one render given twice has none, and
  // every difference from the reference would be infinitely many standard errors. The same
  // seed in two EXR files' attributes makes the same noise too.
  const ImageAttributes atA = ReadAttributes(args.a);
  const ImageAttributes atB = ReadAttributes(args.b);
  const ImageAttributes atRef = ReadAttributes(args.reference);
  CheckSameScene(atA, atRef, args.reference, args.a);
  CheckSameScene(atB, atRef, args.reference, args.b);
  CheckSameScene(atA, atB, args.b, args.a);
  if (SamePixels(a, b) || SameSeed(atA, atB)) {
    throw InputError(args.a + " and " + args.b + ": A and B are the same render" +
                     (SamePixels(a, b) ? "" : " (the same seed)") +
                     ": render B with another --seed");
  }
  for (const auto& [image, path, at] : {std::tie(a, args.a, atA), std::tie(b, args.b, atB)}) {
    if (SamePixels(image, ref) || SameSeed(at, atRef)) {
      throw InputError(path + " and " + args.reference +
                       ": a render and its reference are the same render" +
                       (SamePixels(image, ref) ? "" : " (the same seed)") +
                       ": render the reference with another --seed");
    }
  }
  if (ref2 && SamePixels(ref, *ref2)) {
    throw InputError(args.reference2 + ": the same image as " + args.reference +
                     ": REF2 must be a render independent of REF (another --seed)");
  }
  for (const auto& [image, path] : {std::tie(a, args.a), std::tie(b, args.b)}) {
    const double mean = image.Mean() / args.scale;
    if (mean > 2.0 * ref.Mean() || ref.Mean() > 2.0 * mean) {
      std::fprintf(stderr,
                   "glint compare: warning: %s has mean radiance %.4g, %s the reference's %.4g "
                   "(%s): is the reference of the same scene and mode?\n",
                   path.c_str(), mean, mean > ref.Mean() ? "more than twice" : "less than half",
                   ref.Mean(), args.reference.c_str());
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
