#include "build/cache_manifest.h"

#include <sstream>

#include "build/model_cache.h"
#include "support/content_hash.h"

namespace sylva::build {

namespace {

const std::string kLibraryExtension = ".so";

std::string checksum_of(const std::string& text) {
  ContentHash h;
  h.add(text);
  return h.hex();
}

}  // namespace

bool is_cache_key(const std::string& text) {
  if (text.size() != 32) return false;
  for (char c : text)
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  return true;
}

bool is_library_name(const std::string& name) {
  return name.size() == 32 + kLibraryExtension.size() && name.ends_with(kLibraryExtension) &&
         is_cache_key(name.substr(0, 32));
}

std::string manifest_text(const Manifest& manifest) {
  std::string text = std::string(kCacheFormat) + " " + manifest.lookup_key + "\n";
  text += "library " + manifest.library + "\n";
  for (const std::string& warning : manifest.warnings)
    if (warning.find('\n') == std::string::npos) text += "warning " + warning + "\n";
  for (const Manifest::Dependency& dep : manifest.dependencies) text += "dep " + dep.stamp + " " + dep.path + "\n";
  return text + "check " + checksum_of(text) + "\n";
}

std::optional<Manifest> read_manifest(const std::string& text, const std::string& lookup_key) {
  const std::size_t check = text.rfind("check ");
  if (check == std::string::npos || (check > 0 && text[check - 1] != '\n')) return std::nullopt;
  if (text.substr(check) != "check " + checksum_of(text.substr(0, check)) + "\n") return std::nullopt;

  std::stringstream in(text.substr(0, check));
  std::string line;
  if (!std::getline(in, line) || line != std::string(kCacheFormat) + " " + lookup_key) return std::nullopt;
  Manifest manifest;
  manifest.lookup_key = lookup_key;
  while (std::getline(in, line)) {
    if (line.starts_with("library ")) {
      manifest.library = line.substr(8);
    } else if (line.starts_with("warning ")) {
      manifest.warnings.push_back(line.substr(8));
    } else if (line.starts_with("dep ")) {
      const std::size_t space = line.find(' ', 4);
      if (space == std::string::npos) return std::nullopt;
      manifest.dependencies.push_back({line.substr(4, space - 4), line.substr(space + 1)});
    } else {
      return std::nullopt;
    }
  }
  if (!is_library_name(manifest.library)) return std::nullopt;
  return manifest;
}

}  // namespace sylva::build
