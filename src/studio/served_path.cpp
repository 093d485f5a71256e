#include "studio/served_path.h"

#include <algorithm>

namespace sylva::studio {

namespace fs = std::filesystem;

std::optional<fs::path> served_path(const fs::path& folder, std::string_view request) {
  if (request.empty() || request.find('\0') != std::string_view::npos) return std::nullopt;
  const fs::path relative(request);
  if (relative.is_absolute() || relative.has_root_path()) return std::nullopt;
  if (std::any_of(relative.begin(), relative.end(), [](const fs::path& part) { return part == ".."; }))
    return std::nullopt;

  std::error_code error;
  const fs::path root = fs::canonical(folder, error);
  if (error) return std::nullopt;
  const fs::path file = fs::canonical(root / relative, error);
  if (error || !fs::is_regular_file(file, error)) return std::nullopt;
  // Inside the folder: the root's components are a prefix of the file's.
  const auto [stop, unused] = std::mismatch(root.begin(), root.end(), file.begin(), file.end());
  if (stop != root.end()) return std::nullopt;
  return file;
}

}  // namespace sylva::studio
