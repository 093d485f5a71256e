#include "studio/model_session.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

#include "lang/literal_numbers.h"
#include "support/whole_file.h"

namespace sylva::studio {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The line `line` (from 1) of `path`, or "".
std::string source_line(const std::string& path, int line) {
  std::ifstream in(path);
  std::string text;
  for (int i = 0; i < line && std::getline(in, text); ++i) {
  }
  return line > 0 && in ? text : "";
}

void replace_all(std::string& text, const std::string& from, const std::string& to) {
  if (from.empty()) return;
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
}

}  // namespace

ModelSession::ModelSession(SessionOptions options) : options_(std::move(options)) {
  model_ = fs::absolute(options_.model).lexically_normal().string();
  folder_ = fs::path(model_).parent_path().string();
  for (io::InputFile& input : options_.inputs) input.path = fs::absolute(input.path).lexically_normal().string();
  char pattern[] = "/tmp/sylva-studio-XXXXXX";
  if (const char* dir = ::mkdtemp(pattern)) shadow_dir_ = dir;
  worker_ = std::make_unique<WorkerProcess>(options_.worker_command, folder_, options_.limits);
  std::vector<std::string> problems;
  parameters_ = find_parameters(folder_, model_, options_.inputs, problems);
  for (const std::string& problem : problems) messages_ += problem + "\n";
}

ModelSession::~ModelSession() {
  worker_.reset();
  std::error_code ec;
  if (!shadow_dir_.empty()) fs::remove_all(shadow_dir_, ec);
}

std::vector<std::string> ModelSession::watched_files() const {
  std::set<std::string> files = {model_};
  for (const io::InputFile& input : options_.inputs) files.insert(input.path);
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder_, ec))
    if (entry.is_regular_file(ec) && entry.path().filename().string().front() != '.')
      files.insert(entry.path().string());
  return {files.begin(), files.end()};
}

// ---- what the page does

void ModelSession::reload() {
  std::lock_guard lock(worker_mutex_);
  reload_locked();
}

void ModelSession::reload_if_changed() {
  std::lock_guard lock(worker_mutex_);
  if (files_signature() != opened_signature_) reload_locked();
}

std::string ModelSession::files_signature() const {
  std::string signature;
  std::error_code ec;
  for (const std::string& path : watched_files()) {
    const auto time = fs::last_write_time(path, ec).time_since_epoch().count();
    signature += path + ' ' + std::to_string(time) + ' ' + std::to_string(fs::file_size(path, ec)) + '\n';
  }
  return signature;
}

void ModelSession::reload_locked() {
  {
    std::lock_guard state(state_mutex_);
    // Panel files and the defines may have changed with the save; values
    // moved on sliders and not saved stay where they were.
    std::vector<std::string> problems;
    std::vector<Parameter> found = find_parameters(folder_, model_, options_.inputs, problems);
    for (Parameter& p : found)
      for (const Parameter& old : parameters_)
        if (old.id == p.id && old.message == p.message && old.target == p.target && old.modified() &&
            old.file_value == p.file_value)
          p.value = old.value;
    parameters_ = std::move(found);
  }
  const int at = status_.value("step", -1);
  open_and_derive(at);
}

void ModelSession::step(int count) {
  std::lock_guard lock(worker_mutex_);
  if (!open_) return;  // the error stays until a save, a reload or a rewind
  set_busy("deriving");
  if (call({{"op", "step"}, {"count", count}}, options_.time_limit_seconds)) fetch_scene();
  set_busy(nullptr);
}

void ModelSession::run_to(int step) {
  std::lock_guard lock(worker_mutex_);
  if (!open_) return;
  set_busy("deriving");
  if (call({{"op", "run"}, {"to", step}}, options_.time_limit_seconds)) fetch_scene();
  set_busy(nullptr);
}

void ModelSession::rewind() {
  std::lock_guard lock(worker_mutex_);
  if (!open_) return open_and_derive(0);
  if (call({{"op", "rewind"}}, options_.time_limit_seconds)) fetch_scene();
}

void ModelSession::set_parameter(const std::string& id, int value) {
  {
    std::lock_guard state(state_mutex_);
    auto p = std::find_if(parameters_.begin(), parameters_.end(), [&](const Parameter& x) { return x.id == id; });
    if (p == parameters_.end()) throw std::invalid_argument("no parameter '" + id + "'");
    p->value = p->kind == Parameter::Kind::Button ? (value != 0) : std::clamp(value, p->min, p->max);
  }
  std::lock_guard lock(worker_mutex_);
  open_and_derive(status_.value("step", -1));
}

void ModelSession::reset_parameters() {
  {
    std::lock_guard state(state_mutex_);
    for (Parameter& p : parameters_) p.value = p.file_value;
  }
  std::lock_guard lock(worker_mutex_);
  open_and_derive(status_.value("step", -1));
}

void ModelSession::save_parameters() {
  std::lock_guard state(state_mutex_);
  std::set<std::string> targets;
  for (const Parameter& p : parameters_)
    if (p.modified()) targets.insert(p.target);
  for (const std::string& target : targets) {
    WholeFile file = read_whole_file(target);
    if (!file) throw std::runtime_error("cannot read " + target);
    std::string text = std::move(file.bytes);
    for (const Parameter& p : parameters_)
      if (p.modified() && p.target == target) text = apply_parameter(text, p);
    if (write_file_atomically(target, text) != 0) throw std::runtime_error("cannot write " + target);
  }
  // The files say what the sliders say now; the save reloads the model.
  for (Parameter& p : parameters_) p.file_value = p.value;
  changed();
}

// ---- the worker

json ModelSession::open_request() {
  std::lock_guard state(state_mutex_);
  // A file with changed parameters is opened as a copy with the values
  // applied. The copy of the model includes from the copies' folder first,
  // then from the model's: a changed file the model includes (params.h) is
  // taken from its copy, which needs the model copied too.
  std::set<std::string> changed;
  for (const Parameter& p : parameters_)
    if (p.modified()) changed.insert(p.target);
  std::error_code ec;
  if (!shadow_dir_.empty()) {
    fs::remove_all(shadow_dir_, ec);
    fs::create_directories(shadow_dir_, ec);
  }
  auto copy_with_parameters = [&](const std::string& path) {
    WholeFile file = read_whole_file(path);
    if (shadow_dir_.empty() || !file) return path;
    std::string text = std::move(file.bytes);
    for (const Parameter& p : parameters_)
      if (p.modified() && p.target == path) text = apply_parameter(text, p);
    const std::string copy = (fs::path(shadow_dir_) / fs::path(path).filename()).string();
    return write_file_atomically(copy, text) == 0 ? copy : path;
  };
  json inputs = json::array();
  bool copy_model = changed.count(model_) > 0;
  for (const std::string& target : changed) {
    const bool input = std::any_of(options_.inputs.begin(), options_.inputs.end(),
                                   [&](const io::InputFile& i) { return i.path == target; });
    if (target != model_ && !input) {
      copy_with_parameters(target);
      copy_model = true;
    }
  }
  for (const io::InputFile& input : options_.inputs)
    inputs.push_back({{"path", changed.count(input.path) ? copy_with_parameters(input.path) : input.path},
                      {"kind", static_cast<int>(input.kind)},
                      {"slot", input.slot}});
  return {{"op", "open"},
          {"model", copy_model ? copy_with_parameters(model_) : model_},
          {"inputs", inputs},
          {"defines", options_.defines},
          {"include_dirs", std::vector<std::string>{folder_}},
          {"cache_dir", options_.cache_dir},
          {"compiler", options_.compiler},
          {"language", options_.language}};
}

void ModelSession::open_and_derive(int to_step) {
  open_ = false;
  opened_signature_ = files_signature();
  set_busy("compiling");
  WorkerMessage opened;
  if (call(open_request(), options_.compile_limit_seconds, &opened)) {
    open_ = true;
    {
      std::lock_guard state(state_mutex_);
      model_info_ = {{"animation", opened.json["animation"]}, {"views", opened.json["views"]}};
      error_ = nullptr;
    }
    // Back to where the page was; a fresh start shows the first frame.
    if (to_step < 0) to_step = opened.json["animation"].value("first", 0);
    set_busy("deriving");
    if (to_step == 0 || call({{"op", "run"}, {"to", to_step}}, options_.time_limit_seconds)) fetch_scene();
  }
  set_busy(nullptr);
}

bool ModelSession::call(const json& request, double timeout_seconds, WorkerMessage* answer) {
  WorkerMessage message;
  try {
    message = worker_->request(request, timeout_seconds);
  } catch (const WorkerFailure& failure) {
    open_ = false;
    set_error({{"kind", failure.kind()}, {"message", failure.what()}, {"step", status_.value("step", 0) + 1}});
    return false;
  }
  {
    std::lock_guard state(state_mutex_);
    messages_ += worker_->take_console();
    if (messages_.size() > 64 * 1024) messages_.erase(0, messages_.size() - 64 * 1024);
  }
  if (!message.json.value("ok", false)) {
    json error = located_error(message.json["error"]);
    if (error.value("kind", "") == "memory") worker_->stop();  // its state is not to be trusted
    const std::string op = request.value("op", "");
    if (op == "open") open_ = false;
    if (op == "step" || op == "run") error["step"] = status_.value("step", 0) + 1;
    set_error(error);
    return false;
  }
  take_status(message.json);
  if (answer) *answer = std::move(message);
  return true;
}

void ModelSession::take_status(const json& status) {
  std::lock_guard state(state_mutex_);
  for (const char* key : {"step", "derivation_length", "finished", "stopped", "modules", "step_ms", "warnings",
                          "primary_view"})
    if (status.contains(key)) status_[key] = status[key];
  error_ = nullptr;
  ++version_;
}

void ModelSession::fetch_scene() {
  WorkerMessage answer;
  if (!call({{"op", "scene"}, {"view", status_.value("primary_view", 0)}, {"instances_above", options_.instances_above}},
            options_.time_limit_seconds, &answer))
    return;
  std::lock_guard state(state_mutex_);
  const std::size_t glb_size = std::min(answer.payload.size(), answer.json.value("glb_size", answer.payload.size()));
  scene_ = std::make_shared<const Picture>(Picture{answer.payload.substr(0, glb_size), answer.payload.substr(glb_size)});
  view_ = answer.json["view"];
  ++scene_version_;
  ++version_;
}

WorkerMessage ModelSession::ask(const json& request) {
  std::lock_guard lock(worker_mutex_);
  if (!open_) throw std::runtime_error("the model is not running (see the error)");
  WorkerMessage answer;
  try {
    answer = worker_->request(request, options_.time_limit_seconds);
  } catch (const WorkerFailure& failure) {
    open_ = false;
    set_error({{"kind", failure.kind()}, {"message", failure.what()}});
    throw std::runtime_error(failure.what());
  }
  if (!answer.json.value("ok", false))
    throw std::runtime_error(answer.json["error"].value("message", "the request failed"));
  return answer;
}

// ---- errors and state

// The worker's error with the copies' names put back, and its place in the
// model's files (from the message when the error carries none: a compiler's
// "file:line:column: error:").
json ModelSession::located_error(const json& worker_error) const {
  std::string message = worker_error.value("message", "");
  std::string file = worker_error.value("file", "");
  int line = worker_error.value("line", 0), column = worker_error.value("column", 0);
  if (!shadow_dir_.empty()) {
    replace_all(message, shadow_dir_ + "/", folder_ + "/");
    replace_all(file, shadow_dir_ + "/", folder_ + "/");
  }
  if (line == 0) {
    static const std::regex located(R"(([^\s:]+):(\d+):(\d+):\s*(fatal )?error)");
    std::smatch m;
    if (std::regex_search(message, m, located)) {
      // Numbers past int leave the place unknown.
      const std::optional<int> line_number = lang::nonnegative_int(m[2].str());
      const std::optional<int> column_number = lang::nonnegative_int(m[3].str());
      if (line_number && column_number) {
        file = m[1];
        line = *line_number;
        column = *column_number;
      }
    }
  }
  const std::string absolute = file.empty() ? "" : fs::absolute(fs::path(folder_) / file).lexically_normal().string();
  replace_all(message, folder_ + "/", "");
  json error = {{"kind", worker_error.value("kind", "model")},
                {"message", message},
                {"file", file.empty() ? "" : fs::path(absolute).lexically_relative(folder_).string()},
                {"line", line},
                {"column", column},
                {"source_line", source_line(absolute, line)}};
  return error;
}

void ModelSession::set_error(json error) {
  std::lock_guard state(state_mutex_);
  error_ = std::move(error);
  ++version_;
}

void ModelSession::set_busy(const char* what) {
  std::lock_guard state(state_mutex_);
  busy_ = what ? what : "";
  ++version_;
}

void ModelSession::interrupt() { worker_->interrupt(); }

void ModelSession::changed() { ++version_; }

json ModelSession::state_json() const {
  std::lock_guard state(state_mutex_);
  json files = json::array();
  files.push_back(fs::path(model_).lexically_relative(folder_).string());
  for (const io::InputFile& input : options_.inputs) files.push_back(fs::path(input.path).lexically_relative(folder_));
  json params = json::array();
  bool modified = false;
  for (const Parameter& p : parameters_) {
    json item = {{"id", p.id},
                 {"panel", p.panel},
                 {"kind", p.kind == Parameter::Kind::Button ? "button" : "slider"},
                 {"name", p.name},
                 {"define", p.define},
                 {"value", p.value},
                 {"scale", p.scale},
                 {"target", fs::path(p.target).lexically_relative(folder_).string()},
                 {"modified", p.modified()}};
    if (p.kind == Parameter::Kind::Slider) {
      item["min"] = p.min;
      item["max"] = p.max;
      item["step"] = p.step;
    }
    params.push_back(item);
    modified |= p.modified();
  }
  json out = {{"version", version_},
              {"scene_version", scene_version_},
              {"model", files[0]},
              {"folder", folder_},
              {"files", files},
              {"busy", busy_.empty() ? json(nullptr) : json(busy_)},
              {"step", status_.value("step", 0)},
              {"derivation_length", status_.value("derivation_length", 0)},
              {"finished", status_.value("finished", false)},
              {"stopped", status_.value("stopped", false)},
              {"modules", status_.value("modules", 0)},
              {"step_ms", status_.value("step_ms", 0.0)},
              {"animation", model_info_.value("animation", json::object())},
              {"views", model_info_.value("views", json::array())},
              {"error", error_},
              {"warnings", status_.value("warnings", json::array())},
              {"messages", messages_},
              {"view", view_},
              {"instances", scene_ && !scene_->instances.empty()},
              {"params", params},
              {"params_modified", modified},
              {"formats", {"png", "svg", "pdf", "ps", "eps", "obj", "mtl", "ply", "glb", "string"}}};
  return out;
}

std::pair<std::shared_ptr<const ModelSession::Picture>, std::uint64_t> ModelSession::scene() const {
  std::lock_guard state(state_mutex_);
  return {scene_, scene_version_};
}

}  // namespace sylva::studio
