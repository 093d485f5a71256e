#include "api/timed_run.h"

#include <charconv>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <utility>

#include "api/outputs.h"
#include "api/series_plot.h"
#include "io/output_file.h"
#include "support/diagnostic.h"

namespace sylva {
namespace {

void append_number(std::string& out, double v) {
  char text[32];
  out.append(text, std::to_chars(text, text + sizeof text, v).ptr);
}

// The recorded modules' parameters at each sample, as CSV rows and, when a
// plot is asked for, as its series.
class ParameterRecorder {
 public:
  ParameterRecorder(const Simulation& simulation, const std::vector<std::string>& names, bool keep_series)
      : keep_series_(keep_series) {
    for (const std::string& name : names) {
      const std::optional<ModuleId> id = simulation.types().find(name);
      if (!id)
        throw ModelError(SourceLocation{simulation.model_path(), 0, 0},
                         "--record " + name + ": the model declares no module '" + name + "'");
      ids_.insert(*id);
    }
  }
  bool empty() const { return ids_.empty(); }

  // Rows for the current string at time t.
  void sample(double t, const Simulation& simulation, std::string& rows) {
    const ModuleTypes& types = simulation.types();
    const StringView view = simulation.string().view(types);
    std::size_t index = 0;
    for (std::size_t pos = view.begin; pos < view.end; pos = view.next(pos), ++index) {
      const ModuleId id = view.id_at(pos);
      if (!ids_.count(id)) continue;
      const std::vector<double> values = types.numbers(id, module_params(view.data, pos));
      for (std::size_t k = 0; k < values.size(); ++k) {
        append_number(rows, t);
        rows += ',' + std::to_string(index) + ',' + types.name(id) + ",p" + std::to_string(k + 1) + ',';
        append_number(rows, values[k]);
        rows += '\n';
        if (!keep_series_) continue;
        PlotSeries& series = series_[{types.name(id), k}];
        series.t.push_back(t);
        series.value.push_back(values[k]);
      }
    }
  }

  std::vector<PlotSeries> series() const {
    std::vector<PlotSeries> all;
    for (const auto& [key, s] : series_) {
      all.push_back(s);
      all.back().name = key.first + " p" + std::to_string(key.second + 1);
    }
    return all;
  }

 private:
  std::set<ModuleId> ids_;
  bool keep_series_;
  std::map<std::pair<std::string, std::size_t>, PlotSeries> series_;  // by module name and parameter
};

// Frames share one camera: the view file's, framing every sample's plant
// unless the view file gives a box (a first run finds it).
geometry::ViewParameters frame_camera(Simulation& simulation, const std::vector<double>& times) {
  simulation.rewind();
  simulation.begin();
  geometry::ViewParameters camera = view_file_or_default(simulation).view(simulation.primary_view());
  if (camera.box) return camera;
  geometry::Box box;
  for (double t : times) {
    simulation.advance_to(t);
    box.add(simulation.scene().bounds());
  }
  if (!box.empty()) camera.box = box;
  return camera;
}

}  // namespace

std::vector<double> sample_times(double end, double dt) {
  std::vector<double> times;
  if (dt > 0) {
    // A sample within a millionth of dt of the end is the end.
    for (long k = 0;; ++k) {
      const double t = static_cast<double>(k) * dt;
      if (t > end - 1e-6 * dt) break;
      times.push_back(t);
    }
  } else {
    times.push_back(0);
  }
  if (times.back() < end) times.push_back(end);
  return times;
}

void run_in_time(Simulation& simulation, const TimedRunOptions& options, const OutputOptions& output) {
  if (!simulation.continuous())
    throw ModelError(SourceLocation{simulation.model_path(), 0, 0},
                     "--time needs a model with derivative or event rules (derivatives: / events:); "
                     "run a discrete model with --steps");
  const std::vector<double> times = sample_times(options.end_time, options.dt);
  ParameterRecorder recorder(simulation, options.record, !options.plot_path.empty());
  std::optional<geometry::ViewParameters> camera;
  if (!options.frames_dir.empty()) {
    check_frame_formats(options.frame_formats);
    std::filesystem::create_directories(options.frames_dir);
    camera = frame_camera(simulation, times);
  }
  auto run = [&](const ContentSink* sink) {
    simulation.rewind();
    std::string rows;
    if (sink) (*sink)("t,index,module,parameter,value\n");
    for (std::size_t k = 0; k < times.size(); ++k) {
      simulation.advance_to(times[k]);
      if (!recorder.empty()) {
        rows.clear();
        recorder.sample(times[k], simulation, rows);
        if (sink) (*sink)(rows);
      }
      if (camera)
        write_frame(options.frames_dir, static_cast<int>(k), options.frame_formats, simulation, *camera, output);
    }
  };
  if (options.record_path.empty()) run(nullptr);
  else io::write_output_file(options.record_path, [&](const ContentSink& sink) { run(&sink); });
  if (!options.plot_path.empty()) write_series_plot(options.plot_path, recorder.series(), simulation.model_path());
}

}  // namespace sylva
