// `sylva studio`: the model in the browser (docs/studio.md), and the worker
// processes its models run in (`sylva studio-worker`, started by the studio
// itself, never by hand).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "build/model_builder.h"
#include "inputs/input_files.h"

namespace sylva::app {

struct StudioOptions {
  std::vector<std::string> files;  // only for the help text: read as `run` reads them
  std::string model;
  std::vector<io::InputFile> inputs;
  int port = 0;
  std::string listen;  // an address other than loopback: a token is required
  double time_limit_seconds = 60;
  int memory_limit_mb = 8192;
  int instances_above = 20000;
};

CLI::App* add_studio_command(CLI::App& app, StudioOptions& options);
int run_studio(const StudioOptions& options, const build::BuildOptions& build);

// The name of the hidden command that runs a worker.
inline constexpr const char* kStudioWorkerCommand = "studio-worker";
int run_studio_worker();

}  // namespace sylva::app
