// Keeping the model cache to a size: what it holds, and removing the least
// recently used compiled models past a limit (`sylva cache`, and after each
// compile).
#pragma once

#include <cstdint>
#include <string>

#include "build/model_cache.h"

namespace sylva::build {

struct CacheUsage {
  std::uint64_t bytes = 0;  // Sylva's files in the folder
  int models = 0;           // compiled libraries
};

struct PruneResult {
  int models_removed = 0;
  std::uint64_t bytes_removed = 0;
  CacheUsage left;
};

CacheUsage cache_usage(const ModelCache& cache);

// Removes the least recently used libraries (with their manifests) until the
// cache holds at most `max_bytes`, sparing `keep` (a key just built) and any
// library being compiled, and the leftovers of runs that were killed.
PruneResult prune_cache(const ModelCache& cache, std::uint64_t max_bytes, const std::string& keep = {});

// The same, automatically after a compile of `keep` that wrote `manifest`:
// adds their files to the size last counted, and counts and prunes only if
// that is past the limit.
void prune_cache_if_full(const ModelCache& cache, const std::string& keep, const std::string& manifest);

// Every compiled model but those being compiled now. Files in the folder
// that are not Sylva's are left alone.
PruneResult clear_cache(const ModelCache& cache);

// $SYLVA_CACHE_MAX_SIZE, or 1 GiB.
std::uint64_t cache_size_limit();

// "500M", "2G", "1.5GiB", "4096": binary multiples. Throws
// std::invalid_argument for anything else.
std::uint64_t parse_size(const std::string& text);
std::string format_size(std::uint64_t bytes);

}  // namespace sylva::build
