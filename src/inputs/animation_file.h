// The animation file (.a, LPFG manual 8.2): which derivation steps become
// frames, and how frames follow each other.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace sylva::io {

// cpfg's "frame intervals: 1-50, 60-100 step 5": frames from..to every step.
struct FrameInterval {
  int from = 0;
  int to = 0;
  std::optional<int> step;  // the file's step: when absent
};

struct AnimationFile {
  std::string path;
  int first_frame = 0;
  std::optional<int> last_frame;  // the derivation length when absent (or negative in the file)
  int step = 1;                   // derivation steps between frames
  float swap_interval = 0;        // hundredths of a second between frames
  std::vector<FrameInterval> intervals;  // cpfg; when given, they alone say which steps are frames
  bool stepno_frame_numbers = false;     // lpfg's "frame numbers: stepno" (else consecutive)
  std::string frame_dump_path;           // lpfg's "frame dump path:"
  bool double_buffer = true;
  bool clear_between_frames = true;
  bool center_between_frames = false;   // cpfg
  bool hcenter_between_frames = false;
  bool scale_between_frames = false;
  bool new_view_between_frames = false;
  bool display_on_request = false;  // only DisplayFrame() and the first and last frame are shown
  // Sylva's own, for a differential L-system run in continuous time
  // (docs/continuous-time.md): "end time: T" and "time step: DT", what
  // --time and --dt give on the command line.
  std::optional<double> end_time;
  std::optional<double> time_step;
  // "file:line:column: warning: ..." for commands lpfg does not know.
  std::vector<std::string> warnings;

  // The derivation steps drawn as frames, for a model of `derivation_length` steps.
  std::vector<int> frames(int derivation_length) const;
};

// Read as tolerantly as lpfg and cpfg read it: they never stop on an
// animation file, so neither does Sylva. Comments (/* */ and //) are
// allowed; an unknown command or a value that cannot be read is a warning
// at its line and column, and the setting keeps its default. A number is
// read as C's %d reads one ("130 " and "12x" are 130 and 12).
AnimationFile read_animation_file(const std::string& path);

}  // namespace sylva::io
