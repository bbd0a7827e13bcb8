// How the process reaches pyramids and layers given as http:// or https:// URLs: one HTTP client
// (one connection pool) and one disk cache shared by every store, made on first use.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "core/result.hpp"
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
};

struct NetworkSettings {
  std::filesystem::path cacheDirectory;  // empty: DiskCache::defaultDirectory()
  uint64_t cacheBudgetBytes = uint64_t{2} << 30;
  bool useCache = true;
  RemoteOptions remote;
  HttpSettings http;
};

// Set once by the program before the first URL is opened.
void setNetworkSettings(const NetworkSettings& settings);
NetworkSettings networkSettings();

// An http(s) URL of a directory served by a static server, read through `client` (may be null
// when offline) and `cache` (may be null: no cache).
std::shared_ptr<ByteSource> httpByteSource(std::string directoryUrl,
                                           std::shared_ptr<HttpClient> client,
                                           std::shared_ptr<DiskCache> cache, RemoteOptions options);

}  // namespace globe::transport
