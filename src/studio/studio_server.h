// The studio's web server: the page, the model folder's files, and the API
// the page calls (docs/studio.md lists it), over one ModelSession.
#pragma once

#include <memory>
#include <string>

namespace sylva::studio {

class ModelSession;

struct ServerOptions {
  std::string address = "127.0.0.1";
  int port = 0;        // 0: a free port
  // Required on every request when not empty (a cookie set by the page's
  // first load with ?token=, a ?token= query or an X-Sylva-Token header).
  std::string token;
};

class StudioServer {
 public:
  StudioServer(ModelSession& session, ServerOptions options);
  ~StudioServer();
  // Binds; returns the port. Throws std::runtime_error when it cannot.
  int bind();
  // Serves until stop() (from another thread or a signal handler's thread).
  void serve();
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// A token of 32 random hexadecimal digits, from the system's random source.
std::string make_token();

}  // namespace sylva::studio
