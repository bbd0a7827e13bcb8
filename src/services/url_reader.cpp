#include "services/url_reader.hpp"

#include <filesystem>

#include "transport/http_client.hpp"

namespace globe::services {

std::pair<std::string, std::string> splitOrigin(const std::string& url) {
  if (!transport::isHttpUrl(url)) {
    const std::string path =
        std::filesystem::absolute(url.substr(0, url.find('?'))).lexically_normal().string();
    return {"/", path.substr(1)};
  }
  const size_t hostStart = url.find("://") + 3;
  const size_t pathStart = url.find_first_of("/?", hostStart);
  if (pathStart == std::string::npos) return {url, ""};
  const size_t nameStart = url[pathStart] == '/' ? pathStart + 1 : pathStart;
  return {url.substr(0, pathStart), url.substr(nameStart)};
}

std::string resolveUrl(const std::string& base, const std::string& reference) {
  if (transport::isHttpUrl(reference)) return reference;
  if (!reference.empty() && reference[0] == '/') {
    if (!transport::isHttpUrl(base)) return reference;
    return splitOrigin(base).first + reference;
  }
  // Beside the file: the base without its query and last segment.
  std::string directory = base.substr(0, base.find('?'));
  const size_t slash = directory.rfind('/');
  directory = slash == std::string::npos ? "" : directory.substr(0, slash + 1);
  return directory + reference;
}

bool UrlReader::remote(const std::string& url) const { return transport::isHttpUrl(url); }

Result<std::shared_ptr<transport::ByteSource>> UrlReader::sourceOf(const std::string& origin) {
  {
    std::lock_guard lock(mutex_);
    if (auto it = origins_.find(origin); it != origins_.end()) return it->second;
  }
  auto opened =
      network_ ? network_->open(origin, accept_) : transport::openByteSource(origin, nullptr);
  if (!opened) return Error{opened.error()};
  std::lock_guard lock(mutex_);
  return origins_.emplace(origin, std::move(*opened)).first->second;
}

Result<std::optional<std::vector<std::byte>>> UrlReader::read(const std::string& url,
                                                              size_t maxBytes) {
  auto [origin, name] = splitOrigin(url);
  auto source = sourceOf(origin);
  if (!source) return Error{source.error()};
  return (*source)->readWhole(name, maxBytes);
}

Result<std::optional<std::vector<std::byte>>> UrlReader::readImmutable(const std::string& url,
                                                                       size_t maxBytes) {
  auto [origin, name] = splitOrigin(url);
  auto source = sourceOf(origin);
  if (!source) return Error{source.error()};
  return (*source)->readWholeImmutable(name, maxBytes);
}

}  // namespace globe::services
