#include "job/DataFiles.hpp"

#include <filesystem>
#include <system_error>

namespace glint {

std::string DataFile(const std::string& relative) {
  std::error_code error;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    const std::filesystem::path installed = exe.parent_path() / ".." / "share" / "glint" / relative;
    if (std::filesystem::exists(installed, error)) {
      return installed.lexically_normal().string();
    }
  }
  return (std::filesystem::path(GLINT_SOURCE_DIR) / relative).string();
}

}  // namespace glint
