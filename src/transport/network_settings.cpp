#include "transport/network_settings.hpp"

#include <optional>
#include <utility>

#include "transport/disk_cache.hpp"

namespace globe::transport {

Network::Network(NetworkSettings settings, core::WarningSink warnings)
    : settings_(std::move(settings)), warnings_(std::move(warnings)) {}

Network::~Network() = default;

Result<std::shared_ptr<ByteSource>> Network::open(const std::string& location) {
  return open(location, settings_.remote.accept);
}

Result<std::shared_ptr<ByteSource>> Network::open(const std::string& location,
                                                  const std::string& accept) {
  if (!isHttpUrl(location)) return localByteSource(location);
  std::optional<std::string> warning;  // given to the sink once the lock is released
  Result<std::shared_ptr<ByteSource>> opened = [&]() -> Result<std::shared_ptr<ByteSource>> {
    std::lock_guard lock(mutex_);
    if (settings_.useCache && !cacheTried_) {
      cacheTried_ = true;
      const std::filesystem::path dir = settings_.cacheDirectory.empty()
                                            ? DiskCache::defaultDirectory()
                                            : settings_.cacheDirectory;
      auto cache = DiskCache::open(dir, settings_.cacheBudgetBytes);
      if (cache) {
        cache_ = std::move(*cache);
      } else if (settings_.remote.offline) {
        return Error{cache.error()};
      } else {
        warning = "no disk cache: " + cache.error();
      }
    }
    if (settings_.remote.offline && !cache_) {
      return makeError(location + ": --offline needs the disk cache, and there is none");
    }
    if (!settings_.remote.offline && !client_) {
      client_ = std::make_shared<HttpClient>(settings_.http);
    }
    RemoteOptions remote = settings_.remote;
    remote.accept = accept;
    return httpByteSource(location, remote.offline ? nullptr : client_, cache_, remote);
  }();
  if (warning) core::warn(warnings_, *warning);
  return opened;
}

Result<std::shared_ptr<ByteSource>> openByteSource(const std::string& location, Network* network) {
  if (network != nullptr) return network->open(location);
  if (isHttpUrl(location)) {
    return makeError(location + ": an http(s) URL, and no network to read it through");
  }
  return localByteSource(location);
}

}  // namespace globe::transport
