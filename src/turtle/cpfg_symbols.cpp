#include "turtle/cpfg_symbols.h"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <unordered_map>

#include "sylva/predefined_ids.h"

namespace sylva::turtle {

namespace {

const std::unordered_map<std::string_view, CpfgOp>& command_table() {
  using O = CpfgOp;
  static const std::unordered_map<std::string_view, CpfgOp> table = {
      {"F", O::Forward}, {"f", O::Move}, {"G", O::ForwardNoVertex}, {"g", O::MoveNoVertex},
      {"@M", O::MoveTo},
      {"+", O::Left}, {"-", O::Right}, {"&", O::Down}, {"^", O::Up}, {"\\", O::RollLeft}, {"/", O::RollRight},
      {"|", O::TurnAround},
      // $ ends a sub-L-system's ?(label,s), and does nothing else.
      {"@v", O::RollToVertical}, {"$", O::SubLsystemReturn}, {"?", O::SubLsystemCall},
      {"@R", O::SetHeading},
      {"#", O::WidthUp}, {"!", O::WidthDown},
      {";", O::ColorUp}, {",", O::ColorDown},
      // The Algorithmic Beauty of Plants' increment of the colour index.
      {"'", O::ColorUp},
      {"{", O::PolygonOrCylinderStart}, {"}", O::PolygonOrCylinderEnd}, {".", O::VertexOrCylinderPoint},
      {"@o", O::CircleScreen}, {"@c", O::CircleHL}, {"@bo", O::CircleScreenBoundary}, {"@bc", O::CircleHLBoundary},
      {"@O", O::Sphere},
      {"@Gs", O::CylinderStart}, {"@Gc", O::CylinderPoint}, {"@Ge", O::CylinderEnd},
      {"@Gt", O::CylinderTangents}, {"@Gr", O::CylinderRadiusTangents},
      {"@#", O::Contour}, {"@!", O::ContourSides},
      {"@D", O::SetScale}, {"@Di", O::ScaleUp}, {"@Dd", O::ScaleDown},
      {"@Tx", O::Texture},
      {"@PS", O::SurfaceInit}, {"@PC", O::SurfacePoint}, {"@PD", O::SurfaceDraw},
      {"@Ts", O::ElasticitySet}, {"@T", O::ElasticityUp}, {"@Td", O::ElasticityDown},
      {"?P", O::QueryPosition}, {"?H", O::QueryHeading}, {"?L", O::QueryLeft}, {"?U", O::QueryUp},
      {"@L", O::Label}, {"@Tp", O::MinimizeTwist}, {"@Tf", O::ForceTwist},
      {"@;", O::BackColorUp}, {"@,", O::BackColorDown},
  };
  return table;
}

}  // namespace

CpfgOp cpfg_op(const std::string& symbol) {
  auto it = command_table().find(symbol);
  if (it != command_table().end()) return it->second;
  if (symbol.size() == 2 && symbol[0] == '~') return CpfgOp::PredefinedSurface;  // ~id (CPFG manual 6.7.1)
  return CpfgOp::None;
}

bool cpfg_command_prefix(const std::string& start) {
  if (start == "~") return true;
  for (const auto& [symbol, op] : command_table())
    if (symbol.size() > start.size() && symbol.compare(0, start.size(), start) == 0) return true;
  return false;
}

CpfgSymbols::CpfgSymbols(const ModuleTypes& types) : ops_(types.size(), CpfgOp::None), params_(types.size(), 0) {
  // [ and ] keep the predefined ids; the other predefined modules of L+C
  // never occur in a cpfg string (cpfg's F is its own module type).
  if (ops_.size() > rt::mid::EB) {
    ops_[rt::mid::SB] = CpfgOp::Push;
    ops_[rt::mid::EB] = CpfgOp::Pop;
  }
  for (std::size_t id = rt::mid::PredefinedCount; id < types.size(); ++id) {
    const auto m = static_cast<ModuleId>(id);
    ops_[id] = cpfg_op(types.name(m));
    std::uint32_t size = types[m].param_size;
    if (ops_[id] == CpfgOp::Label) {
      // @L("format", p1, ...): the string's pointer, then the floats.
      if (size < sizeof(const char*)) ops_[id] = CpfgOp::None;
      else size -= sizeof(const char*);
    }
    params_[id] = static_cast<std::uint8_t>(std::min<std::uint32_t>(size / 4, 255));
    const std::string& name = types.name(m);
    if (size == 0 && (name == "@" || name == "?" || name == "~")) ops_[id] = CpfgOp::Prefix;
  }
  // Queries read split: ? then P(x,y,z) (P H L U with two or three parameters).
  bool split_query = false;
  for (std::size_t id = rt::mid::PredefinedCount; id < types.size(); ++id)
    split_query = split_query || (ops_[id] == CpfgOp::Prefix && types.name(static_cast<ModuleId>(id)) == "?");
  for (std::size_t id = rt::mid::PredefinedCount; split_query && id < types.size(); ++id) {
    const std::string& name = types.name(static_cast<ModuleId>(id));
    if ((name == "P" || name == "H" || name == "L" || name == "U") && params_[id] >= 2)
      split_queries_.push_back(static_cast<ModuleId>(id));
  }
}

std::string format_cpfg_label(std::string_view format, const float* values, int count) {
  std::string out;
  int used = 0;
  const std::size_t size = format.size();
  auto digits = [&](std::size_t& j) {
    const std::size_t from = j;
    while (j < size && format[j] >= '0' && format[j] <= '9') ++j;
    return j - from;
  };
  std::size_t i = 0;
  while (i < size) {
    if (format[i] != '%') {
      out += format[i++];
      continue;
    }
    if (i + 1 < size && format[i + 1] == '%') {
      out += '%';
      i += 2;
      continue;
    }
    // %[flags][width][.precision][length]conversion; the length (h l ll L q j
    // z t) is dropped: the value is passed as a double or a long long.
    std::string spec = "%";
    std::size_t j = i + 1;
    while (j < size && std::string_view("-+ #0").find(format[j]) != std::string_view::npos) spec += format[j++];
    std::size_t at = j;
    bool fits = digits(j) <= 3;
    spec += format.substr(at, j - at);
    if (j < size && format[j] == '.') {
      at = j++;
      fits = fits && digits(j) <= 3;
      spec += format.substr(at, j - at);
    }
    while (j < size && std::string_view("hlLqjzt").find(format[j]) != std::string_view::npos) ++j;
    const char conversion = j < size ? format[j] : '\0';
    const bool real = conversion != '\0' && std::string_view("fFeEgGaA").find(conversion) != std::string_view::npos;
    const bool integer = conversion != '\0' && std::string_view("diouxX").find(conversion) != std::string_view::npos;
    const double v = used < count ? static_cast<double>(values[used]) : 0.0;
    // A value too large for a long long is printed as a number, not converted.
    const bool representable = real || (std::isfinite(v) && std::fabs(v) < 9.2e18);
    if (!fits || !(real || integer) || used >= count || !representable) {
      const std::size_t end = std::min(size, j + 1);
      out += format.substr(i, end - i);
      i = end;
      continue;
    }
    ++used;
    int n;
    char buffer[64];
    std::string text;
    if (real) {
      spec += conversion;
      n = std::snprintf(buffer, sizeof buffer, spec.c_str(), v);
      if (n >= static_cast<int>(sizeof buffer)) {
        text.resize(static_cast<std::size_t>(n) + 1);
        std::snprintf(text.data(), text.size(), spec.c_str(), v);
      }
    } else {
      spec += "ll";
      spec += conversion;
      const long long whole = static_cast<long long>(v);  // cpfg's C truncates toward 0
      n = conversion == 'd' || conversion == 'i'
              ? std::snprintf(buffer, sizeof buffer, spec.c_str(), whole)
              : std::snprintf(buffer, sizeof buffer, spec.c_str(), static_cast<unsigned long long>(whole));
      if (n >= static_cast<int>(sizeof buffer)) {
        text.resize(static_cast<std::size_t>(n) + 1);
        if (conversion == 'd' || conversion == 'i') std::snprintf(text.data(), text.size(), spec.c_str(), whole);
        else std::snprintf(text.data(), text.size(), spec.c_str(), static_cast<unsigned long long>(whole));
      }
    }
    if (n > 0) out.append(text.empty() ? buffer : text.data(), static_cast<std::size_t>(n));
    i = j + 1;
  }
  return out;
}

std::vector<ModuleId> CpfgSymbols::query_modules() const {
  std::vector<ModuleId> ids = split_queries_;
  for (std::size_t id = 0; id < ops_.size(); ++id)
    if (is_query(ops_[id])) ids.push_back(static_cast<ModuleId>(id));
  return ids;
}

}  // namespace sylva::turtle
