// A render's identity in its EXR files (header attributes "glint:scene", "glint:mode", ...),
// and the checks that read it back: a reference of another scene or mode is refused, and
// so are two renders that are one (the same seed: their noise is the same noise).
#pragma once

#include <cstdint>
#include <string>

#include "glint/image/ImageIO.hpp"
#include "job/RenderSetup.hpp"

namespace glint {

// scene (the path as given), scene_hash (of its contents), set, size, mode, walls (Monte
// Carlo), fresnel, sampler, spp, seed, version.
ImageAttributes RenderAttributes(const RenderArgs& args, const RenderSetup& s, std::uint64_t spp);

// Throws InputError, naming the field, when `other` (an image file, e.g. "--reference
// r.exr") was rendered from another scene, with other --set values, at another size, in
// another mode, with other walls or Fresnel model: what a converged render shows. Fields
// either side lacks (a PFM, Cycles' EXR) are not compared.
void CheckSameScene(const ImageAttributes& mine, const ImageAttributes& other,
                    const std::string& otherName, const std::string& mineName);

// Both carry a seed and it is the same one, for the same scene and sampler.
bool SameSeed(const ImageAttributes& a, const ImageAttributes& b);

}  // namespace glint
