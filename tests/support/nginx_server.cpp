#include "tests/support/nginx_server.hpp"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

namespace globe::testing {
namespace {

constexpr const char* kNginx = "/usr/sbin/nginx";

int freeLoopbackPort() {
  const int s = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = 0;
  socklen_t length = sizeof address;
  int port = 0;
  if (::bind(s, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0 &&
      ::getsockname(s, reinterpret_cast<sockaddr*>(&address), &length) == 0) {
    port = ntohs(address.sin_port);
  }
  ::close(s);
  return port;
}

bool accepts(int port) {
  const int s = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(static_cast<uint16_t>(port));
  const bool ok = ::connect(s, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0;
  ::close(s);
  return ok;
}

// Sends one GET for `path` to 127.0.0.1:port and reads the answer to its end; false when the
// server does not answer (stopped).
bool answered(int port, const std::string& path) {
  const int s = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(static_cast<uint16_t>(port));
  bool ok = ::connect(s, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0;
  const std::string request = "GET " + path + " HTTP/1.0\r\n\r\n";
  ok = ok && ::send(s, request.data(), request.size(), MSG_NOSIGNAL) ==
                 static_cast<ssize_t>(request.size());
  char buffer[512];
  ssize_t got = 0;
  while (ok && (got = ::recv(s, buffer, sizeof buffer, 0)) > 0) {
  }
  ::close(s);
  return ok && got == 0;
}

std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::unique_ptr<NginxServer> NginxServer::start(const Options& options) {
  std::unique_ptr<NginxServer> server(new NginxServer());
  if (!std::filesystem::exists(kNginx)) {
    ADD_FAILURE() << kNginx << " is missing: install nginx-light (tools/install-deps.sh)";
    return nullptr;
  }
  static int counter = 0;
  server->dir_ = std::filesystem::temp_directory_path() /
                 ("globe_nginx_" + std::to_string(::getpid()) + "_" + std::to_string(++counter));
  std::filesystem::remove_all(server->dir_);
  std::filesystem::create_directories(server->dir_ / "tmp");
  server->port_ = options.port != 0 ? options.port : freeLoopbackPort();
  server->syncPort_ = freeLoopbackPort();
  server->tls_ = !options.certificate.empty() && !options.key.empty();
  const std::string d = server->dir_.string();
  {
    std::ofstream conf(server->dir_ / "nginx.conf");
    // One process, in the foreground, as the test's user: no daemon to lose track of.
    conf << "daemon off;\nmaster_process off;\nworker_processes 1;\n"
         << "pid " << d << "/nginx.pid;\nerror_log " << d << "/error.log warn;\n"
         << "events { worker_connections 256; }\n"
         << "http {\n"
         << "  log_format ranges '$request_method $uri $status \"$http_range\" $bytes_sent "
            "$server_protocol ?$args';\n"
         << "  access_log " << d << "/access.log ranges;\n"
         << "  client_body_temp_path " << d << "/tmp/body;\n"
         << "  proxy_temp_path " << d << "/tmp/proxy;\n"
         << "  fastcgi_temp_path " << d << "/tmp/fastcgi;\n"
         << "  uwsgi_temp_path " << d << "/tmp/uwsgi;\n"
         << "  scgi_temp_path " << d << "/tmp/scgi;\n"
         << "  types { application/json json; }\n"
         << "  default_type application/octet-stream;\n"
         << "  keepalive_requests 10000;\n"
         << "  server {\n"
         << "    listen 127.0.0.1:" << server->port_ << (server->tls_ ? " ssl http2" : "") << ";\n"
         << (server->tls_ ? "    ssl_certificate " + options.certificate.string() +
                                ";\n    ssl_certificate_key " + options.key.string() + ";\n"
                          : std::string())
         << "    root " << std::filesystem::absolute(options.root).string() << ";\n"
         << options.serverDirectives << "\n"
         << "  }\n"
         // accessLog's marker requests: answered and logged by the same single worker, after
         // every request it finished before them (nginx logs a request once it is answered).
         << "  server {\n"
         << "    listen 127.0.0.1:" << server->syncPort_ << ";\n"
         << "    access_log " << d << "/sync.log ranges;\n"
         << "    location / { return 204; }\n"
         << "  }\n"
         << "}\n";
  }
  const pid_t pid = ::fork();
  if (pid == 0) {
    // `timeout`: the server stops by itself even if the test dies without stopping it.
    const std::string conf = d + "/nginx.conf";
    const std::string errors = d + "/error.log";
    ::execl("/usr/bin/timeout", "timeout", "-k", "5", "600", kNginx, "-p", d.c_str(), "-c",
            conf.c_str(), "-e", errors.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  server->pid_ = pid;
  // Until it accepts (a few ms), or exits, or 5 s have passed.
  for (int i = 0; i < 2500; ++i) {
    if (accepts(server->port_)) return server;
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) == pid) {
      server->pid_ = -1;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ADD_FAILURE() << "nginx did not start on 127.0.0.1:" << server->port_ << ":\n"
                << readText(server->dir_ / "error.log");
  return nullptr;
}

NginxServer::~NginxServer() {
  stop();
  std::error_code ignored;
  std::filesystem::remove_all(dir_, ignored);
}

void NginxServer::stop() {
  if (pid_ <= 0) return;
  ::kill(pid_, SIGTERM);  // timeout passes it on to nginx
  int status = 0;
  ::waitpid(pid_, &status, 0);
  pid_ = -1;
}

std::string NginxServer::url(const std::string& path) const {
  return (tls_ ? "https" : "http") + std::string("://127.0.0.1:") + std::to_string(port_) +
         (path.empty() || path[0] != '/' ? "/" : "") + path;
}

std::vector<std::string> NginxServer::accessLog() const {
  // A client may be done before nginx has logged its last request. A marker request to the
  // same worker is handled after it logged every request it answered before; once the marker's
  // own line is in sync.log (written just after its answer) access.log holds all of them.
  static int markers = 0;
  const std::string marker = "/marker-" + std::to_string(++markers);
  if (running() && answered(syncPort_, marker)) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (readText(dir_ / "sync.log").find(marker + " ") == std::string::npos &&
           std::chrono::steady_clock::now() < deadline) {
      std::this_thread::yield();
    }
  }
  std::ifstream in(dir_ / "access.log");
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

}  // namespace globe::testing
