#include "job/Checkpoint.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

#include "glint/core/JsonReader.hpp"
#include "glint/image/ImageIO.hpp"

namespace glint {

namespace {

constexpr const char* kMagic = "glint checkpoint 2\n";

// Per pixel: the sum (3 doubles), the samples (uint64), the complete passes (uint32) and
// light tracing's splats (3 int64, Pixel::SplatSum).
constexpr std::size_t kPixelBytes =
    3 * sizeof(double) + sizeof(std::uint64_t) + sizeof(std::uint32_t) + 3 * sizeof(std::int64_t);

template <typename T>
void Put(std::string& out, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  out.append(raw, sizeof(T));
}

template <typename T>
T Get(const char*& p) {
  T value;
  std::memcpy(&value, p, sizeof(T));
  p += sizeof(T);
  return value;
}

}  // namespace

std::uint64_t Fingerprint(const std::string& bytes) {
  std::uint64_t h = 14695981039346656037ULL;
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ULL;
  }
  return h;
}

std::string FileFingerprint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(Fingerprint(bytes)));
  return hex;
}

void SaveCheckpoint(const std::string& path, const nlohmann::json& identity, const Camera& camera,
                    const CheckpointProgress& progress) {
  const nlohmann::json header = {
      {"identity", identity},        {"passes", progress.passes},
      {"spp", progress.spp},         {"current_rays", progress.currentRays},
      {"seconds", progress.seconds}, {"stats", progress.stats.ToCounters()}};
  const std::size_t count =
      static_cast<std::size_t>(camera.Width()) * static_cast<std::size_t>(camera.Height());
  std::string out = kMagic;
  out += header.dump() + "\n";
  out.reserve(out.size() + count * kPixelBytes);
  for (std::size_t i = 0; i < count; ++i) {
    const Pixel& p = camera.PixelAt(i);
    const Colour s = p.Sum();
    Put(out, s.x);
    Put(out, s.y);
    Put(out, s.z);
    Put(out, p.Samples());
    Put(out, p.Passes());
    for (const std::int64_t v : p.Splats()) Put(out, v);
  }
  WriteFileAtomically(path, out);
}

CheckpointProgress LoadCheckpoint(const std::string& path, const nlohmann::json& identity,
                                  Camera& camera) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("--resume " + path + ": cannot open the checkpoint");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t magic = std::strlen(kMagic);
  const std::size_t eol = bytes.find('\n', magic);
  if (bytes.compare(0, magic, kMagic) != 0 || eol == std::string::npos) {
    throw InputError("--resume " + path + ": not a glint checkpoint");
  }
  nlohmann::json header;
  try {
    header = nlohmann::json::parse(bytes.substr(magic, eol - magic));
  } catch (const nlohmann::json::exception&) {
    throw InputError("--resume " + path + ": not a glint checkpoint (its header is damaged)");
  }
  const nlohmann::json& saved = header.at("identity");
  for (auto it = identity.begin(); it != identity.end(); ++it) {
    if (!saved.contains(it.key()) || saved.at(it.key()) != it.value()) {
      throw InputError("--resume " + path + ": a checkpoint of another render: its " + it.key() +
                       " is " + (saved.contains(it.key()) ? saved.at(it.key()).dump() : "missing") +
                       ", this render's is " + it.value().dump());
    }
  }
  const std::size_t count =
      static_cast<std::size_t>(camera.Width()) * static_cast<std::size_t>(camera.Height());
  if (bytes.size() != eol + 1 + count * kPixelBytes) {
    throw InputError("--resume " + path + ": a truncated checkpoint");
  }
  const char* p = bytes.data() + eol + 1;
  for (std::size_t i = 0; i < count; ++i) {
    const double r = Get<double>(p);
    const double g = Get<double>(p);
    const double b = Get<double>(p);
    const auto samples = Get<std::uint64_t>(p);
    const auto passes = Get<std::uint32_t>(p);
    Pixel::SplatSum splats{};
    for (std::int64_t& v : splats) v = Get<std::int64_t>(p);
    camera.PixelAt(i).Restore(Colour(r, g, b), samples, passes);
    camera.PixelAt(i).RestoreSplats(splats);
  }
  CheckpointProgress progress;
  progress.passes = header.at("passes");
  progress.spp = header.at("spp");
  progress.currentRays = header.at("current_rays");
  progress.seconds = header.at("seconds");
  // A checkpoint of the build before the SIMD lanes holds 9 counters: laneRays, the
  // 10th, was 0 then (no lanes).
  std::vector<std::uint64_t> stats = header.at("stats").get<std::vector<std::uint64_t>>();
  RenderStats::Counters counters{};
  if (stats.size() + 1 == counters.size()) stats.push_back(0);
  if (stats.size() != counters.size()) {
    throw InputError("--resume " + path + ": field stats: expected " +
                     std::to_string(counters.size()) + " counters, found " +
                     std::to_string(stats.size()));
  }
  std::copy(stats.begin(), stats.end(), counters.begin());
  progress.stats = RenderStats::FromCounters(counters);
  return progress;
}

}  // namespace glint
