#include "transport/network_settings.hpp"

#include <cstdio>
#include <mutex>

#include "transport/disk_cache.hpp"

namespace globe::transport {
namespace {

struct Network {
  std::mutex mutex;
  NetworkSettings settings;
  std::shared_ptr<HttpClient> client;  // made on first use
  std::shared_ptr<DiskCache> cache;
  bool cacheTried = false;
};

Network& network() {
  static Network n;
  return n;
}

}  // namespace

void setNetworkSettings(const NetworkSettings& settings) {
  Network& n = network();
  std::lock_guard lock(n.mutex);
  n.settings = settings;
  n.client.reset();
  n.cache.reset();
  n.cacheTried = false;
}

NetworkSettings networkSettings() {
  Network& n = network();
  std::lock_guard lock(n.mutex);
  return n.settings;
}

Result<std::shared_ptr<ByteSource>> openByteSource(const std::string& location) {
  if (!isHttpUrl(location)) return localByteSource(location);
  Network& n = network();
  std::lock_guard lock(n.mutex);
  if (n.settings.useCache && !n.cacheTried) {
    n.cacheTried = true;
    const std::filesystem::path dir = n.settings.cacheDirectory.empty()
                                          ? DiskCache::defaultDirectory()
                                          : n.settings.cacheDirectory;
    auto cache = DiskCache::open(dir, n.settings.cacheBudgetBytes);
    if (cache) {
      n.cache = std::move(*cache);
    } else if (n.settings.remote.offline) {
      return Error{cache.error()};
    } else {
      std::fprintf(stderr, "globe: no disk cache: %s\n", cache.error().c_str());
    }
  }
  if (n.settings.remote.offline && !n.cache) {
    return makeError(location + ": --offline needs the disk cache, and there is none");
  }
  if (!n.settings.remote.offline && !n.client) {
    n.client = std::make_shared<HttpClient>(n.settings.http);
  }
  return httpByteSource(location, n.settings.remote.offline ? nullptr : n.client, n.cache,
                        n.settings.remote);
}

}  // namespace globe::transport
