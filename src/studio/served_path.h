// Which file of the model's folder a request names, for "GET /files/PATH":
// only regular files inside the folder are served, so that a request can
// never read outside it.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

namespace sylva::studio {

// The canonical path of the file `request` (already URL-decoded, relative:
// "plant.l", "sub/x.txt") names in `folder`; nothing when the request is
// empty or absolute, has a ".." component or a NUL, names what is not a
// regular file or does not exist, or leads (symbolic links followed) outside
// the folder. Symbolic links that stay inside the folder are followed.
std::optional<std::filesystem::path> served_path(const std::filesystem::path& folder, std::string_view request);

}  // namespace sylva::studio
