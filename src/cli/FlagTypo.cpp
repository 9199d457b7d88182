#include "cli/FlagTypo.hpp"

#include <utility>

#include "glint/core/JsonReader.hpp"

namespace glint {

namespace {

// Words people type for a flag that glint spells otherwise: a misspelt "samples" is
// nearer "--sampler" than "--spp", which is what it meant.
const std::pair<const char*, const char*> kSynonyms[] = {
    {"samples", "--spp"},     {"rays", "--spp"},
    {"output", "-o"},         {"out", "-o"},
    {"mode", "--mode"},       {"threads", "--threads"},
    {"resolution", "--size"}, {"res", "--size"},
    {"width", "--size"},      {"height", "--size"},
    {"time", "--time"},       {"depth", "--max-depth"},
};

bool HasFlag(const CLI::App& command, const std::string& flag) {
  for (const CLI::Option* o : command.get_options()) {
    for (const std::string& name : o->get_lnames()) {
      if ("--" + name == flag) return true;
    }
    for (const std::string& name : o->get_snames()) {
      if ("-" + name == flag) return true;
    }
  }
  return false;
}

// The nearest flag of `command` to `typed` (without its dashes), or "" if none is near:
// within 2 edits, or a third of the word.
std::string NearestFlag(const CLI::App& command, const std::string& typed) {
  std::string best;
  std::size_t bestDistance = std::max<std::size_t>(2, typed.size() / 3) + 1;
  const auto consider = [&](const std::string& word, const std::string& flag) {
    const std::size_t d = EditDistance(typed, word);
    if (d < bestDistance) {
      bestDistance = d;
      best = flag;
    }
  };
  for (const CLI::Option* o : command.get_options()) {
    for (const std::string& name : o->get_lnames()) consider(name, "--" + name);
  }
  for (const auto& [word, flag] : kSynonyms) {
    if (HasFlag(command, flag)) consider(word, flag);
  }
  return best;
}

}  // namespace

std::string UnknownFlagMessage(const CLI::App& command, const std::vector<std::string>& extras) {
  for (const std::string& arg : extras) {
    if (arg.size() < 2 || arg[0] != '-' || (arg[1] >= '0' && arg[1] <= '9') || arg[1] == '.') {
      continue;  // a value, or a negative number
    }
    const std::string bare = arg.substr(0, arg.find('='));
    const std::string typed = bare.substr(bare.find_first_not_of('-'));
    const std::string name = "glint " + command.get_name();
    const std::string nearest = NearestFlag(command, typed);
    if (!nearest.empty()) {
      return name + ": unknown flag " + bare + " (did you mean " + nearest + "?); '" + name +
             " --help' lists its flags";
    }
    return name + ": unknown flag " + bare + "; '" + name + " --help' lists its flags";
  }
  return "";
}

}  // namespace glint
