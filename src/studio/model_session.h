// One model in the studio: its files, its parameters, the worker that runs
// it, and what the page sees (state_json(), the current picture). Every
// change goes through here: the page's Step/Run/Rewind, a slider, a save of
// any file of the model (reload()). Calls that need the worker are taken one
// at a time; state_json() and scene() never wait for them.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "inputs/input_files.h"
#include "studio/parameters.h"
#include "studio/worker_process.h"

namespace sylva::studio {

struct SessionOptions {
  std::string model;                    // the model file
  std::vector<io::InputFile> inputs;    // as sylva run takes them
  std::string cache_dir, compiler, language;
  std::vector<std::string> defines;     // -D given on the command line
  std::vector<std::string> worker_command;  // runs run_worker(3, 4)
  WorkerLimits limits;
  double time_limit_seconds = 60;       // per request that derives
  double compile_limit_seconds = 600;   // opening a model: translating and compiling
  int instances_above = 20000;          // scene_instances.h
};

class ModelSession {
 public:
  explicit ModelSession(SessionOptions options);
  ~ModelSession();

  // The model's folder: what the page may read (served_path.h).
  const std::string& folder() const { return folder_; }
  const std::string& model() const { return model_; }  // absolute
  // The files whose change reloads the model: the model, its inputs, the
  // panel files and whatever else the model's folder holds.
  std::vector<std::string> watched_files() const;

  // ---- what the page does
  // Opens the model again (after a save) and derives it back to the step it
  // was at. A model that fails keeps the last good picture.
  void reload();
  // A reload, unless every watched file is as it was when the model was
  // last opened (a save the session made itself has been taken already).
  void reload_if_changed();
  void step(int count);
  void run_to(int step);  // -1: the derivation length
  void rewind();
  // Parameters: a value is applied to a copy of its file; save writes the
  // changed values into the files themselves, as awkped does.
  void set_parameter(const std::string& id, int value);
  void reset_parameters();
  void save_parameters();

  // Stops the model's worker now, whatever it is doing (the program is
  // ending); a call waiting for it returns with an error.
  void interrupt();

  nlohmann::json state_json() const;
  // The current picture and its version; empty before the first.
  struct Picture {
    std::string glb;        // binary glTF
    std::string instances;  // scene_instances.h; empty for a small scene
  };
  std::pair<std::shared_ptr<const Picture>, std::uint64_t> scene() const;
  // Pass-through requests (worker.h): string, counts, module, export. Throws
  // std::runtime_error with the worker's message when it fails.
  WorkerMessage ask(const nlohmann::json& request);

 private:
  void reload_locked();
  // The watched files' modification times and sizes.
  std::string files_signature() const;
  void open_and_derive(int to_step);
  // Runs `request` and takes its status; on failure sets the error. Returns
  // whether it succeeded.
  bool call(const nlohmann::json& request, double timeout_seconds, WorkerMessage* answer = nullptr);
  void take_status(const nlohmann::json& status);
  void fetch_scene();
  void set_error(nlohmann::json error);
  nlohmann::json located_error(const nlohmann::json& worker_error) const;
  void set_busy(const char* what);
  // The model and input files to open: copies where a parameter differs from
  // the file.
  nlohmann::json open_request();
  void changed();

  SessionOptions options_;
  std::string folder_, model_;
  std::string shadow_dir_;  // copies of files with changed parameters

  std::mutex worker_mutex_;  // one request at a time
  std::unique_ptr<WorkerProcess> worker_;
  bool open_ = false;
  std::string opened_signature_;  // files_signature() when the model was last opened

  mutable std::mutex state_mutex_;
  std::vector<Parameter> parameters_;
  nlohmann::json status_ = nlohmann::json::object();  // the worker's last status
  nlohmann::json model_info_ = nlohmann::json::object();  // animation, views
  nlohmann::json view_ = nullptr;                     // the picture's camera
  nlohmann::json error_ = nullptr;
  std::string busy_;
  std::string messages_;
  std::uint64_t version_ = 1, scene_version_ = 0;
  std::shared_ptr<const Picture> scene_;
};

}  // namespace sylva::studio
