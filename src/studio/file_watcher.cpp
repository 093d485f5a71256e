#include "studio/file_watcher.h"

#include <sys/stat.h>

#include <chrono>

namespace sylva::studio {

FileWatcher::FileWatcher(std::function<std::vector<std::string>()> files, std::function<void()> changed,
                         int interval_ms)
    : files_(std::move(files)), changed_(std::move(changed)), interval_ms_(interval_ms) {
  thread_ = std::thread([this] { watch(); });
}

FileWatcher::~FileWatcher() {
  stop_ = true;
  thread_.join();
}

FileWatcher::Stamps FileWatcher::stamps() const {
  Stamps out;
  for (const std::string& path : files_()) {
    struct stat s {};
    if (::stat(path.c_str(), &s) == 0)
      out[path] = {static_cast<long long>(s.st_mtim.tv_sec) * 1000000000LL + s.st_mtim.tv_nsec,
                   static_cast<long long>(s.st_size)};
    else
      out[path] = {-1, -1};  // gone (for now: an editor's rename in progress)
  }
  return out;
}

void FileWatcher::watch() {
  Stamps seen = stamps();
  bool pending = false;
  while (!stop_) {
    std::this_thread::sleep_for(std::chrono::milliseconds(interval_ms_));
    Stamps now = stamps();
    if (now != seen) {
      seen = std::move(now);
      pending = true;  // wait for a round without change
    } else if (pending) {
      pending = false;
      changed_();
    }
  }
}

}  // namespace sylva::studio
