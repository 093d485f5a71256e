// The door to the HTTP plugin, libsylva_http.so: cpp-httplib's server, kept
// out of the program until the studio serves (support/plugin_library.h).
// Debian's cpp-httplib is a shared library linking OpenSSL, zlib and brotli;
// loading those seven libraries took every run of the program about 3 ms
// before it read its model.
//
// The studio's routes are written against these few classes alone; the
// plugin turns cpp-httplib's requests and responses into them.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>

#include "support/plugin_library.h"

namespace sylva::studio {

class HttpRequest {
 public:
  // The header's value, or "" when the request has none.
  virtual std::string header(const std::string& name) const = 0;
  virtual bool has_param(const std::string& name) const = 0;
  // The query or form parameter's value, or "" when the request has none.
  virtual std::string param(const std::string& name) const = 0;
  // The route pattern's group `index` (1 for the first) in the path.
  virtual std::string match(std::size_t index) const = 0;
  virtual const std::string& body() const = 0;

 protected:
  ~HttpRequest() = default;
};

class HttpResponse {
 public:
  virtual void set_status(int status) = 0;
  virtual void set_header(const std::string& name, const std::string& value) = 0;
  virtual void set_content(std::string body, const std::string& content_type) = 0;
  // Sends `body` as it is, without copying it; the response holds it until sent.
  virtual void set_shared_content(std::shared_ptr<const std::string> body, const std::string& content_type) = 0;

 protected:
  ~HttpResponse() = default;
};

using HttpHandler = std::function<void(const HttpRequest&, HttpResponse&)>;
// Sees every request before its route; true when it has answered it, and the
// route is not called.
using HttpFilter = std::function<bool(const HttpRequest&, HttpResponse&)>;

class HttpServer {
 public:
  virtual ~HttpServer() = default;
  virtual void set_filter(HttpFilter filter) = 0;
  // `pattern` is a regular expression over the path; its groups are the
  // request's matches.
  virtual void get(const std::string& pattern, HttpHandler handler) = 0;
  virtual void post(const std::string& pattern, HttpHandler handler) = 0;
  // Binds to `port` on `address`, any free port when 0; the port, or -1 when
  // it cannot.
  virtual int bind(const std::string& address, int port) = 0;
  // Serves until stop() (from another thread).
  virtual void listen() = 0;
  virtual void stop() = 0;
};

}  // namespace sylva::studio

// A new server, without routes; the caller owns it.
extern "C" SYLVA_PLUGIN_EXPORT sylva::studio::HttpServer* sylva_new_http_server();
