// The HTTP plugin (http_plugin.h): an HttpServer over cpp-httplib. Built
// into libsylva_http.so alone, never into the program.
#include <httplib.h>

#include "studio/http_plugin.h"

namespace sylva::studio {
namespace {

class Request final : public HttpRequest {
 public:
  explicit Request(const httplib::Request& request) : request_(request) {}
  std::string header(const std::string& name) const override { return request_.get_header_value(name.c_str()); }
  bool has_param(const std::string& name) const override { return request_.has_param(name.c_str()); }
  std::string param(const std::string& name) const override { return request_.get_param_value(name.c_str()); }
  std::string match(std::size_t index) const override {
    return index < request_.matches.size() ? request_.matches[index].str() : std::string();
  }
  const std::string& body() const override { return request_.body; }

 private:
  const httplib::Request& request_;
};

class Response final : public HttpResponse {
 public:
  explicit Response(httplib::Response& response) : response_(response) {}
  void set_status(int status) override { response_.status = status; }
  void set_header(const std::string& name, const std::string& value) override {
    response_.set_header(name.c_str(), value);
  }
  void set_content(std::string body, const std::string& content_type) override {
    response_.set_content(std::move(body), content_type.c_str());
  }
  void set_shared_content(std::shared_ptr<const std::string> body, const std::string& content_type) override {
    const std::size_t size = body->size();
    response_.set_content_provider(size, content_type.c_str(),
                                   [body = std::move(body)](std::size_t offset, std::size_t length,
                                                            httplib::DataSink& sink) {
                                     sink.write(body->data() + offset, length);
                                     return true;
                                   });
  }

 private:
  httplib::Response& response_;
};

httplib::Server::Handler adapted(HttpHandler handler) {
  return [handler = std::move(handler)](const httplib::Request& req, httplib::Response& res) {
    const Request request(req);
    Response response(res);
    handler(request, response);
  };
}

class HttplibServer final : public HttpServer {
 public:
  void set_filter(HttpFilter filter) override {
    http_.set_pre_routing_handler([filter = std::move(filter)](const httplib::Request& req, httplib::Response& res) {
      const Request request(req);
      Response response(res);
      return filter(request, response) ? httplib::Server::HandlerResponse::Handled
                                       : httplib::Server::HandlerResponse::Unhandled;
    });
  }
  void get(const std::string& pattern, HttpHandler handler) override { http_.Get(pattern, adapted(std::move(handler))); }
  void post(const std::string& pattern, HttpHandler handler) override {
    http_.Post(pattern, adapted(std::move(handler)));
  }
  int bind(const std::string& address, int port) override {
    if (port == 0) return http_.bind_to_any_port(address);
    return http_.bind_to_port(address, port) ? port : -1;
  }
  void listen() override { http_.listen_after_bind(); }
  void stop() override { http_.stop(); }

 private:
  httplib::Server http_;
};

}  // namespace
}  // namespace sylva::studio

sylva::studio::HttpServer* sylva_new_http_server() { return new sylva::studio::HttplibServer(); }
