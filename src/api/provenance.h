// Provenance: what produced an output, recorded in the output itself
// (docs/provenance.md). Every file `sylva run` writes (and write_frame,
// write_frames) carries a RunRecord as JSON: the model's path and the
// SHA-256 of its bytes, each input file's, the -D definitions, the seed,
// the step (or time) shown, Sylva's version, the model's compiler, and the
// SHA-256 of the derived string's text, so that `sylva run --reproduce FILE`
// can run it again and check that it gives the same string.
//
// Where the record goes, by format (each writer takes it as JSON text):
//   PNG        a tEXt chunk after IHDR, keyword "sylva:provenance"
//   OBJ        a comment line "# sylva:provenance {json}" near the top
//   PLY        a header line "comment sylva:provenance {json}"
//   GLB        asset.extras["sylva:provenance"]: the JSON as a string
//              (losslessly: glTF's numbers would round a 64-bit seed)
//   SVG        <metadata id="sylva-provenance">{json, XML-escaped}</metadata>
//   PS, EPS    a header comment line "%%sylva:provenance {json}"
//   PDF        the document's Subject: "sylva:provenance {json}"
//   strings    a sidecar file FILE.provenance.json (the string's text stays
//              byte for byte what lpfg's readers take)
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "api/simulation.h"

namespace sylva {

// ---- SHA-256 (FIPS 180-4), through OpenSSL's libcrypto (linked statically)
class Sha256 {
 public:
  Sha256();
  ~Sha256();
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;
  void add(std::string_view bytes);
  // The digest as 64 lowercase hex digits; the hash is finished then.
  std::string hex();

 private:
  void* context_;  // SHA256_CTX
};
std::string sha256_hex(std::string_view bytes);
// The SHA-256 of a file's bytes; nullopt when it cannot be read.
std::optional<std::string> file_sha256(const std::string& path);

// The key every embedded form is found by.
inline constexpr const char* kProvenanceKey = "sylva:provenance";
// The string's sidecar: FILE + this.
inline constexpr const char* kProvenanceSidecarSuffix = ".provenance.json";

struct HashedFile {
  std::string path;    // absolute, as it was when the run began
  std::string sha256;  // of the bytes then
  std::string kind;    // input files: what the file was taken as ("view", "animation", ...; "" recognised by extension)
  int slot = 1;        // cpfg's -m2 / -M3 numbers
  bool operator==(const HashedFile&) const = default;
};

// A run in continuous time (sylva run --time): what the state at `time`
// depends on besides the model.
struct ContinuousRecord {
  std::string integrator = "rk45";  // rk4, rk45 or cvode
  double step = 0.01, max_step = 0, relative_tolerance = 1e-6, absolute_tolerance = 1e-9;
  double event_tolerance = 1e-9;
  int max_event_rounds = 1000;
  double end_time = 0;
  bool operator==(const ContinuousRecord&) const = default;
};

struct RunRecord {
  int format = 1;              // of the record
  std::string sylva_version;   // CMake's project version
  HashedFile model;
  std::vector<HashedFile> inputs;
  std::vector<std::string> defines;  // -D, as given: NAME or NAME=VALUE
  std::optional<long> seed;          // SimulationOptions::seed, when set
  std::string language;              // --lang as given ("" or "auto": recognised)
  bool keyed_random = false;         // --random keyed
  bool cpfg_window_seeding = false;
  std::optional<HashedFile> axiom_from;  // --axiom-from
  std::string compiler;          // the program that compiled the model
  std::string compiler_version;  // the first line of its --version
  // What the output shows: the state after `step` steps (the time, for a
  // run in continuous time), before End unless `finished`.
  int step = 0;
  std::optional<double> time;
  bool finished = false;
  std::optional<ContinuousRecord> continuous;
  // SHA-256 of the derived string's text as `sylva run --string` writes it.
  std::string string_sha256;
  bool operator==(const RunRecord&) const = default;
};

// A run's continuous settings as recorded, and back.
ContinuousRecord continuous_record(const continuous::ContinuousSettings& settings);
continuous::ContinuousSettings continuous_settings(const ContinuousRecord& record);

void to_json(nlohmann::json& j, const RunRecord& record);
void from_json(const nlohmann::json& j, RunRecord& record);
// One line of ASCII JSON (non-ASCII escaped as \uXXXX), as every output
// embeds it.
std::string run_record_json(const RunRecord& record);
// Throws ModelError naming `source` when the text is not a record.
RunRecord parse_run_record(const std::string& json, const std::string& source);

// A file as a record names it: its absolute path and the SHA-256 of its bytes
// ("" when it cannot be read).
HashedFile hashed_file(const std::string& path);
// The input kind a record names ("view", "function-set", ...); recognised by
// `path`'s extension when the name is empty or unknown.
io::InputKind input_kind_named(const std::string& name, const std::string& path);

// What a run's outputs will record that does not change while it runs: the
// model, the inputs, definitions, seed and compiler of `options` (as given
// to the Simulation's constructor). Files are hashed now.
RunRecord make_run_record(const Simulation& simulation, const SimulationOptions& options);
// The same without the compiler's version, which complete_run_record asks
// for when an output is written: a run that writes nothing never starts the
// compiler.
RunRecord make_lazy_run_record(const Simulation& simulation, const SimulationOptions& options);
// The first line of `compiler --version` ("" when it cannot be run), run
// once per compiler per process.
std::string compiler_version(const std::string& compiler);
// This program's version, as records give it.
const char* sylva_version();
// `base` filled with where `simulation` is now: its step (its time when
// base.continuous is set), whether it finished, the string's SHA-256, and
// the compiler's version if it has none.
RunRecord complete_run_record(RunRecord base, const Simulation& simulation);
// The SHA-256 of simulation.string_text(), computed as the text is made.
std::string string_sha256(const Simulation& simulation);

// While a scope lives, every output written of `simulation` through
// api/outputs.h (write_output, Simulation::write, write_frame, write_frames,
// frames of timed runs) carries `base` completed with the state it shows.
// Destroy it before the simulation. Outputs of a simulation without a scope
// carry no record.
class ProvenanceScope {
 public:
  ProvenanceScope(const Simulation& simulation, RunRecord base);
  ~ProvenanceScope();
  ProvenanceScope(const ProvenanceScope&) = delete;
  ProvenanceScope& operator=(const ProvenanceScope&) = delete;

 private:
  const Simulation* simulation_;
};

// The record of `simulation`'s current state as JSON, "" without a scope.
// Computed once per state: outputs of one state share it.
std::string provenance_json(const Simulation& simulation);

// Writes PATH.provenance.json beside a string written to `path` (not for
// "-", nor without a scope).
void write_string_provenance(const std::string& path, const Simulation& simulation);
// Simulation::write_string and, under a scope, its sidecar, the string's
// text hashed as it is written rather than made a second time.
void write_recorded_string(const std::string& path, const Simulation& simulation);

// ---- reading a record back (sylva run --reproduce)
// The record embedded in `path` (by its extension: .png, .obj, .ply, .glb,
// .svg, .ps, .eps, .pdf), its sidecar PATH.provenance.json, or `path`
// itself when it is a .json record. nullopt when the file carries none;
// throws ModelError when it cannot be read or the record is malformed.
std::optional<RunRecord> read_run_record(const std::string& path);

// The text of a PNG's tEXt or (uncompressed) iTXt chunk `keyword`.
std::optional<std::string> png_text_chunk(std::string_view png, const std::string& keyword);

}  // namespace sylva
