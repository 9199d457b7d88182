// What to tell a user whose command line has a flag the command does not know: the
// nearest flag by edit distance, as the scene loader does for a misspelt field.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace glint {

// The message for the arguments `extras` that `command` did not expect, or "" if none of
// them is a flag (CLI11's own message then says which values were not expected).
std::string UnknownFlagMessage(const CLI::App& command, const std::vector<std::string>& extras);

}  // namespace glint
