#include "studio/served_path.h"

namespace sylva::studio {

std::optional<std::filesystem::path> resolve_served_path(const std::filesystem::path& folder,
                                                         const std::string& request_path) {
  namespace fs = std::filesystem;
  const fs::path relative(request_path);
  if (relative.empty() || relative.is_absolute()) return std::nullopt;
  for (const fs::path& part : relative)
    if (part == "..") return std::nullopt;
  std::error_code ec;
  const fs::path root = fs::canonical(folder, ec);
  if (ec) return std::nullopt;
  const fs::path file = fs::canonical(root / relative, ec);
  if (ec || !fs::is_regular_file(file, ec)) return std::nullopt;
  const auto [end, _] = std::mismatch(root.begin(), root.end(), file.begin(), file.end());
  if (end != root.end()) return std::nullopt;
  return file;
}

}  // namespace sylva::studio
