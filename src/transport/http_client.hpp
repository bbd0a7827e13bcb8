// A small blocking HTTP client over libcurl's multi interface: one event-loop thread drives every
// transfer, so the loader's worker threads share one connection pool (keep-alive, a bounded number
// of connections per host, HTTP/2 multiplexing where the server offers it).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace globe::transport {

struct HttpSettings {
  long connectTimeoutMs = 10'000;
  // A transfer that receives (almost) nothing for this long is abandoned: a stalled server. With
  // one retry for a timeout, a request to a stalled server fails in about 16 s.
  long stallTimeoutMs = 8'000;
  long totalTimeoutMs = 30'000;  // a trickle that never stalls still ends
  long maxConnectionsPerHost = 16;
  bool verifyTls = true;
  std::string caFile;  // PEM certificates to trust instead of the system's (empty: the system's)
};

struct HttpRequest {
  std::string url;
  bool ranged = false;  // ask for rangeBytes (> 0) bytes at rangeOffset
  uint64_t rangeOffset = 0;
  uint64_t rangeBytes = 0;
  std::string ifNoneMatch;  // an ETag: 304 when the server's copy still has it
  std::string accept;       // the Accept header, when not empty
  // A longer body is cut off (HttpResponse::bodyTooLong): a server cannot make the viewer
  // allocate more than its caller expects.
  size_t maxBodyBytes = 0;
};

struct HttpResponse {
  long status = 0;             // the final response's status; 0 when none came
  std::string transportError;  // why no complete response came (curl's words); empty when one did
  bool timedOut = false;
  bool bodyTooLong = false;
  std::vector<std::byte> body;
  std::string etag;
  std::string lastModified;
  std::string contentRange;  // "bytes FIRST-LAST/TOTAL" as sent
  // Cache-Control's max-age in seconds (0 for no-cache or no-store); -1 when it says neither.
  long maxAgeSeconds = -1;
};

class HttpClient {
 public:
  explicit HttpClient(HttpSettings settings = {});
  ~HttpClient();  // abandons transfers still running (they end with a transport error)
  HttpClient(const HttpClient&) = delete;
  HttpClient& operator=(const HttpClient&) = delete;

  // Runs one request to its end; thread-safe. Redirects are followed only within the request's
  // own scheme; only http and https are spoken.
  HttpResponse perform(const HttpRequest& request);

  const HttpSettings& settings() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

bool isHttpUrl(const std::string& location);

// Parses "bytes FIRST-LAST/TOTAL"; false when it is not that.
bool parseContentRange(const std::string& value, uint64_t* first, uint64_t* last, uint64_t* total);

}  // namespace globe::transport
