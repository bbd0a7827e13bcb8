// Whole files by URL for the tile services, whatever host each template expands to ({s}
// subdomains): one byte source per origin, all through the program's Network (its HTTP client,
// disk cache, retries and --offline), every GET with the service's Accept header. Local paths
// read as files. Thread-safe.
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "core/result.hpp"
#include "transport/byte_source.hpp"
#include "transport/network_settings.hpp"

namespace globe::services {

// What an imagery service's tiles may be.
inline constexpr const char* kImageAccept =
    "image/png,image/jpeg,image/webp;q=0.9,image/avif;q=0.8,*/*;q=0.5";

class UrlReader {
 public:
  UrlReader(std::shared_ptr<transport::Network> network, std::string accept)
      : network_(std::move(network)), accept_(std::move(accept)) {}
  // The file, nullopt when the server says it does not exist (404/410) or there is no such file;
  // an error naming the URL otherwise (unreachable, refused, longer than maxBytes).
  Result<std::optional<std::vector<std::byte>>> read(const std::string& url, size_t maxBytes);
  // The same for a URL whose content never changes (versioned: ByteSource::readWholeImmutable):
  // a cached copy, or a cached 404, is used without asking the server.
  Result<std::optional<std::vector<std::byte>>> readImmutable(const std::string& url,
                                                              size_t maxBytes);
  bool remote(const std::string& url) const;

 private:
  std::shared_ptr<transport::Network> network_;
  std::string accept_;
  std::mutex mutex_;
  Result<std::shared_ptr<transport::ByteSource>> sourceOf(const std::string& origin);
  std::map<std::string, std::shared_ptr<transport::ByteSource>> origins_;
};

// "https://host:port" and "path?query" of an http(s) URL; for a local path "/" and the path.
std::pair<std::string, std::string> splitOrigin(const std::string& url);
// `reference` resolved against the URL or path of the file it was found in (RFC 3986 in short:
// absolute URLs and root-relative paths as they are, the rest beside the file).
std::string resolveUrl(const std::string& base, const std::string& reference);

}  // namespace globe::services
