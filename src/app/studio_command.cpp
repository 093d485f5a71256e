#include "app/studio_command.h"

#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <thread>

#include "studio/file_watcher.h"
#include "studio/model_session.h"
#include "studio/studio_server.h"
#include "studio/worker.h"

namespace sylva::app {
namespace {

// Ctrl-C (or a TERM) ends the server's loop and stops the model's worker;
// the session then removes its copies of changed files. The signals are
// taken by a thread of their own (every other thread blocks them), which may
// call anything, unlike a signal handler.
void stop_on_signal(studio::StudioServer& server, studio::ModelSession& session) {
  static sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
  std::thread([&server, &session] {
    int signal = 0;
    sigwait(&stop_signals, &signal);
    session.interrupt();
    server.stop();
  }).detach();
}

}  // namespace

CLI::App* add_studio_command(CLI::App& app, StudioOptions& o) {
  CLI::App* studio = app.add_subcommand(
      "studio", "Show a model in the browser: 3D view, animation, live reload on save, parameter panels");
  studio->add_option("files", o.files, "The model and its input files, as `sylva run` takes them")
      ->type_name("FILE...");
  studio->add_option("--port", o.port, "The port to listen on (default: a free one)")->check(CLI::Range(0, 65535));
  studio->add_option("--listen", o.listen,
                     "Listen on ADDR instead of 127.0.0.1 (reachable from other machines: requests then need "
                     "the printed token)")
      ->type_name("ADDR");
  studio->add_option("--time-limit", o.time_limit_seconds,
                     "Seconds one step (or a run to a frame) may take before the model is stopped (default 60)")
      ->check(CLI::PositiveNumber);
  studio->add_option("--memory-limit", o.memory_limit_mb, "Megabytes of memory a model may use (default 8192)")
      ->check(CLI::Range(64, 1 << 30));
  studio->add_option("--instances-above", o.instances_above,
                     "Send a scene's spheres and cylinders to the page as instances when it has more than N "
                     "(default 20000)")
      ->check(CLI::NonNegativeNumber)
      ->type_name("N");
  return studio;
}

int run_studio(const StudioOptions& o, const build::BuildOptions& build) {
  if (o.model.empty()) throw std::invalid_argument("no model: give the L-system file (.l) among the files");
  if (!std::filesystem::is_regular_file(o.model)) throw std::invalid_argument("no such model file: " + o.model);
  studio::SessionOptions session_options;
  session_options.model = o.model;
  session_options.inputs = o.inputs;
  session_options.cache_dir = build.cache_dir;
  session_options.compiler = build.compiler;
  session_options.language = build.language;
  session_options.defines = build.defines;
  session_options.worker_command = {std::filesystem::read_symlink("/proc/self/exe").string(), kStudioWorkerCommand};
  session_options.limits.memory_bytes = static_cast<std::size_t>(o.memory_limit_mb) << 20;
  session_options.time_limit_seconds = o.time_limit_seconds;
  session_options.instances_above = o.instances_above;
  signal(SIGPIPE, SIG_IGN);  // a page closed mid-answer, a worker gone mid-request
  studio::ModelSession session(session_options);

  studio::ServerOptions server_options;
  if (!o.listen.empty()) {
    server_options.address = o.listen;
    server_options.token = studio::make_token();
  }
  server_options.port = o.port;
  studio::StudioServer server(session, server_options);
  const int port = server.bind();
  const std::string host = server_options.address.find(':') != std::string::npos ? "[" + server_options.address + "]"
                                                                                 : server_options.address;
  std::printf("Sylva Studio: http://%s:%d/%s\n", host.c_str(), port,
              server_options.token.empty() ? "" : ("?token=" + server_options.token).c_str());
  std::fflush(stdout);

  stop_on_signal(server, session);
  // The first picture, then one after every save, on threads of their own
  // so the page is served meanwhile.
  std::thread first([&session] { session.reload(); });
  studio::FileWatcher watcher([&session] { return session.watched_files(); },
                              [&session] { session.reload_if_changed(); });
  server.serve();
  session.interrupt();
  first.join();
  return 0;
}

int run_studio_worker() { return studio::run_worker(3, 4); }

}  // namespace sylva::app
