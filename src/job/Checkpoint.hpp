// A render's state on disk, so that a render killed (even by SIGKILL) can go on where
// its last checkpoint left it: every pixel's sum, samples and complete passes, and how
// far the passes had come. `identity` names what the render is (scene file contents,
// overrides, size, seed, mode, switches, rays per pass): a resume refuses a checkpoint
// of anything else, naming the first field that differs.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "glint/camera/Camera.hpp"
#include "glint/camera/RenderStats.hpp"

namespace glint {

struct CheckpointProgress {
  std::uint32_t passes = 0;  // complete passes
  std::uint64_t spp = 0;     // their rays per pixel
  int currentRays = 0;       // rays per pixel of the pass under way (0: none)
  double seconds = 0.0;      // rendering time spent so far
  RenderStats stats;
};

// Writes the checkpoint through a temporary file and a rename: a kill at any moment
// leaves the previous checkpoint or the new one, never half of one.
void SaveCheckpoint(const std::string& path, const nlohmann::json& identity, const Camera& camera,
                    const CheckpointProgress& progress);

// Reads `path` into `camera` (of the same size) and returns the progress; throws
// InputError for a file that is not a checkpoint, or one of another render.
CheckpointProgress LoadCheckpoint(const std::string& path, const nlohmann::json& identity,
                                  Camera& camera);

// FNV-1a, 64 bits: the scene file's fingerprint in the identity.
std::uint64_t Fingerprint(const std::string& bytes);
// The fingerprint of the file at `path`, as 16 hex digits (a checkpoint's identity, an
// EXR's glint:scene_hash).
std::string FileFingerprint(const std::string& path);

}  // namespace glint
