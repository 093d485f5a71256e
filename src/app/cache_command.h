// `sylva cache`: where compiled models are kept and how much room they take;
// `sylva cache prune` and `sylva cache clear` remove them.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace sylva::app {

struct CacheOptions {
  std::string cache_dir;  // empty: build::default_cache_dir()
  std::string max_size;   // prune's limit; empty: the one runs prune to
  CLI::App* prune = nullptr;
  CLI::App* clear = nullptr;
};

CLI::App* add_cache_command(CLI::App& app, CacheOptions& options);
int run_cache_command(const CacheOptions& options);

}  // namespace sylva::app
