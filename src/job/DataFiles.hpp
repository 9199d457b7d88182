// Files glint reads that are not the user's: the canonical scene (glint bench's default)
// and the chart script of glint converge. Installed (cmake --install) they live in
// PREFIX/share/glint beside PREFIX/bin/glint; in a build tree, in the source tree.
#pragma once

#include <string>

namespace glint {

// The path of `relative` (e.g. "scenes/cornell.json"): under ../share/glint from the
// running executable if it is there, else under the source tree glint was built from.
std::string DataFile(const std::string& relative);

}  // namespace glint
