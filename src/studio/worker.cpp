#include "studio/worker.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <new>

#include "api/outputs.h"
#include "api/simulation.h"
#include "geometry/camera.h"
#include "io/output_file.h"
#include "io/string_text.h"
#include "support/diagnostic.h"
#include "support/whole_file.h"
#include "studio/scene_instances.h"
#include "studio/worker_protocol.h"

namespace sylva::studio {
namespace {

using nlohmann::json;

json vec(geometry::Vec3 v) { return json::array({v.x, v.y, v.z}); }
json rgb(geometry::Rgb c) { return json::array({c.r, c.g, c.b}); }

const char* render_mode_name(geometry::RenderMode mode) {
  switch (mode) {
    case geometry::RenderMode::Wireframe: return "wireframe";
    case geometry::RenderMode::Shaded: return "shaded";
    case geometry::RenderMode::Shadows: return "shadows";
    case geometry::RenderMode::Filled: break;
  }
  return "filled";
}

// The camera the PNG renderer would use for this scene, in terms a viewer
// with an ordinary perspective or orthographic camera can take.
json camera_json(const Simulation& simulation, const geometry::Scene& scene, int view_id, int width, int height) {
  const io::ViewFile& view = view_file_or_default(simulation);
  geometry::Box bounds = scene.bounds();
  if (bounds.empty()) bounds.add({0, 0, 0});
  const geometry::Camera camera(view.view(view_id), bounds, width, height);
  const geometry::Vec3 center = (bounds.min + bounds.max) * 0.5f;
  const float distance = std::max(1e-6f, dot(center - camera.eye(), camera.direction()));
  const auto& p = camera.projection();  // column-major: p[0], p[5] the scales, p[8], p[9], p[12], p[13] the offsets
  // The renderer may centre the picture off the line of sight (cpfg frames
  // the box from the view reference point, lpfg pans): an ordinary camera
  // gets there by moving sideways, by what the projection offsets amount to
  // at the distance looked at.
  const float right = camera.perspective() ? p[8] * distance / p[0] : -p[12] / p[0];
  const float up = camera.perspective() ? p[9] * distance / p[5] : -p[13] / p[5];
  const geometry::Vec3 shift = camera.right() * right + camera.up() * up;
  json out = {
      {"perspective", camera.perspective()},
      {"eye", vec(camera.eye() + shift)},
      {"target", vec(camera.eye() + camera.direction() * distance + shift)},
      {"up", vec(camera.up())},
      {"near", camera.near_plane()},
      {"far", camera.far_plane()},
      {"background", rgb(simulation.inputs().palette.background())},
      {"line_width", view.render.wireframe_line_width},
      {"render_mode", render_mode_name(view.render.mode)},
      {"stationary_lights", view.render.stationary_lights},
      {"bounds", {vec(bounds.min), vec(bounds.max)}},
  };
  if (camera.perspective()) out["fov"] = 2 * std::atan(1 / p[5]) * 180 / M_PI;
  else out["ortho_half_height"] = 1 / p[5];
  out["fov"] = out.value("fov", view.view(view_id).fov);
  // A flat model (all z equal) is shown orthographic, as a drawing.
  out["two_d"] = bounds.max.z - bounds.min.z <= 1e-6f * std::max(1.0f, bounds.max.x - bounds.min.x);
  json lights = json::array();
  for (const geometry::Light& light : view.lights_or_default()) {
    const char* kind = light.kind == geometry::Light::Kind::Directional ? "directional"
                       : light.kind == geometry::Light::Kind::Point     ? "point"
                                                                        : "spot";
    lights.push_back({{"kind", kind},
                      {"direction", vec(light.direction)},
                      {"position", vec(light.position)},
                      {"ambient", rgb(light.ambient)},
                      {"diffuse", rgb(light.diffuse)},
                      {"specular", rgb(light.specular)}});
  }
  out["lights"] = lights;
  return out;
}

std::string module_text(const ModuleTypes& types, const StringView& v, std::size_t at) {
  std::string text;
  io::append_module_text(v, at, types, text);
  return text;
}

class Worker {
 public:
  WorkerMessage answer(const json& request) {
    const std::string op = request.value("op", "");
    if (op == "open") return open(request);
    if (!simulation_) throw std::runtime_error("no model is open");
    if (op == "step") {
      const int count = std::max(1, request.value("count", 1));
      for (int i = 0; i < count && at_most_length(); ++i) simulation_->step();
      finish_at_length();
      return status();
    }
    if (op == "run") {
      int to = request.value("to", -1);
      if (to < 0 || to > simulation_->derivation_length()) to = simulation_->derivation_length();
      if (simulation_->step_number() > to) restart();
      while (simulation_->step_number() < to && simulation_->step()) {
      }
      finish_at_length();
      return status();
    }
    if (op == "rewind") {
      restart();
      return status();
    }
    if (op == "scene")
      return scene(request.value("view", 0), request.value("width", 800), request.value("height", 800),
                   request.value("instances_above", 20000));
    if (op == "string") return string_page(request);
    if (op == "counts") return counts();
    if (op == "module") return module(request.value("index", 0u));
    if (op == "export") return export_file(request);
    throw std::runtime_error("unknown request '" + op + "'");
  }

 private:
  WorkerMessage open(const json& request) {
    simulation_.reset();  // the old model's library goes before the new one loads
    SimulationOptions options;
    options.build.defines = request.value("defines", std::vector<std::string>{});
    options.build.include_dirs = request.value("include_dirs", std::vector<std::string>{});
    options.build.cache_dir = request.value("cache_dir", "");
    options.build.compiler = request.value("compiler", "");
    options.build.language = request.value("language", "");
    for (const json& input : request.value("inputs", json::array()))
      options.input_files.emplace_back(input.at("path").get<std::string>(),
                                       static_cast<io::InputKind>(input.at("kind").get<int>()),
                                       input.value("slot", 1));
    simulation_ = std::make_unique<Simulation>(request.at("model").get<std::string>(), options,
                                               [](const std::string& text) { std::fputs(text.c_str(), stderr); });
    simulation_->track_births(true);  // for the inspector's "made at step"
    simulation_->begin();
    WorkerMessage out = status();
    out.json["compiled_now"] = simulation_->compiled_now();
    const io::AnimationFile animation = simulation_->inputs().animation.value_or(io::AnimationFile{});
    const int length = simulation_->derivation_length();
    out.json["animation"] = {{"first", std::min(animation.first_frame, length)},
                             {"last", std::min(animation.last_frame.value_or(length), length)},
                             {"step", std::max(1, animation.step)},
                             {"swap_interval_ms", animation.swap_interval * 10},
                             {"double_buffer", animation.double_buffer}};
    json views = json::array();
    views.push_back({{"id", 0}, {"name", ""}});
    if (simulation_->inputs().view)
      for (std::size_t i = 0; i < simulation_->inputs().view->windows.size(); ++i)
        views.push_back({{"id", i + 1}, {"name", simulation_->inputs().view->windows[i].name}});
    out.json["views"] = views;
    return out;
  }

  bool at_most_length() const { return simulation_->step_number() < simulation_->derivation_length(); }
  // End runs when the derivation length is reached, as in a whole run.
  void finish_at_length() {
    if (!at_most_length() || simulation_->stopped()) simulation_->finish();
  }
  void restart() {
    simulation_->rewind();
    simulation_->begin();
  }

  WorkerMessage status() const {
    const Simulation& s = *simulation_;
    json out = {{"ok", true},
                {"step", s.step_number()},
                {"derivation_length", s.derivation_length()},
                {"finished", s.finished()},
                {"stopped", s.stopped()},
                {"modules", s.string().count_modules(s.types())},
                {"step_ms", s.step_seconds().empty() ? 0.0 : s.step_seconds().back() * 1000},
                {"warnings", s.warnings()},
                {"primary_view", s.primary_view()}};
    return {out, {}};
  }

  // The picture: binary glTF, then the instances of a big scene's spheres
  // and cylinders (scene_instances.h), "glb_size" telling where one ends.
  WorkerMessage scene(int view, int width, int height, int instances_above) {
    geometry::Scene scene = simulation_->scene(view);
    WorkerMessage out = status();
    out.json["view"] = camera_json(*simulation_, scene, view, width, height);
    const std::string instances =
        take_instances(scene, simulation_->inputs().palette, view_file_or_default(*simulation_).tessellation_options(),
                       static_cast<std::size_t>(std::max(0, instances_above)));
    out.payload = scene_glb(scene, *simulation_);
    out.json["glb_size"] = out.payload.size();
    out.payload += instances;
    return out;
  }

  WorkerMessage string_page(const json& request) {
    const ModuleTypes& types = simulation_->types();
    const StringView v = simulation_->string().view(types);
    const std::size_t offset = request.value("offset", 0u);
    const std::size_t limit = std::min<std::size_t>(request.value("limit", 1000u), 20000);
    const std::string search = request.value("search", "");
    json items = json::array(), matches = json::array();
    std::size_t index = 0, match_count = 0;
    for (std::size_t at = v.begin; at < v.end; at = v.next(at), ++index) {
      const bool in_page = index >= offset && index < offset + limit;
      if (!in_page && search.empty()) {
        if (index >= offset + limit) break;
        continue;
      }
      const std::string text = module_text(types, v, at);
      if (in_page) items.push_back({{"index", index}, {"text", text}});
      if (!search.empty() && text.find(search) != std::string::npos) {
        if (match_count < 1000) matches.push_back(index);
        ++match_count;
      }
    }
    json out = {{"ok", true},
                {"modules", simulation_->string().count_modules(types)},
                {"offset", offset},
                {"items", items}};
    if (!search.empty()) {
      out["matches"] = matches;
      out["match_count"] = match_count;
    }
    return {out, {}};
  }

  WorkerMessage counts() const {
    const ModuleTypes& types = simulation_->types();
    const StringView v = simulation_->string().view(types);
    std::map<ModuleId, std::size_t> by_id;
    for (std::size_t at = v.begin; at < v.end; at = v.next(at)) ++by_id[v.id_at(at)];
    std::vector<std::pair<ModuleId, std::size_t>> sorted(by_id.begin(), by_id.end());
    std::stable_sort(sorted.begin(), sorted.end(), [](auto& a, auto& b) { return a.second > b.second; });
    json list = json::array();
    for (auto [id, count] : sorted) list.push_back({{"name", types.name(id)}, {"count", count}});
    return {{{"ok", true}, {"counts", list}}, {}};
  }

  // Module `index` of the string: the index the glTF provenance gives for
  // what it drew (through the view's interpretation rules, if any).
  WorkerMessage module(std::size_t index) {
    const ModuleTypes& types = simulation_->types();
    const StringView v = simulation_->string().view(types);
    std::size_t i = 0, at = v.begin;
    for (; at < v.end && i < index; at = v.next(at)) ++i;
    if (at >= v.end) throw std::runtime_error("no module at index " + std::to_string(index));
    const ModuleId id = v.id_at(at);
    std::string params;
    if (types[id].param_size > 0) types.format_params(id, module_params(v.data, at), params);
    // As the string writes them (floats with the digits that read back),
    // split at the commas between parameters, not those inside a struct's
    // braces or a vector's parentheses.
    json parameters = json::array();
    int depth = 0;
    std::string parameter;
    for (char c : params) {
      depth += (c == '{' || c == '(') - (c == '}' || c == ')');
      if (c == ',' && depth == 0) {
        parameters.push_back(std::exchange(parameter, {}));
      } else {
        parameter += c;
      }
    }
    if (!params.empty()) parameters.push_back(parameter);
    const std::vector<std::uint32_t>& births = simulation_->birth_steps();
    return {{{"ok", true},
             {"index", index},
             {"name", types.name(id)},
             {"text", module_text(types, v, at)},
             {"parameters", parameters},
             {"step", index < births.size() ? json(births[index]) : json(nullptr)},
             {"string_index", index}},
            {}};
  }

  WorkerMessage export_file(const json& request) {
    const std::string format = request.value("format", "png");
    const int view = request.value("view", simulation_->primary_view());
    WorkerMessage out = status();
    if (format == "string") {
      out.payload = simulation_->string_text();
      return out;
    }
    // The writers write whole files (an OBJ with its MTL beside it): write
    // into a folder of this worker's own (made new and private, so nothing
    // another user put there is written through) and hand the bytes back.
    std::string made = (std::filesystem::temp_directory_path() / "sylva-studio-export-XXXXXX").string();
    if (!::mkdtemp(made.data()))
      throw std::runtime_error(std::string("cannot make a folder for the export: ") + std::strerror(errno));
    const std::filesystem::path dir = made;
    const std::string file_format = format == "mtl" ? "obj" : format;
    const std::filesystem::path path = dir / ("model." + file_format);
    check_output_path(path.string());
    OutputOptions size;
    size.width = std::clamp(request.value("width", 800), 1, 8192);
    size.height = std::clamp(request.value("height", 800), 1, 8192);
    write_output(path.string(), simulation_->scene(view), *simulation_, size, view);
    WholeFile file = read_whole_file((dir / ("model." + format)).string());
    std::filesystem::remove_all(dir);
    if (!file) throw std::runtime_error("the " + format + " file was not written");
    out.payload = std::move(file.bytes);
    return out;
  }

  std::unique_ptr<Simulation> simulation_;
};

json error_json(const std::string& message, const SourceLocation& where = {}) {
  return {{"ok", false},
          {"error", {{"message", message}, {"file", where.file}, {"line", where.line}, {"column", where.column}}}};
}

}  // namespace

int run_worker(int requests, int answers) {
  Worker worker;
  WorkerMessage request;
  while (read_message(requests, request)) {
    WorkerMessage answer;
    try {
      answer = worker.answer(request.json);
    } catch (const ModelError& e) {
      answer.json = error_json(e.what(), e.where());
    } catch (const std::bad_alloc&) {
      answer.json = error_json("out of memory: the model needs more than the studio's memory limit");
      answer.json["error"]["kind"] = "memory";
    } catch (const std::exception& e) {
      answer.json = error_json(e.what());
    }
    std::fflush(stdout);
    std::fflush(stderr);
    if (!write_message(answers, answer)) break;
  }
  return 0;
}

}  // namespace sylva::studio
