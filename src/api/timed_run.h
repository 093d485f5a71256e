// A differential L-system run in time rather than in steps
// (`sylva run --time T --dt DT`, docs/continuous-time.md): the state sampled
// at t = 0, dt, 2dt ... T, whatever the times of the events; at each sample
// the recorded parameters and the frames asked for.
#pragma once

#include <string>
#include <vector>

#include "api/simulation.h"

namespace sylva {

struct TimedRunOptions {
  double end_time = 0;
  double dt = 0;  // 0: the end alone
  // Modules, by name, whose parameters are written at every sample.
  std::vector<std::string> record;
  std::string record_path;  // CSV: t,index,module,parameter,value ("-": standard output)
  std::string plot_path;    // PNG of the recorded parameters against time
  std::string frames_dir;   // frame-NNNN.EXT, N the sample
  std::vector<std::string> frame_formats = {"png"};  // as write_frame (api/outputs.h) takes them
};

// 0, dt, 2dt ... and `end` (once, even where dt does not divide it); k dt
// computed as a product, not a running sum, so that halving dt gives the
// same times at every other sample.
std::vector<double> sample_times(double end, double dt);

// Runs `simulation` from t = 0 (rewinding it) to options.end_time, writing
// what the options ask for. Throws ModelError for a model without derivative
// or event rules, an unknown module to record, or a run that fails.
void run_in_time(Simulation& simulation, const TimedRunOptions& options, const OutputOptions& output);

}  // namespace sylva
