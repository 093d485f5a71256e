// A manifest: what a model built into, found without translating the model
// again. It is named after the lookup key (the model file, its text and the
// tools) and names the library by its bare file name inside the cache; it
// ends with a checksum of its own text, so a damaged manifest, or one
// copied or edited to name another model's library, is not believed.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace sylva::build {

struct Manifest {
  std::string lookup_key;
  std::string library;  // a library's file name in the cache: KEY.so
  std::vector<std::string> warnings;
  struct Dependency {
    std::string stamp;  // file_stamp() when the model was built
    std::string path;   // absolute
  };
  std::vector<Dependency> dependencies;
};

// A cache key: 32 lowercase hex digits (support/content_hash.h).
bool is_cache_key(const std::string& text);
// KEY.so with KEY a cache key: a bare name, nothing outside the cache.
bool is_library_name(const std::string& name);

std::string manifest_text(const Manifest& manifest);

// Nothing if the text is not a whole, unaltered manifest written for
// `lookup_key` by this version of Sylva, or if it names anything but a
// library file of the cache.
std::optional<Manifest> read_manifest(const std::string& text, const std::string& lookup_key);

}  // namespace sylva::build
