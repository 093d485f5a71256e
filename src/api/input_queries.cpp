#include "api/input_queries.h"

#include <algorithm>
#include <cmath>

#include "geometry/contour_edit.h"
#include "sylva/abi.h"

namespace sylva {
namespace {

using geometry::Vec3;

// Points along a curve by arc length, fine enough that linear interpolation
// between them stays within a fraction of a percent of the curve.
constexpr int kCurveSamples = 512;

Vec3 curve_point(const geometry::Contour& contour, const std::vector<Vec3>& points, double s, Vec3* tangent) {
  if (points.empty()) return {};
  const int segments = contour.closed ? kCurveSamples : kCurveSamples - 1;
  double t = std::clamp(s, 0.0, 1.0) * segments;
  int k = std::min(static_cast<int>(t), segments - 1);
  float f = static_cast<float>(t - k);
  const Vec3& a = points[static_cast<std::size_t>(k)];
  const Vec3& b = points[static_cast<std::size_t>((k + 1) % kCurveSamples)];
  if (tangent) *tangent = geometry::normalized(b - a);
  return a + (b - a) * f;
}

}  // namespace

bool answer_input_query(void* answers, int query, int id, const double* in, double* out) {
  return static_cast<InputAnswers*>(answers)->answer(query, id, in, out);
}

struct InputAnswers::Evaluators {
  std::unique_ptr<geometry::LpfgFunction> lpfg;
  std::unique_ptr<geometry::CpfgFunction> cpfg;
  // The interval tfunc maps onto [0,1]: the .tset file's, until pfunc sets it.
  float low = 0, up = 1;
};

InputAnswers::InputAnswers(io::InputFiles& files)
    : files_(files),
      functions_(files.functions.size()),
      // curveScale and kin change contours even where the curve functions read cpfg's curves.
      curves_(std::max(files.contours.size(), files.curves.size())),
      cpfg_curves_(files.curves.size()) {
  for (std::size_t k = 0; k < functions_.size(); ++k) {
    functions_[k].low = files_.functions[k].low;
    functions_[k].up = files_.functions[k].up;
  }
}

InputAnswers::~InputAnswers() = default;

bool InputAnswers::answer_function(int query, int id, const double* in, double* out) {
  if (id < 1 || id > static_cast<int>(files_.functions.size())) return false;
  const geometry::Function& f = files_.functions[static_cast<std::size_t>(id - 1)];
  Evaluators& e = functions_[static_cast<std::size_t>(id - 1)];
  if (query == abi::kQueryParameter) {
    // lpfg keeps .vset parameters among its functions; a function has no value.
    if (!f.constant) return false;
    out[0] = *f.constant;
    return true;
  }
  if (f.constant) return false;  // a parameter has no curve
  if (query == abi::kQueryFunctionLimits) {
    e.low = static_cast<float>(in[0]);
    e.up = static_cast<float>(in[1]);
    return true;
  }
  if (query == abi::kQueryCpfgFunction) {
    if (!e.cpfg) e.cpfg = std::make_unique<geometry::CpfgFunction>(f);
    out[0] = e.cpfg->value(in[0]);
    return true;
  }
  if (!e.lpfg) e.lpfg = std::make_unique<geometry::LpfgFunction>(f);
  float x = static_cast<float>(in[0]);
  // tfunc, pfunc and funcTangent map x from the function's interval onto [0,1].
  if (query != abi::kQueryFunction) x = (x - e.low) / (e.up - e.low);
  if (query == abi::kQueryFunctionTangent) {
    const geometry::Vec2 t = e.lpfg->tangent(x);
    out[0] = t.x;
    out[1] = t.y;
    out[2] = 0;
  } else {
    out[0] = e.lpfg->value(x);
  }
  return true;
}

bool InputAnswers::answer_surface(int query, int id, const double* in, double* out) const {
  if (id < 0 || id >= static_cast<int>(files_.surfaces.size())) return false;
  const std::vector<geometry::BezierPatch>& patches = files_.surfaces[static_cast<std::size_t>(id)].patches;
  if (query == abi::kQuerySurfacePatch) {
    if (patches.empty()) return false;
    for (int k = 0; k < 16; ++k) {
      out[3 * k] = patches.front().points[k].x;
      out[3 * k + 1] = patches.front().points[k].y;
      out[3 * k + 2] = patches.front().points[k].z;
    }
    return true;
  }
  // GetSurfacePoint: point k of patch p is 16 p + k.
  const int point = static_cast<int>(in[0]);
  if (point < 0 || point / 16 >= static_cast<int>(patches.size())) return false;
  const geometry::Vec3 p = patches[static_cast<std::size_t>(point / 16)].points[point % 16];
  out[0] = p.x;
  out[1] = p.y;
  out[2] = p.z;
  return true;
}

const std::vector<Vec3>& InputAnswers::curve(int id) {
  std::vector<Vec3>& samples = curves_[static_cast<std::size_t>(id - 1)];
  if (samples.empty()) samples = curve_source()[static_cast<std::size_t>(id - 1)].resample(kCurveSamples);
  return samples;
}

const geometry::CpfgCurve& InputAnswers::cpfg_curve(int id) {
  std::unique_ptr<geometry::CpfgCurve>& curve = cpfg_curves_[static_cast<std::size_t>(id - 1)];
  if (!curve) {
    const geometry::Contour& contour = files_.curves[static_cast<std::size_t>(id - 1)];
    curve = std::make_unique<geometry::CpfgCurve>(contour, contour.samples);
  }
  return *curve;
}

void InputAnswers::restore_curves() {
  if (original_contours_.empty()) return;
  files_.contours = original_contours_;
  for (auto& samples : curves_) samples.clear();
}

bool InputAnswers::change_curve(int query, int id, const double* in) {
  if (id < 1 || id > static_cast<int>(files_.contours.size())) return false;
  if (original_contours_.empty()) original_contours_ = files_.contours;
  const auto k = static_cast<std::size_t>(id - 1);
  geometry::Contour& contour = files_.contours[k];
  switch (query) {
    case abi::kQueryCurveScale:
      geometry::scale_contour(contour, Vec3{static_cast<float>(in[0]), static_cast<float>(in[1]), static_cast<float>(in[2])});
      break;
    case abi::kQueryCurveSetPoint:
      // The curve functions keep their samples until curveRecalculate.
      return geometry::set_contour_point(
          contour, static_cast<int>(in[0]),
          Vec3{static_cast<float>(in[1]), static_cast<float>(in[2]), static_cast<float>(in[3])});
    case abi::kQueryCurveReset:
      contour = original_contours_[k];
      break;
    default:  // kQueryCurveRecalculate
      break;
  }
  curves_[k].clear();
  return true;
}

bool InputAnswers::answer(int query, int id, const double* in, double* out) {
  const io::InputFiles& inputs = files_;
  switch (query) {
    case abi::kQueryCurveScale:
    case abi::kQueryCurveSetPoint:
    case abi::kQueryCurveRecalculate:
    case abi::kQueryCurveReset:
      return change_curve(query, id, in);
    case abi::kQueryCpfgViewVolume: {
      // cpfg's defaults without a view file's front and back distance: -100000 and 100000.
      const geometry::ViewParameters view = inputs.view ? inputs.view->view(0) : geometry::ViewParameters{};
      const double values[7] = {0, 0, 0, 0, view.front_distance.value_or(-100000.0f),
                                view.back_distance.value_or(100000.0f), view.scale};
      for (int k = 0; k < 7; ++k) out[k] = values[k];
      return true;
    }
    case abi::kQueryParameter:
    case abi::kQueryFunction:
    case abi::kQueryTimelineFunction:
    case abi::kQueryFunctionLimits:
    case abi::kQueryFunctionTangent:
    case abi::kQueryCpfgFunction:
      return answer_function(query, id, in, out);
    case abi::kQuerySurfacePatch:
    case abi::kQuerySurfacePoint:
      return answer_surface(query, id, in, out);
    case abi::kQueryCurvePoint:
    case abi::kQueryCurveNormal: {
      if (id < 1 || id > static_cast<int>(curve_source().size())) return false;
      if (query == abi::kQueryCurvePoint && !files_.curves.empty()) {
        const Vec3 p = cpfg_curve(id).at(in[0]);
        out[0] = p.x;
        out[1] = p.y;
        out[2] = p.z;
        return true;
      }
      Vec3 tangent;
      Vec3 p = curve_point(curve_source()[static_cast<std::size_t>(id - 1)], curve(id), in[0], &tangent);
      // The normal lies in the curve's plane, to the right of the direction of travel.
      Vec3 v = query == abi::kQueryCurvePoint ? p : Vec3{tangent.y, -tangent.x, 0};
      out[0] = v.x;
      out[1] = v.y;
      out[2] = v.z;
      return true;
    }
    case abi::kQueryCurveLength: {
      if (id < 1 || id > static_cast<int>(curve_source().size())) return false;
      if (!files_.curves.empty()) {
        out[0] = cpfg_curve(id).length();
        return true;
      }
      const std::vector<Vec3>& points = curve(id);
      const geometry::Contour& contour = curve_source()[static_cast<std::size_t>(id - 1)];
      double length = 0;
      for (std::size_t k = 1; k < points.size(); ++k) length += geometry::length(points[k] - points[k - 1]);
      if (contour.closed && points.size() > 1) length += geometry::length(points.front() - points.back());
      out[0] = length;
      return true;
    }
    default:
      return false;
  }
}

std::vector<std::string> function_name_defines(const io::InputFiles& inputs) {
  std::vector<std::string> defines;
  for (std::size_t k = 0; k < inputs.functions.size(); ++k)
    if (!inputs.functions[k].name.empty()) defines.push_back(inputs.functions[k].name + "=" + std::to_string(k + 1));
  return defines;
}

}  // namespace sylva
