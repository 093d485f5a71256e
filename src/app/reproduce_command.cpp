#include "app/reproduce_command.h"

#include <cstdio>

#include "io/string_reader.h"
#include "support/default_compiler.h"
#include "support/diagnostic.h"

namespace sylva::app {

RunRecord run_record(const Simulation& simulation, const SimulationOptions& options, const std::string& axiom_from,
                     const continuous::ContinuousSettings* in_time) {
  RunRecord record = make_lazy_run_record(simulation, options);
  if (!axiom_from.empty()) record.axiom_from = hashed_file(axiom_from);
  if (in_time) record.continuous = continuous_record(*in_time);
  return record;
}

namespace {

// Whether `file` still has the recorded bytes; says which file changed if not.
bool unchanged(const HashedFile& file, const char* what, const std::string& record_file) {
  const std::optional<std::string> now = file_sha256(file.path);
  if (now && *now == file.sha256) return true;
  if (!now)
    std::fprintf(stderr, "sylva: error: %s: the %s %s records is missing or unreadable\n", file.path.c_str(), what,
                 record_file.c_str());
  else
    std::fprintf(stderr,
                 "sylva: error: %s: the %s has changed since %s was written (sha256 recorded %s, now %s)\n",
                 file.path.c_str(), what, record_file.c_str(), file.sha256.c_str(), now->c_str());
  return false;
}

}  // namespace

int run_reproduce(const std::string& file, const build::BuildOptions& build) {
  const std::optional<RunRecord> found = read_run_record(file);
  if (!found) {
    std::fprintf(stderr,
                 "sylva: error: %s: no provenance record (expected one embedded by sylva run, or a sidecar %s%s)\n",
                 file.c_str(), file.c_str(), kProvenanceSidecarSuffix);
    return kNoRecord;
  }
  const RunRecord& record = *found;
  bool same_files = unchanged(record.model, "model", file);
  for (const HashedFile& input : record.inputs) same_files = unchanged(input, "input file", file) && same_files;
  if (record.axiom_from) same_files = unchanged(*record.axiom_from, "saved axiom string", file) && same_files;
  if (!same_files) return kNotReproduced;

  SimulationOptions options;
  options.build = build;
  if (options.build.compiler.empty()) options.build.compiler = record.compiler;
  options.build.defines = record.defines;
  options.build.language = record.language;
  for (const HashedFile& input : record.inputs)
    options.input_files.emplace_back(input.path, input_kind_named(input.kind, input.path), input.slot);
  options.seed = record.seed;
  options.keyed_random = record.keyed_random;
  options.cpfg_window_seeding = record.cpfg_window_seeding;

  Simulation simulation(record.model.path, options);
  // The files were hashed above: only the versions are compared here.
  const std::string compiler = compiler_version(compiler_or_default(options.build.compiler));
  if (!record.compiler_version.empty() && compiler != record.compiler_version)
    std::fprintf(stderr, "sylva: note: the model was compiled by %s, now by %s\n", record.compiler_version.c_str(),
                 compiler.c_str());
  if (!record.sylva_version.empty() && record.sylva_version != sylva_version())
    std::fprintf(stderr, "sylva: note: %s was written by Sylva %s, this is Sylva %s\n", file.c_str(),
                 record.sylva_version.c_str(), sylva_version());
  if (record.axiom_from) simulation.start_from(io::read_string_file(record.axiom_from->path, simulation.types()));

  if (record.continuous) {
    // The integrator's steps depend on the settings' end, not on the times
    // asked for: advancing straight to the recorded time gives its state.
    simulation.set_continuous_settings(continuous_settings(*record.continuous));
    simulation.begin();
    simulation.advance_to(record.time.value_or(0));
  } else {
    simulation.begin();
    while (simulation.step_number() < record.step && simulation.step()) {
    }
  }
  if (record.finished) simulation.finish();

  if (!record.continuous && simulation.step_number() != record.step) {
    std::fprintf(stderr, "sylva: error: %s: the run stopped after %d steps, the record shows step %d\n",
                 file.c_str(), simulation.step_number(), record.step);
    return kNotReproduced;
  }
  const std::string hash = string_sha256(simulation);
  if (hash != record.string_sha256) {
    std::fprintf(stderr,
                 "sylva: error: %s: not reproduced: the string's sha256 is %s, the record says %s (step %d)\n",
                 file.c_str(), hash.c_str(), record.string_sha256.c_str(), record.step);
    return kNotReproduced;
  }
  std::printf("reproduced: %s (string sha256 %s)\n", file.c_str(), hash.c_str());
  return kReproduced;
}

}  // namespace sylva::app
