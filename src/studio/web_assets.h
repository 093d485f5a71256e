// The studio's page (web/), bundled at build time and compiled into the
// program, so the studio needs no network and no files beside the binary.
#pragma once

#include <optional>
#include <string_view>

namespace sylva::studio {

struct WebAsset {
  std::string_view content;
  const char* content_type;
};

// "index.html", "studio.js" or "studio.css"; nothing for any other name.
std::optional<WebAsset> web_asset(std::string_view name);

}  // namespace sylva::studio
