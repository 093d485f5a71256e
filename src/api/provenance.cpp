#include "api/provenance.h"

// SHA-256 without the EVP layer: EVP starts OpenSSL's providers and reads its
// configuration file at the first hash, and every run hashes its model before
// deriving (1.4 ms of a 0-step run's 3.9 ms).
#define OPENSSL_API_COMPAT 10101
#include <openssl/sha.h>

#include <cstdint>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <tuple>

#include "io/output_file.h"
#include "io/string_text.h"
#include "support/default_compiler.h"
#include "support/diagnostic.h"
#include "support/subprocess.h"
#include "support/whole_file.h"

#ifndef SYLVA_VERSION
#define SYLVA_VERSION "unknown"
#endif

namespace sylva {

// ---- SHA-256

Sha256::Sha256() : context_(new SHA256_CTX) {
  if (SHA256_Init(static_cast<SHA256_CTX*>(context_)) != 1) throw std::runtime_error("cannot start a SHA-256 digest");
}

Sha256::~Sha256() { delete static_cast<SHA256_CTX*>(context_); }

void Sha256::add(std::string_view bytes) {
  if (!bytes.empty() && SHA256_Update(static_cast<SHA256_CTX*>(context_), bytes.data(), bytes.size()) != 1)
    throw std::runtime_error("SHA-256 digest failed");
}

std::string Sha256::hex() {
  unsigned char digest[SHA256_DIGEST_LENGTH];
  if (SHA256_Final(digest, static_cast<SHA256_CTX*>(context_)) != 1) throw std::runtime_error("SHA-256 digest failed");
  static const char* kHex = "0123456789abcdef";
  std::string out;
  for (unsigned char byte : digest) {
    out += kHex[byte >> 4];
    out += kHex[byte & 15];
  }
  return out;
}

std::string sha256_hex(std::string_view bytes) {
  Sha256 hash;
  hash.add(bytes);
  return hash.hex();
}

std::optional<std::string> file_sha256(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in || std::filesystem::is_directory(path)) return std::nullopt;
  Sha256 hash;
  std::string buffer(std::size_t{1} << 16, '\0');
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    hash.add(std::string_view(buffer.data(), static_cast<std::size_t>(in.gcount())));
  }
  if (in.bad()) return std::nullopt;
  return hash.hex();
}

// ---- continuous settings

ContinuousRecord continuous_record(const continuous::ContinuousSettings& s) {
  ContinuousRecord r;
  using continuous::Method;
  r.integrator = s.integrator.method == Method::kRungeKutta4 ? "rk4" : s.integrator.method == Method::kCvode ? "cvode" : "rk45";
  r.step = s.integrator.step;
  r.max_step = s.integrator.max_step;
  r.relative_tolerance = s.integrator.relative_tolerance;
  r.absolute_tolerance = s.integrator.absolute_tolerance;
  r.event_tolerance = s.event_tolerance;
  r.max_event_rounds = s.max_event_rounds;
  r.end_time = s.end_time;
  return r;
}

continuous::ContinuousSettings continuous_settings(const ContinuousRecord& r) {
  continuous::ContinuousSettings s;
  s.integrator.method = continuous::method_named(r.integrator);
  s.integrator.step = r.step;
  s.integrator.max_step = r.max_step;
  s.integrator.relative_tolerance = r.relative_tolerance;
  s.integrator.absolute_tolerance = r.absolute_tolerance;
  s.event_tolerance = r.event_tolerance;
  s.max_event_rounds = r.max_event_rounds;
  s.end_time = r.end_time;
  return s;
}

// ---- JSON

namespace {

using nlohmann::json;

void put_file(json& j, const HashedFile& f, bool input) {
  j = json{{"path", f.path}, {"sha256", f.sha256}};
  if (input) {
    if (!f.kind.empty()) j["kind"] = f.kind;
    if (f.slot != 1) j["slot"] = f.slot;
  }
}

HashedFile get_file(const json& j) {
  HashedFile f;
  f.path = j.at("path").get<std::string>();
  f.sha256 = j.at("sha256").get<std::string>();
  f.kind = j.value("kind", std::string());
  f.slot = j.value("slot", 1);
  return f;
}

}  // namespace

void to_json(nlohmann::json& j, const RunRecord& r) {
  j = json::object();
  j["format"] = r.format;
  j["sylva_version"] = r.sylva_version;
  put_file(j["model"], r.model, false);
  j["inputs"] = json::array();
  for (const HashedFile& f : r.inputs) {
    json one;
    put_file(one, f, true);
    j["inputs"].push_back(std::move(one));
  }
  j["defines"] = r.defines;
  if (r.seed) j["seed"] = *r.seed;
  if (!r.language.empty()) j["language"] = r.language;
  if (r.keyed_random) j["random"] = "keyed";
  if (r.cpfg_window_seeding) j["cpfg_window_seeding"] = true;
  if (r.axiom_from) put_file(j["axiom_from"], *r.axiom_from, false);
  j["compiler"] = r.compiler;
  j["compiler_version"] = r.compiler_version;
  j["step"] = r.step;
  if (r.time) j["time"] = *r.time;
  j["finished"] = r.finished;
  if (r.continuous) {
    const ContinuousRecord& c = *r.continuous;
    j["continuous"] = json{{"integrator", c.integrator},
                           {"step", c.step},
                           {"max_step", c.max_step},
                           {"relative_tolerance", c.relative_tolerance},
                           {"absolute_tolerance", c.absolute_tolerance},
                           {"event_tolerance", c.event_tolerance},
                           {"max_event_rounds", c.max_event_rounds},
                           {"end_time", c.end_time}};
  }
  j["string_sha256"] = r.string_sha256;
}

void from_json(const nlohmann::json& j, RunRecord& r) {
  r = RunRecord{};
  r.format = j.value("format", 1);
  r.sylva_version = j.value("sylva_version", std::string());
  r.model = get_file(j.at("model"));
  if (j.contains("inputs"))
    for (const json& f : j.at("inputs")) r.inputs.push_back(get_file(f));
  if (j.contains("defines")) r.defines = j.at("defines").get<std::vector<std::string>>();
  if (j.contains("seed") && !j.at("seed").is_null()) r.seed = j.at("seed").get<long>();
  r.language = j.value("language", std::string());
  r.keyed_random = j.value("random", std::string("lpfg")) == "keyed";
  r.cpfg_window_seeding = j.value("cpfg_window_seeding", false);
  if (j.contains("axiom_from")) r.axiom_from = get_file(j.at("axiom_from"));
  r.compiler = j.value("compiler", std::string());
  r.compiler_version = j.value("compiler_version", std::string());
  r.step = j.at("step").get<int>();
  if (j.contains("time") && !j.at("time").is_null()) r.time = j.at("time").get<double>();
  r.finished = j.value("finished", false);
  if (j.contains("continuous")) {
    const json& c = j.at("continuous");
    ContinuousRecord cr;
    cr.integrator = c.value("integrator", cr.integrator);
    cr.step = c.value("step", cr.step);
    cr.max_step = c.value("max_step", cr.max_step);
    cr.relative_tolerance = c.value("relative_tolerance", cr.relative_tolerance);
    cr.absolute_tolerance = c.value("absolute_tolerance", cr.absolute_tolerance);
    cr.event_tolerance = c.value("event_tolerance", cr.event_tolerance);
    cr.max_event_rounds = c.value("max_event_rounds", cr.max_event_rounds);
    cr.end_time = c.value("end_time", cr.end_time);
    r.continuous = cr;
  }
  r.string_sha256 = j.at("string_sha256").get<std::string>();
}

std::string run_record_json(const RunRecord& record) {
  return json(record).dump(-1, ' ', /*ensure_ascii=*/true);
}

RunRecord parse_run_record(const std::string& text, const std::string& source) {
  try {
    return json::parse(text).get<RunRecord>();
  } catch (const json::exception& e) {
    throw ModelError(SourceLocation{source, 0, 0}, std::string("malformed provenance record: ") + e.what());
  }
}

// ---- making records

namespace {

// The names records give input kinds, both ways.
constexpr std::pair<io::InputKind, const char*> kKindNames[] = {
    {io::InputKind::View, "view"},
    {io::InputKind::Animation, "animation"},
    {io::InputKind::Colormap, "colormap"},
    {io::InputKind::Materials, "materials"},
    {io::InputKind::Contour, "contour"},
    {io::InputKind::ContourSet, "contour-set"},
    {io::InputKind::Function, "function"},
    {io::InputKind::FunctionSet, "function-set"},
    {io::InputKind::TimedFunctionSet, "timed-function-set"},
    {io::InputKind::Parameters, "parameters"},
    {io::InputKind::Environment, "environment"}};

const char* kind_name(io::InputKind kind) {
  for (const auto& [k, name] : kKindNames)
    if (k == kind) return name;
  return "";
}

}  // namespace

io::InputKind input_kind_named(const std::string& name, const std::string& path) {
  for (const auto& [kind, kind_name] : kKindNames)
    if (name == kind_name) return kind;
  return io::input_kind_of(path);
}

HashedFile hashed_file(const std::string& path) {
  HashedFile f;
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
  f.path = ec ? path : absolute.lexically_normal().string();
  f.sha256 = file_sha256(path).value_or("");
  return f;
}

std::string compiler_version(const std::string& compiler) {
  static std::mutex mutex;
  static std::map<std::string, std::string> known;  // one run per compiler per process
  std::lock_guard<std::mutex> lock(mutex);
  auto found = known.find(compiler);
  if (found != known.end()) return found->second;
  std::string line;
  try {
    const ProcessResult result = run_process({compiler, "--version"}, 30);
    if (result.exit_code == 0) line = result.out.substr(0, result.out.find('\n'));
  } catch (...) {
  }
  known.emplace(compiler, line);
  return line;
}

const char* sylva_version() { return SYLVA_VERSION; }

RunRecord make_run_record(const Simulation& simulation, const SimulationOptions& options) {
  RunRecord r = make_lazy_run_record(simulation, options);
  r.compiler_version = compiler_version(r.compiler);
  return r;
}

RunRecord make_lazy_run_record(const Simulation& simulation, const SimulationOptions& options) {
  RunRecord r;
  r.sylva_version = sylva_version();
  r.model = hashed_file(simulation.model_path());
  for (const io::InputFile& input : options.input_files) {
    HashedFile f = hashed_file(input.path);
    f.kind = kind_name(input.kind);
    f.slot = input.slot;
    r.inputs.push_back(std::move(f));
  }
  if (!options.environment.comm_file.empty()) {
    HashedFile f = hashed_file(options.environment.comm_file);
    f.kind = kind_name(io::InputKind::Environment);
    r.inputs.push_back(std::move(f));
  }
  r.defines = options.build.defines;
  r.seed = options.seed;
  r.language = options.build.language == "auto" ? "" : options.build.language;
  r.keyed_random = options.keyed_random;
  r.cpfg_window_seeding = options.cpfg_window_seeding;
  r.compiler = compiler_or_default(options.build.compiler);
  return r;
}

std::string string_sha256(const Simulation& simulation) {
  Sha256 hash;
  io::write_string_text(simulation.string(), simulation.types(), [&hash](std::string_view piece) { hash.add(piece); });
  return hash.hex();
}

namespace {

// `string_sha256`: the string's hash when it is already known.
RunRecord completed(RunRecord r, const Simulation& simulation, std::string string_sha256_hex) {
  if (r.compiler_version.empty()) r.compiler_version = compiler_version(r.compiler);
  r.step = simulation.step_number();
  if (r.continuous) r.time = simulation.time();
  r.finished = simulation.finished();
  r.string_sha256 = string_sha256_hex.empty() ? string_sha256(simulation) : std::move(string_sha256_hex);
  return r;
}

}  // namespace

RunRecord complete_run_record(RunRecord r, const Simulation& simulation) { return completed(std::move(r), simulation, ""); }

// ---- the outputs' records

namespace {

struct Registered {
  RunRecord base;
  // The state the cached JSON was made for.
  std::tuple<bool, bool, int, double, std::size_t> state{};
  std::string json;
};

std::mutex registry_mutex;
std::map<const Simulation*, Registered>& registry() {
  static std::map<const Simulation*, Registered> map;
  return map;
}

}  // namespace

ProvenanceScope::ProvenanceScope(const Simulation& simulation, RunRecord base) : simulation_(&simulation) {
  std::lock_guard<std::mutex> lock(registry_mutex);
  registry()[simulation_] = Registered{std::move(base), {}, {}};
}

ProvenanceScope::~ProvenanceScope() {
  std::lock_guard<std::mutex> lock(registry_mutex);
  registry().erase(simulation_);
}

namespace {

// The record of the simulation's state, made once per state; `known_sha256`:
// the string's hash, when the caller has just computed it.
std::string record_json(const Simulation& simulation, const std::string& known_sha256) {
  std::lock_guard<std::mutex> lock(registry_mutex);
  auto found = registry().find(&simulation);
  if (found == registry().end()) return {};
  Registered& entry = found->second;
  const auto state = std::make_tuple(simulation.begun(), simulation.finished(), simulation.step_number(),
                                     entry.base.continuous ? simulation.time() : 0.0,
                                     simulation.string().size_bytes());
  if (entry.json.empty() || entry.state != state) {
    entry.json = run_record_json(completed(entry.base, simulation, known_sha256));
    entry.state = state;
  }
  return entry.json;
}

bool recorded(const Simulation& simulation) {
  std::lock_guard<std::mutex> lock(registry_mutex);
  return registry().count(&simulation) > 0;
}

void write_sidecar(const std::string& path, const std::string& record) {
  if (path == "-" || record.empty()) return;
  io::write_output_file(path + kProvenanceSidecarSuffix, json::parse(record).dump(2) + "\n");
}

}  // namespace

std::string provenance_json(const Simulation& simulation) { return record_json(simulation, ""); }

void write_string_provenance(const std::string& path, const Simulation& simulation) {
  write_sidecar(path, provenance_json(simulation));
}

void write_recorded_string(const std::string& path, const Simulation& simulation) {
  if (path == "-" || !recorded(simulation)) {  // no sidecar to write
    simulation.write_string(path);
    return;
  }
  // The string's text is hashed as it is written rather than made again.
  Sha256 hash;
  io::write_output_file(path, [&](const ContentSink& sink) {
    io::write_string_text(simulation.string(), simulation.types(), [&](std::string_view piece) {
      hash.add(piece);
      sink(piece);
    });
  });
  write_sidecar(path, record_json(simulation, hash.hex()));
}

// ---- reading records back

std::optional<std::string> png_text_chunk(std::string_view png, const std::string& keyword) {
  if (png.size() < 8 || png.substr(0, 8) != std::string_view("\x89PNG\r\n\x1a\n", 8)) return std::nullopt;
  std::size_t at = 8;
  while (at + 12 <= png.size()) {
    std::uint32_t length = 0;
    for (int k = 0; k < 4; ++k) length = (length << 8) | static_cast<unsigned char>(png[at + k]);
    const std::string_view type = png.substr(at + 4, 4);
    if (at + 12 + length > png.size()) break;
    const std::string_view data = png.substr(at + 8, length);
    if (type == "IEND") break;
    const std::size_t nul = data.find('\0');
    if (nul != std::string_view::npos && data.substr(0, nul) == keyword) {
      if (type == "tEXt") return std::string(data.substr(nul + 1));
      // iTXt: keyword, NUL, compression flag, method, language, NUL, translated keyword, NUL, text.
      if (type == "iTXt" && nul + 2 < data.size() && data[nul + 1] == 0) {
        const std::size_t language_end = data.find('\0', nul + 3);
        const std::size_t translated_end =
            language_end == std::string_view::npos ? language_end : data.find('\0', language_end + 1);
        if (translated_end != std::string_view::npos) return std::string(data.substr(translated_end + 1));
      }
    }
    at += 12 + length;
  }
  return std::nullopt;
}

namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// The rest of the line after `prefix`, where a line of `text` starts with it.
std::optional<std::string> line_after(const std::string& text, const std::string& prefix) {
  std::size_t at = text.rfind(prefix, 0) == 0 ? 0 : text.find("\n" + prefix);
  if (at == std::string::npos) return std::nullopt;
  if (text[at] == '\n') ++at;
  at += prefix.size();
  std::size_t end = text.find('\n', at);
  std::string line = text.substr(at, end == std::string::npos ? std::string::npos : end - at);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return line;
}

std::string xml_unescape(const std::string& text) {
  static const std::pair<const char*, char> kEntities[] = {
      {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    bool replaced = false;
    if (text[i] == '&')
      for (const auto& [entity, ch] : kEntities)
        if (text.compare(i, std::strlen(entity), entity) == 0) {
          out += ch;
          i += std::strlen(entity) - 1;
          replaced = true;
          break;
        }
    if (!replaced) out += text[i];
  }
  return out;
}

std::optional<std::string> svg_metadata(const std::string& text) {
  const std::string open = "<metadata id=\"sylva-provenance\">";
  const std::size_t at = text.find(open);
  if (at == std::string::npos) return std::nullopt;
  const std::size_t end = text.find("</metadata>", at);
  if (end == std::string::npos) return std::nullopt;
  return xml_unescape(text.substr(at + open.size(), end - at - open.size()));
}

// The glTF JSON chunk of a GLB file: asset.extras["sylva:provenance"].
std::optional<std::string> glb_record(const std::string& bytes) {
  auto u32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(k)]);
    return v;
  };
  if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0 || bytes.compare(16, 4, "JSON") != 0) return std::nullopt;
  const std::uint32_t length = u32(12);
  if (20 + std::size_t{length} > bytes.size()) return std::nullopt;
  const json gltf = json::parse(bytes.substr(20, length), nullptr, false);
  if (gltf.is_discarded()) return std::nullopt;
  const json::json_pointer pointer("/asset/extras/sylva:provenance");
  if (!gltf.contains(pointer)) return std::nullopt;
  const json& value = gltf.at(pointer);
  return value.is_string() ? value.get<std::string>() : value.dump();
}

// The Info dictionary's Subject, as cairo writes it: a hex string of
// UTF-16BE after a byte order mark (cairo 1.16), or a literal string with
// `(`, `)` and `\` escaped. The record follows its key.
std::optional<std::string> pdf_subject_record(const std::string& bytes) {
  std::size_t at = bytes.find("/Subject");
  if (at == std::string::npos) return std::nullopt;
  at += 8;
  while (at < bytes.size() && (bytes[at] == ' ' || bytes[at] == '\n' || bytes[at] == '\r')) ++at;
  if (at >= bytes.size()) return std::nullopt;
  std::string raw;
  if (bytes[at] == '(') {
    for (++at; at < bytes.size() && bytes[at] != ')'; ++at) {
      if (bytes[at] == '\\' && at + 1 < bytes.size()) ++at;
      raw += bytes[at];
    }
  } else if (bytes[at] == '<') {
    auto digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) ? c - '0' : (std::toupper(c) - 'A' + 10); };
    std::string hex;
    for (++at; at < bytes.size() && bytes[at] != '>'; ++at)
      if (std::isxdigit(static_cast<unsigned char>(bytes[at]))) hex += bytes[at];
    for (std::size_t i = 0; i + 1 < hex.size(); i += 2) raw += static_cast<char>(digit(hex[i]) * 16 + digit(hex[i + 1]));
    if (raw.size() >= 2 && raw[0] == '\xFE' && raw[1] == '\xFF') {
      // UTF-16BE to UTF-8.
      std::string utf8;
      for (std::size_t i = 2; i + 1 < raw.size(); i += 2) {
        std::uint32_t u = static_cast<unsigned char>(raw[i]) << 8 | static_cast<unsigned char>(raw[i + 1]);
        if (u >= 0xD800 && u < 0xDC00 && i + 3 < raw.size()) {
          const std::uint32_t low = static_cast<unsigned char>(raw[i + 2]) << 8 | static_cast<unsigned char>(raw[i + 3]);
          u = 0x10000 + ((u - 0xD800) << 10) + (low - 0xDC00);
          i += 2;
        }
        if (u < 0x80) {
          utf8 += static_cast<char>(u);
        } else if (u < 0x800) {
          utf8 += static_cast<char>(0xC0 | (u >> 6));
          utf8 += static_cast<char>(0x80 | (u & 0x3F));
        } else if (u < 0x10000) {
          utf8 += static_cast<char>(0xE0 | (u >> 12));
          utf8 += static_cast<char>(0x80 | ((u >> 6) & 0x3F));
          utf8 += static_cast<char>(0x80 | (u & 0x3F));
        } else {
          utf8 += static_cast<char>(0xF0 | (u >> 18));
          utf8 += static_cast<char>(0x80 | ((u >> 12) & 0x3F));
          utf8 += static_cast<char>(0x80 | ((u >> 6) & 0x3F));
          utf8 += static_cast<char>(0x80 | (u & 0x3F));
        }
      }
      raw = std::move(utf8);
    }
  } else {
    return std::nullopt;
  }
  const std::string key = std::string(kProvenanceKey) + " ";
  if (raw.rfind(key, 0) != 0) return std::nullopt;
  return raw.substr(key.size());
}

}  // namespace

std::optional<RunRecord> read_run_record(const std::string& path) {
  const std::string ext = lower_extension(path);
  auto read = [&](const std::string& file) {
    WholeFile whole = read_whole_file(file);
    if (!whole) throw ModelError(SourceLocation{file, 0, 0}, "cannot read the file");
    return std::move(whole.bytes);
  };
  if (ext == ".json") return parse_run_record(read(path), path);
  const std::string bytes = read(path);
  std::optional<std::string> embedded;
  if (ext == ".png") embedded = png_text_chunk(bytes, kProvenanceKey);
  else if (ext == ".obj") embedded = line_after(bytes, std::string("# ") + kProvenanceKey + " ");
  else if (ext == ".ply") {
    const std::size_t header_end = bytes.find("\nend_header");
    embedded = line_after(bytes.substr(0, header_end), std::string("comment ") + kProvenanceKey + " ");
  } else if (ext == ".glb") embedded = glb_record(bytes);
  else if (ext == ".svg") embedded = svg_metadata(bytes);
  else if (ext == ".ps" || ext == ".eps") embedded = line_after(bytes, std::string("%%") + kProvenanceKey + " ");
  else if (ext == ".pdf") embedded = pdf_subject_record(bytes);
  if (embedded) return parse_run_record(*embedded, path);
  // A string (or any file) with its record beside it.
  const std::string sidecar = path + kProvenanceSidecarSuffix;
  std::error_code ec;
  if (std::filesystem::is_regular_file(sidecar, ec)) return parse_run_record(read(sidecar), sidecar);
  return std::nullopt;
}

}  // namespace sylva
