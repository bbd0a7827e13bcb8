// How a program reaches pyramids and layers given as http:// or https:// URLs: its settings, and
// the Network it makes from them and passes down to every store (one HTTP client, one connection
// pool and one disk cache shared by all of them, made on first use).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>

#include "core/result.hpp"
#include "core/warnings.hpp"
#include "transport/byte_source.hpp"
#include "transport/http_client.hpp"

namespace globe::transport {

class DiskCache;

// Loads at once (and loader threads) for a store on a server: they wait on round trips, not on
// the CPU, so many in flight hide the latency.
inline constexpr unsigned kRemoteLoadsInFlight = 24;

struct RemoteOptions {
  bool offline = false;          // the disk cache alone; a miss is an error
  int attempts = 3;              // per request, on timeouts, dropped connections and 5xx
  long firstRetryDelayMs = 200;  // doubled after each failed attempt
  // Sent as Accept with every GET (a terrain service picks the tile's extensions by it).
  std::string accept{};
};

struct NetworkSettings {
  std::filesystem::path cacheDirectory;  // empty: DiskCache::defaultDirectory()
  uint64_t cacheBudgetBytes = uint64_t{2} << 30;
  bool useCache = true;
  RemoteOptions remote;
  HttpSettings http;
};

// Made once by the program from its flags and shared (std::shared_ptr) by everything that opens
// pyramids and layers: the HTTP client and the disk cache are made when the first URL is opened,
// then shared by every source opened through it. Thread-safe.
class Network {
 public:
  // `warnings` gets "no disk cache: <why>" when the cache cannot be opened (the URLs are then
  // read without one), on the thread that opens the first URL.
  explicit Network(NetworkSettings settings = {}, core::WarningSink warnings = {});
  ~Network();
  Network(const Network&) = delete;
  Network& operator=(const Network&) = delete;

  const NetworkSettings& settings() const { return settings_; }

  // A local directory (no network needed), or an http:// / https:// URL of the same directory
  // on a static server. Errors: --offline without a disk cache (naming the URL), or the disk
  // cache's own error when offline.
  Result<std::shared_ptr<ByteSource>> open(const std::string& location);
  // The same, every GET sent with this Accept header.
  Result<std::shared_ptr<ByteSource>> open(const std::string& location, const std::string& accept);

 private:
  const NetworkSettings settings_;
  const core::WarningSink warnings_;
  std::mutex mutex_;
  std::shared_ptr<HttpClient> client_;  // made on first use
  std::shared_ptr<DiskCache> cache_;
  bool cacheTried_ = false;
};

// An http(s) URL of a directory served by a static server, read through `client` (may be null
// when offline) and `cache` (may be null: no cache).
std::shared_ptr<ByteSource> httpByteSource(std::string directoryUrl,
                                           std::shared_ptr<HttpClient> client,
                                           std::shared_ptr<DiskCache> cache, RemoteOptions options);

}  // namespace globe::transport
