#include "experiment/measures.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>

namespace sylva::experiment {

// A parsed expression: a tree evaluated over a Summary.
struct Measures::Expression {
  enum class Kind { kNumber, kAdd, kSub, kMul, kDiv, kPow, kNeg, kSqrt, kLog, kExp, kAbs,
                    kCount, kSum, kMean, kMin, kMax, kModules, kScene, kMeasure };
  Kind kind = Kind::kNumber;
  double number = 0;   // kNumber
  int index = 0;       // kCount..kMax: into wanted_; kScene: which; kMeasure: an earlier measure
  std::unique_ptr<Expression> a, b;
};

namespace {

using Expression = Measures::Expression;
using Kind = Expression::Kind;
constexpr double kNotANumber = std::numeric_limits<double>::quiet_NaN();

struct Stat {
  double count = 0, sum = 0, min = kNotANumber, max = kNotANumber;
};

struct Summary {
  std::vector<Stat> stats;  // by wanted index
  double modules = 0;
  SceneMeasures scene;
  std::vector<double> earlier;  // the values of the measures before this one
};

const char* const kSceneNames[] = {"height", "width", "depth", "segment_length", "segments", "leaf_area"};

double scene_value(const SceneMeasures& s, int which) {
  switch (which) {
    case 0: return s.height;
    case 1: return s.width;
    case 2: return s.depth;
    case 3: return s.segment_length;
    case 4: return s.segments;
    default: return s.leaf_area;
  }
}

double evaluate(const Expression& e, const Summary& s) {
  switch (e.kind) {
    case Kind::kNumber: return e.number;
    case Kind::kAdd: return evaluate(*e.a, s) + evaluate(*e.b, s);
    case Kind::kSub: return evaluate(*e.a, s) - evaluate(*e.b, s);
    case Kind::kMul: return evaluate(*e.a, s) * evaluate(*e.b, s);
    case Kind::kDiv: return evaluate(*e.a, s) / evaluate(*e.b, s);
    case Kind::kPow: return std::pow(evaluate(*e.a, s), evaluate(*e.b, s));
    case Kind::kNeg: return -evaluate(*e.a, s);
    case Kind::kSqrt: return std::sqrt(evaluate(*e.a, s));
    case Kind::kLog: return std::log(evaluate(*e.a, s));
    case Kind::kExp: return std::exp(evaluate(*e.a, s));
    case Kind::kAbs: return std::fabs(evaluate(*e.a, s));
    case Kind::kCount: return s.stats[e.index].count;
    case Kind::kSum: return s.stats[e.index].sum;
    case Kind::kMean: return s.stats[e.index].count ? s.stats[e.index].sum / s.stats[e.index].count : kNotANumber;
    case Kind::kMin: return s.stats[e.index].min;
    case Kind::kMax: return s.stats[e.index].max;
    case Kind::kModules: return s.modules;
    case Kind::kScene: return scene_value(s.scene, e.index);
    case Kind::kMeasure: return s.earlier[e.index];
  }
  return kNotANumber;
}

// Recursive descent over one measure's text.
class Parser {
 public:
  Parser(const MeasureSpec& spec, const std::vector<MeasureSpec>& earlier, const ModuleTypes& types,
         std::vector<std::pair<ModuleId, int>>& wanted, bool& needs_scene)
      : spec_(spec), text_(spec.expression), earlier_(earlier), types_(types), wanted_(wanted), needs_scene_(needs_scene) {}

  std::unique_ptr<Expression> parse() {
    auto e = sum();
    skip_space();
    if (at_ < text_.size()) fail(at_, "unexpected '" + std::string(1, text_[at_]) + "' in the measure '" + spec_.name + "'");
    return e;
  }

 private:
  [[noreturn]] void fail(std::size_t column, const std::string& message) const {
    SourceLocation where = spec_.at;
    where.column += static_cast<int>(column);
    throw ModelError(where, message);
  }
  void skip_space() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
  }
  bool accept(char c) {
    skip_space();
    if (at_ < text_.size() && text_[at_] == c) {
      ++at_;
      return true;
    }
    return false;
  }
  void expect(char c, const char* what) {
    if (!accept(c)) fail(at_, std::string("expected ") + what + " in the measure '" + spec_.name + "'");
  }
  static std::unique_ptr<Expression> node(Kind kind, std::unique_ptr<Expression> a = {}, std::unique_ptr<Expression> b = {}) {
    auto e = std::make_unique<Expression>();
    e->kind = kind;
    e->a = std::move(a);
    e->b = std::move(b);
    return e;
  }

  std::unique_ptr<Expression> sum() {
    auto left = product();
    for (;;) {
      if (accept('+')) left = node(Kind::kAdd, std::move(left), product());
      else if (accept('-')) left = node(Kind::kSub, std::move(left), product());
      else return left;
    }
  }
  std::unique_ptr<Expression> product() {
    auto left = unary();
    for (;;) {
      if (accept('*')) left = node(Kind::kMul, std::move(left), unary());
      else if (accept('/')) left = node(Kind::kDiv, std::move(left), unary());
      else return left;
    }
  }
  std::unique_ptr<Expression> unary() {
    if (accept('-')) return node(Kind::kNeg, unary());
    if (accept('+')) return unary();
    auto base = primary();
    if (accept('^')) return node(Kind::kPow, std::move(base), unary());
    return base;
  }
  std::string identifier() {
    skip_space();
    const std::size_t start = at_;
    while (at_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[at_])) || text_[at_] == '_')) ++at_;
    return text_.substr(start, at_ - start);
  }
  std::unique_ptr<Expression> primary() {
    skip_space();
    if (at_ >= text_.size()) fail(at_, "the measure '" + spec_.name + "' ends where a value was expected");
    const char c = text_[at_];
    if (c == '(') {
      ++at_;
      auto inner = sum();
      expect(')', "')'");
      return inner;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      const char* begin = text_.c_str() + at_;
      char* end = nullptr;
      const double value = std::strtod(begin, &end);
      if (end == begin) fail(at_, "expected a number");
      at_ += static_cast<std::size_t>(end - begin);
      auto e = node(Kind::kNumber);
      e->number = value;
      return e;
    }
    const std::size_t start = at_;
    const std::string name = identifier();
    if (name.empty()) fail(start, "expected a value, a measure or a function, found '" + std::string(1, c) + "'");
    if (accept('(')) return call(name, start);
    if (name == "modules") return node(Kind::kModules);
    for (int k = 0; k < 6; ++k) {
      if (name == kSceneNames[k]) {
        needs_scene_ = true;
        auto e = node(Kind::kScene);
        e->index = k;
        return e;
      }
    }
    for (std::size_t k = 0; k < earlier_.size(); ++k) {
      if (earlier_[k].name == name) {
        auto e = node(Kind::kMeasure);
        e->index = static_cast<int>(k);
        return e;
      }
    }
    fail(start, "unknown name '" + name + "' in the measure '" + spec_.name +
                    "' (a measure above it, modules, height, width, depth, segment_length, segments, leaf_area, "
                    "or a function: count, sum, mean, min, max, sqrt, log, exp, abs)");
  }
  std::unique_ptr<Expression> call(const std::string& name, std::size_t start) {
    static const std::map<std::string, Kind> math = {{"sqrt", Kind::kSqrt}, {"log", Kind::kLog}, {"exp", Kind::kExp},
                                                     {"abs", Kind::kAbs}};
    static const std::map<std::string, Kind> stats = {{"count", Kind::kCount}, {"sum", Kind::kSum}, {"mean", Kind::kMean},
                                                      {"min", Kind::kMin}, {"max", Kind::kMax}};
    if (auto m = math.find(name); m != math.end()) {
      auto e = node(m->second, sum());
      expect(')', "')'");
      return e;
    }
    const auto s = stats.find(name);
    if (s == stats.end()) fail(start, "unknown function '" + name + "' in the measure '" + spec_.name + "'");
    const std::size_t module_at = (skip_space(), at_);
    const ModuleId id = module(module_at);
    int parameter = 0;
    if (s->second != Kind::kCount) {
      expect(',', "',' and the parameter's number (1 for the first)");
      skip_space();
      const std::size_t number_at = at_;
      const std::string digits = identifier();
      if (digits.empty() || !std::all_of(digits.begin(), digits.end(), ::isdigit) || std::stoi(digits) < 1)
        fail(number_at, "expected the parameter's number (1 for the first)");
      parameter = std::stoi(digits);
      const std::size_t arity = types_.params(id).size();
      if (!types_.params(id).empty() && static_cast<std::size_t>(parameter) > arity)
        fail(number_at, "module " + types_.name(id) + " has " + std::to_string(arity) + " parameter" +
                            (arity == 1 ? "" : "s") + ", not " + digits);
    }
    expect(')', "')'");
    const std::pair<ModuleId, int> want{id, parameter};
    auto found = std::find(wanted_.begin(), wanted_.end(), want);
    if (found == wanted_.end()) found = wanted_.insert(wanted_.end(), want);
    auto e = node(s->second);
    e->index = static_cast<int>(found - wanted_.begin());
    return e;
  }
  ModuleId module(std::size_t start) {
    std::string name;
    if (accept('"')) {
      const std::size_t close = text_.find('"', at_);
      if (close == std::string::npos) fail(start, "a module name in quotes needs its closing '\"'");
      name = text_.substr(at_, close - at_);
      at_ = close + 1;
    } else {
      name = identifier();
    }
    if (name.empty()) fail(start, "expected a module's name");
    const std::optional<ModuleId> id = types_.find(name);
    if (!id) fail(start, "the model has no module '" + name + "' (measure '" + spec_.name + "')");
    return *id;
  }

  const MeasureSpec& spec_;
  const std::string& text_;
  const std::vector<MeasureSpec>& earlier_;
  const ModuleTypes& types_;
  std::vector<std::pair<ModuleId, int>>& wanted_;
  bool& needs_scene_;
  std::size_t at_ = 0;
};

double triangle_area(const geometry::Vec3& a, const geometry::Vec3& b, const geometry::Vec3& c) {
  const geometry::Vec3 u = b - a, v = c - a;
  const double x = double(u.y) * v.z - double(u.z) * v.y, y = double(u.z) * v.x - double(u.x) * v.z,
               z = double(u.x) * v.y - double(u.y) * v.x;
  return 0.5 * std::sqrt(x * x + y * y + z * z);
}

}  // namespace

SceneMeasures measure_scene(const geometry::Scene& scene) {
  SceneMeasures m;
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  auto take = [&](const geometry::Vec3& p, double r) {
    const double c[3] = {p.x, p.y, p.z};
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], c[k] - r);
      hi[k] = std::max(hi[k], c[k] + r);
    }
  };
  for (const geometry::Segment& s : scene.segments) {
    take(s.start, 0);
    take(s.end, 0);
    const geometry::Vec3 d = s.end - s.start;
    m.segment_length += std::sqrt(double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z);
  }
  m.segments = static_cast<double>(scene.segments.size());
  for (const geometry::Circle& c : scene.circles) take(c.center, c.radius);
  for (const geometry::Sphere& s : scene.spheres) take(s.center, s.radius);
  for (const geometry::TriangleGroup& g : scene.groups) {
    using K = geometry::TriangleGroup::Kind;
    const bool leaf = g.kind == K::Polygon || g.kind == K::Rhombus || g.kind == K::Triangle || g.kind == K::Surface;
    for (std::uint32_t i = g.first_index; i + 2 < g.first_index + g.index_count; i += 3) {
      const geometry::Vec3& a = scene.positions[scene.indices[i]];
      const geometry::Vec3& b = scene.positions[scene.indices[i + 1]];
      const geometry::Vec3& c = scene.positions[scene.indices[i + 2]];
      take(a, 0);
      take(b, 0);
      take(c, 0);
      if (leaf) m.leaf_area += triangle_area(a, b, c);
    }
  }
  if (lo[0] <= hi[0]) {
    m.width = hi[0] - lo[0];
    m.height = hi[1] - lo[1];
    m.depth = hi[2] - lo[2];
  }
  return m;
}

Measures::Measures(const std::vector<MeasureSpec>& specs, const ModuleTypes& types) {
  std::vector<MeasureSpec> earlier;
  for (const MeasureSpec& spec : specs) {
    expressions_.push_back(Parser(spec, earlier, types, wanted_, needs_scene_).parse());
    earlier.push_back(spec);
  }
  feeds_.resize(types.size());
  for (std::size_t w = 0; w < wanted_.size(); ++w) feeds_[wanted_[w].first].push_back(static_cast<int>(w));
}

Measures::~Measures() = default;
Measures::Measures(Measures&&) noexcept = default;

bool Measures::needs_scene() const { return needs_scene_; }

std::vector<double> Measures::evaluate(const ModuleString& string, const ModuleTypes& types,
                                       const geometry::Scene* scene) const {
  Summary summary;
  summary.stats.resize(wanted_.size());
  const StringView view = string.view(types);
  for (std::size_t at = view.begin; at < view.end; at = view.next(at)) {
    ++summary.modules;
    const ModuleId id = view.id_at(at);
    if (feeds_[id].empty()) continue;
    std::vector<double> numbers;
    bool read = false;
    for (int w : feeds_[id]) {
      Stat& stat = summary.stats[w];
      ++stat.count;
      const int parameter = wanted_[w].second;
      if (parameter == 0) continue;
      if (!read) {
        numbers = types.numbers(id, module_params(view.data, at));
        read = true;
      }
      const double value = static_cast<std::size_t>(parameter) <= numbers.size() ? numbers[parameter - 1] : kNotANumber;
      stat.sum += value;
      stat.min = std::isnan(stat.min) ? value : std::min(stat.min, value);
      stat.max = std::isnan(stat.max) ? value : std::max(stat.max, value);
    }
  }
  if (scene) summary.scene = measure_scene(*scene);
  std::vector<double> values;
  for (const auto& e : expressions_) {
    values.push_back(sylva::experiment::evaluate(*e, summary));
    summary.earlier.push_back(values.back());
  }
  return values;
}

}  // namespace sylva::experiment
