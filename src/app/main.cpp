// sylva — the command line over the engine's public API.
#include <CLI/CLI.hpp>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <new>
#include <optional>

#include "api/outputs.h"
#include "api/reference_command_line.h"
#include "api/simulation.h"
#include "api/timed_run.h"
#include "api/verify_string.h"
#include "app/cache_command.h"
#include "app/experiment_command.h"
#include "app/reproduce_command.h"  // --reproduce, and the record every output carries
#include "app/run_watchdog.h"
#include "app/studio_command.h"
#include "build/model_builder.h"
#include "gpu/gpu_run.h"  // --gpu
#include "io/output_file.h"
#include "io/string_reader.h"
#include "support/diagnostic.h"
#include "support/interruption.h"

namespace {

struct CommonOptions {
  sylva::build::BuildOptions build;
};

void add_build_options(CLI::App& command, CommonOptions& o) {
  command.add_option("--cache-dir", o.build.cache_dir,
                     "Where compiled models are kept (default: $SYLVA_CACHE_DIR or ~/.cache/sylva)")
      ->type_name("DIR");
  command.add_option("--compiler", o.build.compiler, "C++ compiler for models (default: $SYLVA_CXX, $CXX or g++)")
      ->type_name("PROGRAM");
  command.add_option("-D,--define", o.build.defines, "Preprocessor definition NAME[=VALUE] for the model")
      ->type_name("NAME[=VALUE]");
  command.add_flag("-v,--verbose", o.build.verbose, "Say when a model is compiled");
  command.add_option("--lang", o.build.language, "The model's language (default: recognised from the file)")
      ->check(CLI::IsMember({"cpfg", "lc", "auto"}))
      ->type_name("cpfg|lc");
}

void add_limit_options(CLI::App& run, sylva::RunLimits& limits) {
  const sylva::RunLimits defaults = sylva::default_run_limits();
  // Before --max-modules: options are applied in the order they are added,
  // and a memory limit given alone sets the module limit it implies.
  run.add_option_function<std::string>(
         "--max-memory",
         [&limits](const std::string& text) {
           const std::optional<std::size_t> bytes = sylva::parse_byte_size(text);
           if (!bytes) throw CLI::ValidationError("--max-memory", "expected a size such as 4G or 512M, not '" + text + "'");
           limits.max_memory = *bytes;
           limits.max_drawn_modules = sylva::max_modules_for_memory(*bytes);
         },
         "Stop a run whose strings would take more than SIZE (bytes, or with K, M, G; default half the "
         "physical memory, " + std::to_string(defaults.max_memory >> 20) + "M; 0: none), or that would draw "
         "more modules than a module per 64 bytes of it (" + std::to_string(defaults.max_drawn_modules) + ")")
      ->type_name("SIZE");
  run.add_option("--max-modules", limits.max_modules,
                 "Stop a run whose string grows past N modules (default: none, the memory limit bounds it)")
      ->type_name("N");
  run.add_option("--timeout", limits.timeout_seconds,
                 "Stop a run (derivation, interpretation and outputs) that takes more than SECONDS (default: none)")
      ->check(CLI::NonNegativeNumber)
      ->type_name("SECONDS");
}

struct RunOptions {
  std::vector<std::string> files;  // only for the help text: the files are read by read_reference_command_line
  std::string model;
  std::vector<sylva::io::InputFile> inputs;
  bool interpreted_string = false;  // cpfg's -h
  bool compile_only = false;        // lpfg's -c
  int steps = -1;
  std::string string_path, interpreted_path, turtle_path, frames_dir, axiom_from;
  std::vector<std::string> frame_formats = {"png"};
  std::vector<std::string> outputs;
  sylva::OutputOptions output;
  sylva::EnvironmentOptions environment;
  bool cpfg_window_seeding = false;
  bool huge_pages = false;
  int threads = 0;  // 0: one per core
  bool explain_parallel = false;
  bool keyed_random = false;
  std::optional<long> seed;
  bool gpu = false;  // --gpu: point-subdivision L-systems derived on the GPU (gpu/gpu_run.h)
  sylva::RunLimits limits = sylva::default_run_limits();
  // Continuous time (docs/continuous-time.md): --time switches the run to it.
  sylva::TimedRunOptions timed;
  std::string integrator = "rk45";
  sylva::continuous::ContinuousSettings continuous;
};

// The options of a run in continuous time.
void add_time_options(CLI::App& run, RunOptions& r) {
  const sylva::continuous::ContinuousSettings defaults;
  run.add_option("--time", r.timed.end_time,
                 "Run a differential L-system in continuous time up to T (instead of steps); the outputs show "
                 "the state at T")
      ->check(CLI::PositiveNumber)
      ->type_name("T");
  run.add_option("--dt", r.timed.dt,
                 "With --time: sample the state at 0, DT, 2 DT ... for --record and --frames (independent of "
                 "the events' times)")
      ->check(CLI::PositiveNumber)
      ->type_name("DT");
  run.add_option("--integrator", r.integrator,
                 "rk4 (fixed step), rk45 (adaptive Dormand-Prince, the default) or cvode (stiff systems)")
      ->check(CLI::IsMember({"rk4", "rk45", "cvode"}))
      ->type_name("METHOD");
  run.add_option("--step", r.continuous.integrator.step,
                 "rk4's step; the first step the adaptive methods try (default " +
                     std::to_string(defaults.integrator.step) + ")")
      ->check(CLI::PositiveNumber);
  run.add_option("--max-step", r.continuous.integrator.max_step,
                 "The longest step rk45 and cvode may take (default: no limit); events are looked for at the "
                 "ends of steps, so a condition true only briefly needs steps shorter than that")
      ->check(CLI::PositiveNumber);
  run.add_option("--tolerance", r.continuous.integrator.relative_tolerance,
                 "Relative error allowed per step of rk45 and cvode (default 1e-6)")
      ->check(CLI::PositiveNumber);
  run.add_option("--event-tolerance", r.continuous.event_tolerance,
                 "Events are placed within this much time after they happen (default 1e-9)")
      ->check(CLI::PositiveNumber);
  run.add_option("--record", r.timed.record,
                 "With --time: record the parameters of the modules named NAME at every sample (repeatable)")
      ->type_name("NAME");
  run.add_option("--record-file", r.timed.record_path,
                 "Where --record writes its CSV (t,index,module,parameter,value; default standard output)")
      ->type_name("FILE");
  run.add_option("--plot", r.timed.plot_path, "With --record: a PNG of the recorded parameters against time")
      ->type_name("FILE");
}

// VerifyString: (LPFG manual 10.4). On a mismatch lpfg's two files of module
// names, Verify_MODEL_expected.txt and Verify_MODEL_actual.txt, are written in
// the current folder, and the run fails.
bool check_verify_string(sylva::Simulation& simulation, const std::string& model) {
  const sylva::StringVerification v = sylva::verify_string(simulation);
  if (v.outcome == sylva::StringVerification::kNoStatement) return true;
  if (v.outcome == sylva::StringVerification::kSuccess) {
    std::fprintf(stderr, "Verify: Success\n");
    return true;
  }
  const std::string name = std::filesystem::path(model).filename().string();
  const std::string expected = "Verify_" + name + "_expected.txt", actual = "Verify_" + name + "_actual.txt";
  sylva::io::write_output_file(expected, v.expected);
  sylva::io::write_output_file(actual, v.actual);
  std::fprintf(stderr, "Verify: Fail\n%s: error: the derived string is not the one VerifyString: gives: %s (see %s and %s)\n",
               model.c_str(), v.difference.c_str(), expected.c_str(), actual.c_str());
  return false;
}

// `--string none`: no string at all, not even on standard output (a run
// wanted for its time, its other outputs or its VerifyString check).
constexpr const char* kNoString = "none";

int run_command(const RunOptions& r, const CommonOptions& o) {
  // Bad output names fail before any work is done.
  for (const std::string& path : r.outputs) sylva::check_output_path(path);
  if (r.model.empty()) throw std::invalid_argument("no model: give the L-system file (.l) among the files");
  if (r.compile_only) {
    sylva::build::build_model(r.model, o.build);
    return 0;
  }
  sylva::use_huge_pages(r.huge_pages);
  sylva::SimulationOptions options{o.build, r.inputs};
  options.environment = r.environment;
  options.cpfg_window_seeding = r.cpfg_window_seeding;
  options.threads = r.threads;
  options.keyed_random = r.keyed_random;
  options.seed = r.seed;
  options.limits = r.limits;
  // --gpu (gpu/gpu_run.h): the final string only, of a point-subdivision L-system.
  if (r.gpu) {
    const bool string_only = r.outputs.empty() && r.interpreted_path.empty() && r.turtle_path.empty() &&
                             r.frames_dir.empty() && r.axiom_from.empty() && !r.interpreted_string &&
                             r.timed.end_time == 0 && r.string_path != kNoString;
    if (!string_only)
      std::fprintf(stderr, "sylva: --gpu writes the final string only; deriving on the CPU\n");
    else if (sylva::gpu::run_on_gpu(r.model, options, r.steps, r.string_path.empty() ? "-" : r.string_path))
      return 0;
  }
  sylva::Simulation simulation(r.model, options);
  if (r.explain_parallel) std::fputs(simulation.parallel_explanation().c_str(), stderr);
  std::optional<sylva::app::RunWatchdog> watchdog;
  if (r.limits.timeout_seconds > 0)
    watchdog.emplace(r.limits.timeout_seconds, [&simulation] { return simulation.budget().where(); });
  simulation.set_output_options(r.output);
  if (!r.axiom_from.empty())
    simulation.start_from(sylva::io::read_string_file(r.axiom_from, simulation.types()));
  sylva::TimedRunOptions timed = r.timed;
  // The animation file's times, where the command line gives none.
  if (const auto& animation = simulation.inputs().animation; animation && simulation.continuous()) {
    if (timed.end_time == 0 && animation->end_time) timed.end_time = *animation->end_time;
    if (timed.dt == 0 && animation->time_step) timed.dt = *animation->time_step;
  }
  const bool in_time = timed.end_time > 0;
  // Every output records what made it (api/provenance.h); destroyed before the simulation.
  std::optional<sylva::ProvenanceScope> provenance;
  if (!in_time) provenance.emplace(simulation, sylva::app::run_record(simulation, options, r.axiom_from, nullptr));
  if (in_time) {
    timed.frames_dir = r.frames_dir;
    timed.frame_formats = r.frame_formats;
    if (!timed.record.empty() && timed.record_path.empty()) timed.record_path = "-";
    sylva::continuous::ContinuousSettings settings = r.continuous;
    settings.integrator.method = sylva::continuous::method_named(r.integrator);
    settings.end_time = timed.end_time;
    simulation.set_continuous_settings(settings);
    provenance.emplace(simulation, sylva::app::run_record(simulation, options, r.axiom_from, &settings));
    sylva::run_in_time(simulation, timed, r.output);
    if (o.build.verbose) {
      const auto counts = simulation.continuous_counts();
      std::fprintf(stderr, "sylva: t = %g: %zu events, %zu integrator steps, %zu evaluations, %zu location probes\n",
                   simulation.time(), counts.events, counts.steps, counts.evaluations, counts.location_probes);
    }
  } else if (!r.frames_dir.empty()) {
    const int frames = sylva::write_frames(r.frames_dir, simulation, r.output, r.steps, r.frame_formats);
    if (o.build.verbose) std::fprintf(stderr, "sylva: wrote %d frames to %s\n", frames, r.frames_dir.c_str());
  }
  if (!in_time) simulation.run(r.steps);  // frames that ended on the final step leave it in place
  if (!check_verify_string(simulation, r.model)) return 1;
  // As the first view draws it.
  if (!r.interpreted_path.empty())
    simulation.write_interpreted_string(r.interpreted_path, simulation.primary_view());
  if (!r.turtle_path.empty())
    sylva::io::write_output_file(r.turtle_path, simulation.turtle_trace(simulation.primary_view()));
  simulation.write(r.outputs);
  const bool other_output = !r.interpreted_path.empty() || !r.turtle_path.empty() || !r.outputs.empty() ||
                            !r.frames_dir.empty() || !r.timed.record.empty() || !r.timed.plot_path.empty();
  if (r.string_path == kNoString) return 0;
  if (!r.string_path.empty() || !other_output) {
    const std::string path = r.string_path.empty() ? "-" : r.string_path;
    // cpfg's -h: the string after homomorphism. PATH.provenance.json beside
    // the string (api/provenance.h).
    if (r.interpreted_string) {
      simulation.write_interpreted_string(path, simulation.primary_view());
      sylva::write_string_provenance(path, simulation);
    } else {
      sylva::write_recorded_string(path, simulation);
    }
  }
  return 0;
}

// A standard stream closed by whoever started us would be taken by the next
// file or pipe opened (a compiler's output pipe becoming fd 1). Closed ones
// are held by /dev/null, read-only, so a write to a closed standard output
// still fails as it should.
void hold_closed_standard_streams() {
  for (int fd = 0; fd <= 2; ++fd)
    if (fcntl(fd, F_GETFD) == -1 && errno == EBADF) open("/dev/null", O_RDONLY);  // the lowest free: fd
}

}  // namespace

int main(int argc, char** argv) {
  hold_closed_standard_streams();
  if (argc == 2 && std::string(argv[1]) == sylva::app::kStudioWorkerCommand) return sylva::app::run_studio_worker();
  sylva::io::check_standard_output_at_exit();
  CLI::App app{"Sylva: L-system plant modelling. Runs L+C models as lpfg does."};
  // Usage errors read like the others: "sylva: error: ...".
  app.failure_message([](const CLI::App* a, const CLI::Error& e) {
    return "sylva: error: " + CLI::FailureMessage::simple(a, e);
  });
  // At most one command; a missing one is reported after parsing, so that a
  // mistyped command is named as such rather than reported as missing.
  app.require_subcommand(0, 1);

  CommonOptions run_options;
  RunOptions r;
  CLI::App* run = app.add_subcommand("run", "Derive a model and write its string, geometry, drawings or images");
  run->add_option("files", r.files,
                  "The model (L+C or cpfg, usually *.l) and its input files, in any order as lpfg takes them, "
                  "recognised by extension: view (.v), animation (.a), colormap (.map), materials (.mat), "
                  "contours (.con, .cset), functions (.func, .fset), parameters (.vset), environment (.e); or "
                  "as cpfg takes them: -m FILE (colormap), -M FILE (materials), -e FILE (environment), then the "
                  "L-system, the view file and the animation file. The reference programs' other options are "
                  "accepted (docs/reference-dialects.md)")
      ->type_name("FILE...");
  run->add_option("-e,--environment", r.environment.comm_file,
                  "The communication specification file of the model's environment (cpfg's -e; a .e file among "
                  "the input files is taken as well)")
      ->type_name("FILE.e");
  run->add_option("--env-timeout", r.environment.timeout_seconds,
                  "Seconds an environmental program may take to answer one pass before it is stopped (default 60)")
      ->check(CLI::Validator(
          [](std::string& value) -> std::string {
            // inf and nan parse as numbers; neither is a time limit.
            char* end = nullptr;
            const double seconds = std::strtod(value.c_str(), &end);
            if (end == value.c_str() || *end != '\0' || !std::isfinite(seconds) || seconds <= 0)
              return "expected a positive number of seconds, got '" + value + "'";
            return {};
          },
          "SECONDS"))
      ->type_name("SECONDS");
  run->add_flag("--clean-ea20,--cleanEA20", r.environment.clean_ea20,
                "Zero EA20's values before the environment's answers are written (lpfg's -cleanEA20)");
  run->add_option("--threads", r.threads,
                  "Threads a derivation step may use (default: one per core); the string is the same with any "
                  "number, as steps run in parallel only where the result cannot differ (docs/parallel-derivation.md)")
      ->check(CLI::NonNegativeNumber)
      ->type_name("N");
  run->add_flag("--explain-parallel", r.explain_parallel,
                "Say whether productions and decomposition run in parallel, or which rule keeps them serial and why");
  run->add_option_function<std::string>(
         "--random",
         [&r](const std::string& mode) { r.keyed_random = mode == "keyed"; },
         "ran() in rule bodies: 'lpfg' (default) draws lpfg's sequence; 'keyed' draws from a generator keyed by "
         "the step and the module, so a stochastic model gives one string at any number of threads")
      ->check(CLI::IsMember({"lpfg", "keyed"}))
      ->type_name("MODE");
  run->add_option("--seed", r.seed,
                  "Start the random generators from SEED (ran(), SeedGillespie's, a cpfg model's seed: and srand()), "
                  "passing over the model's own seeding, so replicates of a stochastic model differ")
      ->type_name("SEED");
  run->add_flag("--cpfg-window-seeding", r.cpfg_window_seeding,
                "cpfg models: choose among stochastic productions from seed: as cpfg's window does "
                "(cpfg -g, and Sylva by default, ignore seed:)");
  run->add_flag("--gpu", r.gpu,
                "Derive a point-subdivision L-system (a closed or open curve of points, each replaced by "
                "affine combinations of its neighbours: Chaikin, B-spline, four-point) on the GPU through "
                "OpenGL; other models, and runs asking for more than the string, are derived on the CPU");
  run->add_option("--steps,-n", r.steps, "Number of derivation steps (default: the model's derivation length)")
      ->check(CLI::Validator(
          [](std::string& value) -> std::string {
            int n = 0;
            auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), n);
            if (error != std::errc() || end != value.data() + value.size() || n < 0)
              return "expected a number of steps (0 or more), not '" + value + "'";
            return {};
          },
          "NONNEGATIVE"));
  add_limit_options(*run, r.limits);
  add_time_options(*run, r);
  run->add_flag("--huge-pages", r.huge_pages,
                "Keep large strings in transparent huge pages: faster where the system has free huge pages at "
                "hand, slower on virtual machines that return free memory to their host (docs/performance.md)");
  run->add_option("--string,-s", r.string_path,
                  "Write the final string to FILE ('-' for standard output; the default when no other output is "
                  "asked for; 'none' for no string at all, ./none for a file of that name)")
      ->type_name("FILE");
  run->add_option("--interpreted", r.interpreted_path,
                  "Write the final string after interpretation rules (what the turtle draws) to FILE or '-'")
      ->type_name("FILE");
  run->add_option("-o,--output", r.outputs,
                  "Write the final state to FILE, in the format its extension names: mesh (.obj with .mtl, .ply, "
                  ".glb), drawing (.svg, .pdf, .ps, .eps) or image (.png); repeatable. A model drawing several "
                  "views (UseView) writes one file per view: FILE for the first, FILE-NAME.ext for the others")
      ->type_name("FILE");
  run->add_option("--width", r.output.width, "Width of images and drawings in pixels (default 800)")
      ->check(CLI::Range(1, 16384));
  run->add_option("--height", r.output.height, "Height of images and drawings in pixels (default 800)")
      ->check(CLI::Range(1, 16384));
  run->add_option("--frames", r.frames_dir,
                  "Write one PNG per animation frame into DIR (frames from the animation file's first frame, "
                  "last frame and step; every step without one)")
      ->type_name("DIR");
  run->add_option("--frame-format", r.frame_formats,
                  "What --frames writes for each frame (repeatable; default png): png, obj, ply, glb, svg, pdf, ps, "
                  "eps, or str for the string")
      ->type_name("EXT");
  run->add_option("--axiom-from", r.axiom_from,
                  "Start from the string saved in FILE (by --string or OutputString) instead of the axiom")
      ->type_name("FILE");
  run->add_option("--turtle", r.turtle_path,
                  "Write the turtle's commands for the final string to FILE or '-', one per line")
      ->type_name("FILE");
  std::string reproduce_file;
  run->add_option("--reproduce", reproduce_file,
                  "Run again the run that wrote FILE (an output carrying a provenance record, a string's "
                  "FILE.provenance.json): check that the model and input files are unchanged and that the string "
                  "is the same (exit 0), say what differs (1), or that FILE has no record (2); docs/provenance.md")
      ->type_name("FILE");
  add_build_options(*run, run_options);
  run->add_option("--compile-timeout", run_options.build.compile_timeout_seconds,
                  "Seconds the C++ compiler may take for the model before it is stopped (default: "
                  "$SYLVA_COMPILE_TIMEOUT or 600)")
      ->check(CLI::PositiveNumber)
      ->type_name("SECONDS");

  CommonOptions experiment_build;
  sylva::app::ExperimentCommandOptions experiment_options;
  CLI::App* experiment = sylva::app::add_experiment_command(app, experiment_options);
  add_build_options(*experiment, experiment_build);

  CommonOptions translate_options;
  std::string translate_model, translate_output = "-";
  CLI::App* translate = app.add_subcommand("translate", "Print the C++ a model is translated into");
  translate->add_option("model", translate_model, "The model file")->required()->type_name("MODEL");
  translate->add_option("-o,--output", translate_output, "Write the C++ to FILE instead of standard output")
      ->type_name("FILE");
  add_build_options(*translate, translate_options);

  CommonOptions studio_build;
  sylva::app::StudioOptions studio_options;
  CLI::App* studio = sylva::app::add_studio_command(app, studio_options);
  add_build_options(*studio, studio_build);

  sylva::app::CacheOptions cache_options;
  CLI::App* cache = sylva::app::add_cache_command(app, cache_options);

  // `run` and `studio` take lpfg's and cpfg's command lines as they are:
  // their files and options are taken out first, and Sylva's own options
  // left for CLI11.
  std::vector<std::string> arguments(argv + 1, argv + argc);
  std::vector<std::string> reference_outputs;
  std::string reference_string;
  CLI::App* reference_command = arguments.empty()           ? nullptr
                                : arguments[0] == "run"    ? run
                                : arguments[0] == "studio" ? studio
                                                           : nullptr;
  if (reference_command) {
    try {
      sylva::ReferenceCommandLine line = sylva::read_reference_command_line(
          {arguments.begin() + 1, arguments.end()}, [reference_command](const std::string& name) -> std::optional<int> {
            const CLI::Option* option = reference_command->get_option_no_throw(name);
            if (option == nullptr) return std::nullopt;
            return option->get_expected_max() == 0 ? 0 : option->get_type_size();  // a flag, or one value
          });
      for (const std::string& note : line.notes) std::fprintf(stderr, "sylva: note: %s\n", note.c_str());
      studio_options.model = r.model = line.model;
      studio_options.inputs = r.inputs = line.inputs;
      reference_outputs = line.outputs;
      reference_string = line.string_path;
      r.interpreted_string = line.interpreted_string;
      r.compile_only = line.compile_only;
      r.environment.clean_ea20 = line.clean_ea20;
      if (line.width) r.output.width = *line.width;
      if (line.height) r.output.height = *line.height;
      arguments.assign(1, arguments[0]);
      arguments.insert(arguments.end(), line.sylva_arguments.begin(), line.sylva_arguments.end());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "sylva: error: %s\n", e.what());
      return 109;  // CLI11's exit status for a usage error
    }
  }
  try {
    std::reverse(arguments.begin(), arguments.end());  // CLI11 takes them last first
    app.parse(arguments);
    if (app.get_subcommands().empty()) throw CLI::RequiredError("A command (run, experiment, studio or translate)");
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  r.outputs.insert(r.outputs.end(), reference_outputs.begin(), reference_outputs.end());
  if (r.string_path.empty()) r.string_path = reference_string;

  // The studio stops its worker and server on these signals itself.
  if (!*studio) sylva::interruption::install_handlers();
  try {
    if (*run && !reproduce_file.empty()) return sylva::app::run_reproduce(reproduce_file, run_options.build);
    if (*run) return run_command(r, run_options);
    if (*studio) return sylva::app::run_studio(studio_options, studio_build.build);
    if (*cache) return sylva::app::run_cache_command(cache_options);
    if (*experiment) return sylva::app::run_experiment_command(experiment_options, experiment_build.build);
    if (*translate) {
      sylva::io::write_output_file(translate_output,
                                   sylva::build::translate_model(translate_model, translate_options.build));
      return 0;
    }
  } catch (const sylva::ModelError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "sylva: error: out of memory (--max-memory SIZE and --max-modules N stop a run that grows too "
                         "large at the step where it does)\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sylva: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
