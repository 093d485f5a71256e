// Which file of the model's folder a URL path names.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace sylva::studio {

// The file `request_path` names inside `folder`, or nothing when it is
// absolute, has a `..` component, is not a regular file, or leads (through
// symbolic links) outside the folder.
std::optional<std::filesystem::path> resolve_served_path(const std::filesystem::path& folder,
                                                         const std::string& request_path);

}  // namespace sylva::studio
