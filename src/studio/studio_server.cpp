#include "studio/studio_server.h"

#include <httplib.h>

#include <fstream>
#include <random>

#include "studio/model_session.h"
#include "studio/served_path.h"
#include "studio/web_assets.h"
#include "support/whole_file.h"

namespace sylva::studio {
namespace {

using nlohmann::json;

void send_json(httplib::Response& res, const json& body, int status = 200) {
  res.status = status;
  res.set_content(body.dump(), "application/json");
  res.set_header("Cache-Control", "no-store");
}

void send_error(httplib::Response& res, int status, const std::string& message) {
  send_json(res, {{"error", message}}, status);
}

json body_json(const httplib::Request& req) {
  if (req.body.empty()) return json::object();
  json body = json::parse(req.body, nullptr, false);
  if (body.is_discarded() || !body.is_object()) throw std::invalid_argument("the request's body is not a JSON object");
  return body;
}

int int_param(const httplib::Request& req, const char* name, int fallback) {
  if (!req.has_param(name)) return fallback;
  try {
    return std::stoi(req.get_param_value(name));
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
bool host_allowed(const httplib::Request& req, const std::string& address, int port) {
  std::string host = req.get_header_value("Host");
  const std::string suffix = ":" + std::to_string(port);
  if (host.size() > suffix.size() && host.compare(host.size() - suffix.size(), suffix.size(), suffix) == 0)
    host.resize(host.size() - suffix.size());
  return host == "127.0.0.1" || host == "localhost" || host == "[::1]" || host == address ||
         (address == "0.0.0.0" || address == "::");
}

std::string cookie_token(const httplib::Request& req) {
  const std::string cookies = req.get_header_value("Cookie");
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
  httplib::Server http;
  int port = 0;

  Impl(ModelSession& s, ServerOptions o) : session(s), options(std::move(o)) { routes(); }

  // Runs `work`, answering bad requests with 400 and failures with 500.
  template <typename Work>
  static void guarded(httplib::Response& res, Work&& work) {
    try {
      work();
    } catch (const std::invalid_argument& e) {
      send_error(res, 400, e.what());
    } catch (const std::exception& e) {
      send_error(res, 500, e.what());
    }
  }

  void routes() {
    http.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
      if (!host_allowed(req, options.address, port)) {
        send_error(res, 403, "this server answers only to its own address");
        return httplib::Server::HandlerResponse::Handled;
      }
      if (!options.token.empty()) {
        const bool carried = req.get_param_value("token") == options.token ||
                             req.get_header_value("X-Sylva-Token") == options.token ||
                             cookie_token(req) == options.token;
        if (!carried) {
          send_error(res, 403, "this studio needs its token: open the address it printed");
          return httplib::Server::HandlerResponse::Handled;
        }
        // The page's later requests carry it as a cookie.
        if (req.get_param_value("token") == options.token)
          res.set_header("Set-Cookie", "sylva_token=" + options.token + "; HttpOnly; SameSite=Strict; Path=/");
      }
      return httplib::Server::HandlerResponse::Unhandled;
    });

    auto asset = [](const std::string& name) {
      return [name](const httplib::Request&, httplib::Response& res) {
        const std::optional<WebAsset> a = web_asset(name);
        if (!a) return send_error(res, 404, "no " + name);
        res.set_content(a->content.data(), a->content.size(), a->content_type);
      };
    };
    http.Get("/", asset("index.html"));
    http.Get("/index.html", asset("index.html"));
    http.Get("/studio.js", asset("studio.js"));
    http.Get("/studio.css", asset("studio.css"));

    // The model folder's files, and nothing outside it.
    http.Get(R"(/files/(.+))", [this](const httplib::Request& req, httplib::Response& res) {
      const std::optional<std::filesystem::path> path = served_path(session.folder(), req.matches[1].str());
      if (!path) return send_error(res, 403, "only the model's folder is served");
      WholeFile file = read_whole_file(path->string());
      if (!file) return send_error(res, 404, "cannot read " + req.matches[1].str());
      res.set_content(file.bytes, content_type_of(path->string()));
      res.set_header("Cache-Control", "no-store");
    });

    http.Get("/api/state", [this](const httplib::Request&, httplib::Response& res) {
      send_json(res, session.state_json());
    });
    // The picture in two parts: its triangles and lines, and its instances.
    auto picture_part = [this](std::string ModelSession::Picture::*part, const char* type) {
      return [this, part, type](const httplib::Request&, httplib::Response& res) {
        auto [scene, version] = session.scene();
        if (!scene || ((*scene).*part).empty()) {
          res.status = 204;
          return;
        }
        // The picture is shared, not copied: it outlives the answer.
        res.set_content_provider(((*scene).*part).size(), type,
                                 [scene = scene, part](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                                   sink.write(((*scene).*part).data() + offset, length);
                                   return true;
                                 });
        res.set_header("X-Sylva-Scene-Version", std::to_string(version));
        res.set_header("Cache-Control", "no-store");
      };
    };
    http.Get("/api/scene.glb", picture_part(&ModelSession::Picture::glb, "model/gltf-binary"));
    http.Get("/api/scene-instances.bin", picture_part(&ModelSession::Picture::instances, "application/octet-stream"));

    auto post = [this](const char* path, auto action) {
      http.Post(path, [this, action](const httplib::Request& req, httplib::Response& res) {
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
      http.Get(path, [this, make_request, answer](const httplib::Request& req, httplib::Response& res) {
        guarded(res, [&] { answer(req, res, session.ask(make_request(req))); });
      });
    };
    auto answer_json = [](const httplib::Request&, httplib::Response& res, const WorkerMessage& m) {
      json out = m.json;
      out.erase("ok");
      send_json(res, out);
    };
    ask("/api/string",
        [](const httplib::Request& req) {
          return json{{"op", "string"},
                      {"offset", std::max(0, int_param(req, "offset", 0))},
                      {"limit", std::max(0, int_param(req, "limit", 1000))},
                      {"search", req.get_param_value("search")}};
        },
        answer_json);
    ask("/api/counts", [](const httplib::Request&) { return json{{"op", "counts"}}; }, answer_json);
    ask("/api/module",
        [](const httplib::Request& req) {
          return json{{"op", "module"}, {"view", int_param(req, "view", 0)}, {"index", int_param(req, "index", 0)}};
        },
        answer_json);
    ask("/api/export",
        [](const httplib::Request& req) {
          const std::string format = req.has_param("format") ? req.get_param_value("format") : "png";
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
        [this](const httplib::Request& req, httplib::Response& res, const WorkerMessage& m) {
          std::string format = req.has_param("format") ? req.get_param_value("format") : "png";
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
  if (i.options.port == 0) i.port = i.http.bind_to_any_port(i.options.address);
  else i.port = i.http.bind_to_port(i.options.address, i.options.port) ? i.options.port : -1;
  if (i.port <= 0)
    throw std::runtime_error("cannot listen on " + i.options.address +
                             (i.options.port ? ":" + std::to_string(i.options.port) : std::string()));
  return i.port;
}

void StudioServer::serve() { impl_->http.listen_after_bind(); }

void StudioServer::stop() { impl_->http.stop(); }

std::string make_token() {
  std::random_device random;  // the system's random source
  static const char digits[] = "0123456789abcdef";
  std::string token;
  for (int i = 0; i < 32; ++i) token += digits[random() % 16];
  return token;
}

}  // namespace sylva::studio
