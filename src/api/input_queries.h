// Answers a model's questions about its input files (func, curveXYZ,
// GetSurface ...; LPFG manual 6.2) from the files read at start.
#pragma once

#include <memory>

#include "geometry/curve_cpfg.h"
#include "inputs/input_files.h"

namespace sylva {

// What a model asks of its input files, with each curve sampled once (models
// call curveX and the like per module, every step). curveScale, curveSetPoint
// and curveReset change the contours in `files` themselves, so the turtle
// draws the changed ones.
class InputAnswers {
 public:
  explicit InputAnswers(io::InputFiles& files);
  ~InputAnswers();
  bool answer(int query, int id, const double* in, double* out);
  // Every contour back as read (a new run).
  void restore_curves();

 private:
  // What the curve functions read: cpfg's curves where a cpfg view file
  // gives them, else the contours.
  const std::vector<geometry::Contour>& curve_source() const {
    return files_.curves.empty() ? files_.contours : files_.curves;
  }
  // The functions' answers (func, tfunc, pfunc, funcTangent, val; cpfg's func).
  bool answer_function(int query, int id, const double* in, double* out);
  bool answer_surface(int query, int id, const double* in, double* out) const;
  // Curve id (from 1) sampled evenly by arc length; empty if no such id.
  const std::vector<geometry::Vec3>& curve(int id);
  bool change_curve(int query, int id, const double* in);

  io::InputFiles& files_;
  // Each function as lpfg and as cpfg evaluate it, made on first use.
  struct Evaluators;
  std::vector<Evaluators> functions_;
  std::vector<std::vector<geometry::Vec3>> curves_;
  // cpfg's curves (InputFiles::curves) as cpfg evaluates them, made on first use.
  const geometry::CpfgCurve& cpfg_curve(int id);
  std::vector<std::unique_ptr<geometry::CpfgCurve>> cpfg_curves_;
  // The contours as read, kept from the first change on for curveReset.
  std::vector<geometry::Contour> original_contours_;
};

// The ControlState::input_query callback; `answers` is an InputAnswers.
bool answer_input_query(void* answers, int query, int id, const double* in, double* out);

// "-D name=id" for every function and parameter of the input files, as lpfg
// defines them (ids from 1 in lpfg's order, InputFiles::functions), so models
// can write func(name, x) and val(name).
std::vector<std::string> function_name_defines(const io::InputFiles& inputs);

}  // namespace sylva
