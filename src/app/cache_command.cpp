#include "app/cache_command.h"

#include <cstdio>

#include "build/cache_maintenance.h"
#include "build/model_builder.h"
#include "build/model_cache.h"

namespace sylva::app {

CLI::App* add_cache_command(CLI::App& app, CacheOptions& options) {
  CLI::App* cache = app.add_subcommand(
      "cache", "Show the cache of compiled models: its folder, size and number of models (prune, clear)");
  cache->add_option("--cache-dir", options.cache_dir,
                    "The cache's folder (default: $SYLVA_CACHE_DIR or ~/.cache/sylva)")
      ->type_name("DIR");
  options.prune = cache->add_subcommand(
      "prune", "Remove the least recently used compiled models until the cache is no larger than the limit");
  options.prune
      ->add_option("--max-size", options.max_size,
                   "The limit, e.g. 500M or 2G (default: $SYLVA_CACHE_MAX_SIZE or 1G, the limit every run "
                   "prunes the cache to after compiling)")
      ->type_name("SIZE")
      ->check(CLI::Validator(
          [](std::string& value) -> std::string {
            try {
              build::parse_size(value);
              return {};
            } catch (const std::invalid_argument& e) {
              return e.what();
            }
          },
          "SIZE"));
  options.clear = cache->add_subcommand("clear", "Remove every compiled model");
  // `sylva cache prune --cache-dir DIR` as well as `sylva cache --cache-dir DIR prune`.
  options.prune->fallthrough();
  options.clear->fallthrough();
  cache->require_subcommand(0, 1);
  return cache;
}

int run_cache_command(const CacheOptions& options) {
  const build::ModelCache cache(options.cache_dir.empty() ? build::default_cache_dir() : options.cache_dir);
  if (*options.prune || *options.clear) {
    const build::PruneResult result =
        *options.clear ? build::clear_cache(cache)
                       : build::prune_cache(cache, options.max_size.empty() ? build::cache_size_limit()
                                                                           : build::parse_size(options.max_size));
    std::printf("removed %d compiled model%s (%s); %s left\n", result.models_removed,
                result.models_removed == 1 ? "" : "s", build::format_size(result.bytes_removed).c_str(),
                build::format_size(result.left.bytes).c_str());
    return 0;
  }
  const build::CacheUsage usage = build::cache_usage(cache);
  std::printf("folder: %s\nsize:   %s (runs prune it to %s)\nmodels: %d\n", cache.dir().c_str(),
              build::format_size(usage.bytes).c_str(), build::format_size(build::cache_size_limit()).c_str(),
              usage.models);
  return 0;
}

}  // namespace sylva::app
