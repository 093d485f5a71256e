// Notices when files change, by looking at their modification times and
// sizes a few times a second: it works the same on every file system (a
// network home folder, a container's bind mount), where change notification
// does not. Editors that save by writing a new file and renaming it over
// the old one are seen as a change too.
#pragma once

#include <atomic>
#include <functional>
#include <map>
#include <string>
#include <thread>
#include <vector>

namespace sylva::studio {

class FileWatcher {
 public:
  // `files()` names the files to watch (asked again every round, so a new
  // file of the folder is watched too); `changed()` is called, on the
  // watcher's thread, once a change has settled (nothing changed for one
  // more round: an editor's save is complete).
  FileWatcher(std::function<std::vector<std::string>()> files, std::function<void()> changed,
              int interval_ms = 250);
  ~FileWatcher();

 private:
  using Stamps = std::map<std::string, std::pair<long long, long long>>;  // path -> (mtime ns, size)
  Stamps stamps() const;
  void watch();

  std::function<std::vector<std::string>()> files_;
  std::function<void()> changed_;
  int interval_ms_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace sylva::studio
