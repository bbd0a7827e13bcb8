// A real nginx for the HTTP tests: started on 127.0.0.1 (never another address) at a free port
// with a generated configuration, serving one directory; stopped by the destructor, and in any
// case after ten minutes by the `timeout` it runs under, so no test leaves a server behind.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace globe::testing {

class NginxServer {
 public:
  struct Options {
    std::filesystem::path root;    // served at /
    std::string serverDirectives;  // extra lines inside server { } (locations, limit_rate ...)
    int port = 0;                  // 0: a free one
    // With both: https (and HTTP/2) with this certificate and key instead of plain http.
    std::filesystem::path certificate{};
    std::filesystem::path key{};
  };
  // Starts nginx and waits until it accepts connections; a test failure (with nginx's error
  // log) when it cannot.
  static std::unique_ptr<NginxServer> start(const Options& options);
  ~NginxServer();
  NginxServer(const NginxServer&) = delete;
  NginxServer& operator=(const NginxServer&) = delete;

  void stop();  // kills it and waits for it; idempotent
  bool running() const { return pid_ > 0; }
  int port() const { return port_; }
  // http(s)://127.0.0.1:PORT/path
  std::string url(const std::string& path) const;
  // The requests served so far (every one answered before the call): one line each, "METHOD URI STATUS
  // \"RANGE\" BYTES PROTOCOL ?QUERY".
  std::vector<std::string> accessLog() const;

 private:
  NginxServer() = default;
  std::filesystem::path dir_;
  pid_t pid_ = -1;
  int port_ = 0;
  int syncPort_ = 0;  // accessLog's marker requests (plain http)
  bool tls_ = false;
};

}  // namespace globe::testing
