// The animation file (.a, LPFG manual 8.2): which derivation steps become
// frames, and how frames follow each other.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace sylva::io {

struct AnimationFile {
  std::string path;
  int first_frame = 0;
  std::optional<int> last_frame;  // the derivation length when absent
  int step = 1;                   // derivation steps between frames
  float swap_interval = 0;        // hundredths of a second between frames
  bool double_buffer = true;
  bool clear_between_frames = true;
  bool hcenter_between_frames = false;
  bool scale_between_frames = false;
  bool new_view_between_frames = false;
  bool display_on_request = false;  // only DisplayFrame() and the first and last frame are shown
  // "file:line:column: warning: ..." for commands lpfg does not know.
  std::vector<std::string> warnings;

  // The derivation steps drawn as frames, for a model of `derivation_length` steps.
  std::vector<int> frames(int derivation_length) const;
};

// Comments (/* */ and //) are allowed. A malformed value is a ModelError at
// its line and column; an unknown command is a warning.
AnimationFile read_animation_file(const std::string& path);

}  // namespace sylva::io
