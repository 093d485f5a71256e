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

const std::vector<Vec3>& InputAnswers::curve(int id) {
  std::vector<Vec3>& samples = curves_[static_cast<std::size_t>(id - 1)];
  if (samples.empty()) samples = files_.contours[static_cast<std::size_t>(id - 1)].resample(kCurveSamples);
  return samples;
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
      if (id < 1 || id > static_cast<int>(inputs.parameters.size())) return false;
      out[0] = inputs.parameters[static_cast<std::size_t>(id - 1)].value;
      return true;
    case abi::kQueryFunction:
    case abi::kQueryFunctionTangent: {
      if (id < 1 || id > static_cast<int>(inputs.functions.size())) return false;
      const geometry::Function& f = inputs.functions[static_cast<std::size_t>(id - 1)];
      if (query == abi::kQueryFunction) {
        // pfunc: x in [min,max] is mapped onto the function's [0,1].
        double min = in[1], max = in[2];
        double x = max > min ? (std::clamp(in[0], min, max) - min) / (max - min) : std::clamp(in[0], 0.0, 1.0);
        out[0] = f(static_cast<float>(x));
      } else {
        const double h = 1e-3;
        double x = std::clamp(in[0], h, 1.0 - h);
        double dy = (f(static_cast<float>(x + h)) - f(static_cast<float>(x - h))) / (2 * h);
        double length = std::sqrt(1 + dy * dy);
        out[0] = 1 / length;
        out[1] = dy / length;
      }
      return true;
    }
    case abi::kQueryCurvePoint:
    case abi::kQueryCurveNormal: {
      if (id < 1 || id > static_cast<int>(inputs.contours.size())) return false;
      Vec3 tangent;
      Vec3 p = curve_point(inputs.contours[static_cast<std::size_t>(id - 1)], curve(id), in[0], &tangent);
      // The normal lies in the curve's plane, to the right of the direction of travel.
      Vec3 v = query == abi::kQueryCurvePoint ? p : Vec3{tangent.y, -tangent.x, 0};
      out[0] = v.x;
      out[1] = v.y;
      out[2] = v.z;
      return true;
    }
    case abi::kQueryCurveLength: {
      if (id < 1 || id > static_cast<int>(inputs.contours.size())) return false;
      const std::vector<Vec3>& points = curve(id);
      const geometry::Contour& contour = inputs.contours[static_cast<std::size_t>(id - 1)];
      double length = 0;
      for (std::size_t k = 1; k < points.size(); ++k) length += geometry::length(points[k] - points[k - 1]);
      if (contour.closed && points.size() > 1) length += geometry::length(points.front() - points.back());
      out[0] = length;
      return true;
    }
    case abi::kQuerySurfacePatch: {
      if (id < 0 || id >= static_cast<int>(inputs.surfaces.size()) || inputs.surfaces[id].patches.empty())
        return false;
      const geometry::BezierPatch& patch = inputs.surfaces[static_cast<std::size_t>(id)].patches.front();
      for (int k = 0; k < 16; ++k) {
        out[3 * k] = patch.points[k].x;
        out[3 * k + 1] = patch.points[k].y;
        out[3 * k + 2] = patch.points[k].z;
      }
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

std::vector<std::string> parameter_name_defines(const io::InputFiles& inputs) {
  std::vector<std::string> defines;
  for (std::size_t k = 0; k < inputs.parameters.size(); ++k)
    defines.push_back(inputs.parameters[k].name + "=" + std::to_string(k + 1));
  return defines;
}

}  // namespace sylva
