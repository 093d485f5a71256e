#include "studio/studio_server.h"

#include <fstream>
#include <random>

#include "studio/http_plugin.h"
#include "studio/model_session.h"
#include "studio/served_path.h"
#include "studio/web_assets.h"
#include "support/whole_file.h"

namespace sylva::studio {
namespace {

using nlohmann::json;

void send_json(HttpResponse& res, const json& body, int status = 200) {
  res.set_status(status);
  res.set_content(body.dump(), "application/json");
  res.set_header("Cache-Control", "no-store");
}

void send_error(HttpResponse& res, int status, const std::string& message) {
  send_json(res, {{"error", message}}, status);
}

json body_json(const HttpRequest& req) {
  if (req.body().empty()) return json::object();
  json body = json::parse(req.body(), nullptr, false);
  if (body.is_discarded() || !body.is_object()) throw std::invalid_argument("the request's body is not a JSON object");
  return body;
}

int int_param(const HttpRequest& req, const char* name, int fallback) {
  if (!req.has_param(name)) return fallback;
  try {
    return std::stoi(req.param(name));
  } catch (const std::exception&) {
    throw std::invalid_argument(std::string("the parameter ") + name + " is not a number");
  }
}

const char* content_type_of(const std::string& path) {
  const std::string ext = path.substr(path.find_last_of('.') + 1);
  if (ext == "png") return "image/png";
  if (ext == "svg") return "image/svg+xml";
  if (ext == "pdf") return "application/pdf";
  if (ext == "glb") return "model/gltf-binary";
  if (ext == "ps" || ext == "eps") return "application/postscript";
  if (ext == "ply") return "application/octet-stream";
  return "text/plain; charset=utf-8";
}

// Whether the request comes for this server by a name it answers to: a web
// page elsewhere cannot reach a loopback server through a name of its own
// (DNS rebinding).
bool host_allowed(const HttpRequest& req, const std::string& address, int port) {
  std::string host = req.header("Host");
  const std::string suffix = ":" + std::to_string(port);
  if (host.size() > suffix.size() && host.compare(host.size() - suffix.size(), suffix.size(), suffix) == 0)
    host.resize(host.size() - suffix.size());
  return host == "127.0.0.1" || host == "localhost" || host == "[::1]" || host == address ||
         (address == "0.0.0.0" || address == "::");
}

std::string cookie_token(const HttpRequest& req) {
  const std::string cookies = req.header("Cookie");
  const std::string key = "sylva_token=";
  const std::size_t at = cookies.find(key);
  if (at == std::string::npos) return "";
  const std::size_t end = cookies.find(';', at);
  return cookies.substr(at + key.size(), end == std::string::npos ? std::string::npos : end - at - key.size());
}

}  // namespace

struct StudioServer::Impl {
  ModelSession& session;
  ServerOptions options;
  std::unique_ptr<HttpServer> http{reinterpret_cast<HttpServer* (*)()>(plugin_symbol(
      "libsylva_http.so", "sylva_new_http_server", "serves the studio"))()};
  int port = 0;

  Impl(ModelSession& s, ServerOptions o) : session(s), options(std::move(o)) { routes(); }

  // Runs `work`, answering bad requests with 400 and failures with 500.
  template <typename Work>
  static void guarded(HttpResponse& res, Work&& work) {
    try {
      work();
    } catch (const std::invalid_argument& e) {
      send_error(res, 400, e.what());
    } catch (const std::exception& e) {
      send_error(res, 500, e.what());
    }
  }

  void routes() {
    http->set_filter([this](const HttpRequest& req, HttpResponse& res) {
      if (!host_allowed(req, options.address, port)) {
        send_error(res, 403, "this server answers only to its own address");
        return true;
      }
      if (!options.token.empty()) {
        const bool carried = req.param("token") == options.token || req.header("X-Sylva-Token") == options.token ||
                             cookie_token(req) == options.token;
        if (!carried) {
          send_error(res, 403, "this studio needs its token: open the address it printed");
          return true;
        }
        // The page's later requests carry it as a cookie.
        if (req.param("token") == options.token)
          res.set_header("Set-Cookie", "sylva_token=" + options.token + "; HttpOnly; SameSite=Strict; Path=/");
      }
      return false;
    });

    auto asset = [](const std::string& name) {
      return [name](const HttpRequest&, HttpResponse& res) {
        const std::optional<WebAsset> a = web_asset(name);
        if (!a) return send_error(res, 404, "no " + name);
        res.set_content(std::string(a->content), a->content_type);
      };
    };
    http->get("/", asset("index.html"));
    http->get("/index.html", asset("index.html"));
    http->get("/studio.js", asset("studio.js"));
    http->get("/studio.css", asset("studio.css"));

    // The model folder's files, and nothing outside it.
    http->get(R"(/files/(.+))", [this](const HttpRequest& req, HttpResponse& res) {
      const std::optional<std::filesystem::path> path = served_path(session.folder(), req.match(1));
      if (!path) return send_error(res, 403, "only the model's folder is served");
      WholeFile file = read_whole_file(path->string());
      if (!file) return send_error(res, 404, "cannot read " + req.match(1));
      res.set_content(std::move(file.bytes), content_type_of(path->string()));
      res.set_header("Cache-Control", "no-store");
    });

    http->get("/api/state", [this](const HttpRequest&, HttpResponse& res) {
      send_json(res, session.state_json());
    });
    // The picture in two parts: its triangles and lines, and its instances.
    auto picture_part = [this](std::string ModelSession::Picture::*part, const char* type) {
      return [this, part, type](const HttpRequest&, HttpResponse& res) {
        auto [scene, version] = session.scene();
        if (!scene || ((*scene).*part).empty()) {
          res.set_status(204);
          return;
        }
        // The picture is shared, not copied: it outlives the answer.
        res.set_shared_content(std::shared_ptr<const std::string>(scene, &((*scene).*part)), type);
        res.set_header("X-Sylva-Scene-Version", std::to_string(version));
        res.set_header("Cache-Control", "no-store");
      };
    };
    http->get("/api/scene.glb", picture_part(&ModelSession::Picture::glb, "model/gltf-binary"));
    http->get("/api/scene-instances.bin", picture_part(&ModelSession::Picture::instances, "application/octet-stream"));

    auto post = [this](const char* path, auto action) {
      http->post(path, [this, action](const HttpRequest& req, HttpResponse& res) {
        guarded(res, [&] {
          action(body_json(req));
          send_json(res, session.state_json());
        });
      });
    };
    post("/api/step", [this](const json& body) { session.step(std::max(1, body.value("count", 1))); });
    post("/api/run", [this](const json& body) { session.run_to(body.value("to", -1)); });
    post("/api/rewind", [this](const json&) { session.rewind(); });
    post("/api/reload", [this](const json&) { session.reload(); });
    post("/api/param", [this](const json& body) {
      if (!body.contains("id") || !body.contains("value")) throw std::invalid_argument("expected {id, value}");
      session.set_parameter(body["id"].get<std::string>(), body["value"].get<int>());
    });
    post("/api/param/reset", [this](const json&) { session.reset_parameters(); });
    post("/api/param/save", [this](const json&) {
      session.save_parameters();
      session.reload();
    });

    // Questions the worker answers.
    auto ask = [this](const char* path, auto make_request, auto answer) {
      http->get(path, [this, make_request, answer](const HttpRequest& req, HttpResponse& res) {
        guarded(res, [&] { answer(req, res, session.ask(make_request(req))); });
      });
    };
    auto answer_json = [](const HttpRequest&, HttpResponse& res, const WorkerMessage& m) {
      json out = m.json;
      out.erase("ok");
      send_json(res, out);
    };
    ask("/api/string",
        [](const HttpRequest& req) {
          return json{{"op", "string"},
                      {"offset", std::max(0, int_param(req, "offset", 0))},
                      {"limit", std::max(0, int_param(req, "limit", 1000))},
                      {"search", req.param("search")}};
        },
        answer_json);
    ask("/api/counts", [](const HttpRequest&) { return json{{"op", "counts"}}; }, answer_json);
    ask("/api/module",
        [](const HttpRequest& req) {
          return json{{"op", "module"}, {"view", int_param(req, "view", 0)}, {"index", int_param(req, "index", 0)}};
        },
        answer_json);
    ask("/api/export",
        [](const HttpRequest& req) {
          const std::string format = req.has_param("format") ? req.param("format") : "png";
          static const std::vector<std::string> formats = {"png", "svg", "pdf", "ps",  "eps",
                                                           "obj", "mtl", "ply", "glb", "string"};
          if (std::find(formats.begin(), formats.end(), format) == formats.end())
            throw std::invalid_argument("unknown format '" + format + "'");
          return json{{"op", "export"},
                      {"format", format},
                      {"view", int_param(req, "view", 0)},
                      {"width", int_param(req, "width", 800)},
                      {"height", int_param(req, "height", 800)}};
        },
        [this](const HttpRequest& req, HttpResponse& res, const WorkerMessage& m) {
          std::string format = req.has_param("format") ? req.param("format") : "png";
          const std::string name =
              std::filesystem::path(session.model()).stem().string() + (format == "string" ? ".str" : "." + format);
          res.set_content(m.payload, content_type_of(name));
          res.set_header("Content-Disposition", "attachment; filename=\"" + name + "\"");
        });
  }
};

StudioServer::StudioServer(ModelSession& session, ServerOptions options)
    : impl_(std::make_unique<Impl>(session, std::move(options))) {}

StudioServer::~StudioServer() = default;

int StudioServer::bind() {
  Impl& i = *impl_;
  i.port = i.http->bind(i.options.address, i.options.port);
  if (i.port <= 0)
    throw std::runtime_error("cannot listen on " + i.options.address +
                             (i.options.port ? ":" + std::to_string(i.options.port) : std::string()));
  return i.port;
}

void StudioServer::serve() { impl_->http->listen(); }

void StudioServer::stop() { impl_->http->stop(); }

std::string make_token() {
  std::random_device random;  // the system's random source
  static const char digits[] = "0123456789abcdef";
  std::string token;
  for (int i = 0; i < 32; ++i) token += digits[random() % 16];
  return token;
}

}  // namespace sylva::studio
