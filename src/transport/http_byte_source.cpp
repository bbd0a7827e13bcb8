// ByteSource over a static web server: manifests by GET, pack headers and tiles by one range
// request each, every response kept in the disk cache and revalidated by ETag, so a republished
// pyramid is never served stale and --offline works from the cache alone.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <ctime>
#include <thread>
#include <utility>

#include "core/big_endian.hpp"
#include "transport/disk_cache.hpp"
#include "transport/network_settings.hpp"

namespace globe::transport {
namespace {

// Retries one source may spend in a run (a process): a server that fails every request costs
// each request one try once these are gone, so a run against it ends in bounded time.
constexpr int kRetriesPerRun = 64;

bool retryable(const HttpResponse& r) {
  if (r.bodyTooLong) return false;
  return r.status == 0 || r.status == 429 || r.status >= 500;
}

std::string describe(const std::string& url, const HttpResponse& r) {
  if (r.bodyTooLong) return url + ": the server sent (or announced) more bytes than asked for";
  if (r.status == 0) {
    return url + ": " + (r.timedOut ? "timed out (" + r.transportError + ")" : r.transportError);
  }
  if (r.status == 404 || r.status == 410)
    return url + ": not found (HTTP " + std::to_string(r.status) + ")";
  if (r.status >= 300 && r.status < 400) {
    return url + ": HTTP " + std::to_string(r.status) +
           ", a redirect not followed (only within its scheme, at most 5)";
  }
  return url + ": HTTP " + std::to_string(r.status);
}

std::string ignoresRanges(const std::string& url) {
  return url +
         ": the server ignores Range requests (it answered 200 with the whole file); serve the "
         "directory with a server that honours them (nginx, Apache, any S3-compatible store)";
}

std::string rangeKey(const std::string& url, uint64_t offset, uint64_t bytes) {
  return "range " + url + " " + std::to_string(offset) + "+" + std::to_string(bytes);
}

class HttpByteSource;

class HttpFile final : public ByteFile {
 public:
  HttpFile(std::shared_ptr<HttpByteSource> source, std::string url, uint64_t sizeBytes,
           std::string validator)
      : source_(std::move(source)),
        url_(std::move(url)),
        sizeBytes_(sizeBytes),
        validator_(std::move(validator)) {}
  uint64_t sizeBytes() const override { return sizeBytes_; }
  Result<void> read(std::span<std::byte> out, uint64_t offset) const override;
  Result<void> readPieces(std::span<std::byte> out, uint64_t offset,
                          std::span<const uint32_t> pieceBytes) const override;
  const std::string& location() const override { return url_; }

 private:
  std::shared_ptr<HttpByteSource> source_;
  std::string url_;
  uint64_t sizeBytes_;
  std::string validator_;  // the ETag the head was served with: every range must match it
};

class HttpByteSource final : public ByteSource,
                             public std::enable_shared_from_this<HttpByteSource> {
 public:
  HttpByteSource(std::string url, std::shared_ptr<HttpClient> client,
                 std::shared_ptr<DiskCache> cache, RemoteOptions options)
      : url_(std::move(url)),
        client_(std::move(client)),
        cache_(std::move(cache)),
        options_(options) {
    while (!url_.empty() && url_.back() == '/') url_.pop_back();
    if (client_ == nullptr) options_.offline = true;
  }

  Result<std::optional<std::vector<std::byte>>> readWhole(const std::string& name,
                                                          size_t maxBytes) override {
    const std::string url = locationOf(name);
    const std::string key = "get " + url;
    std::optional<CacheEntry> cached = cache_ ? cache_->get(key) : std::nullopt;
    if (options_.offline) {
      if (!cached) {
        // A file the server said it does not have (a tile service's 404) is absent offline too.
        if (cache_ && cache_->get("absent " + url)) return std::optional<std::vector<std::byte>>();
        return makeError(url + ": not in the disk cache (offline)");
      }
      return std::optional<std::vector<std::byte>>(std::move(cached->body));
    }
    // Still fresh by the server's Cache-Control max-age: no round trip at all.
    if (cached && freshUntil(url, cached->validator) > std::time(nullptr)) {
      headsTrusted_ = true;
      return std::optional<std::vector<std::byte>>(std::move(cached->body));
    }
    HttpRequest q;
    q.url = url;
    q.maxBodyBytes = maxBytes;
    q.accept = options_.accept;
    if (cached) q.ifNoneMatch = cached->validator;
    HttpResponse r = fetch(q);
    if (r.status == 304 && cached) {
      // The manifest is unchanged: the tiler rewrites it on every run, so the packs are too.
      headsTrusted_ = true;
      keepFresh(url, cached->validator, r.maxAgeSeconds);
      return std::optional<std::vector<std::byte>>(std::move(cached->body));
    }
    headsTrusted_ = false;
    if (r.status == 200 && !r.bodyTooLong) {
      store(key, r.etag, r.body.size(), r.body);
      keepFresh(url, r.etag, r.maxAgeSeconds);
      return std::optional<std::vector<std::byte>>(std::move(r.body));
    }
    if (r.status == 404 || r.status == 410) {
      // Remembered for --offline only: online the server is asked again (it may have it now).
      if (cache_) (void)cache_->put("absent " + url, CacheEntry{"absent", 0, {}});
      return std::optional<std::vector<std::byte>>();
    }
    if (r.bodyTooLong) {
      return makeError(url + ": larger than " + std::to_string(maxBytes) + " bytes");
    }
    // The server cannot be reached or fails: what the cache holds still serves.
    if (cached && r.status == 0)
      return std::optional<std::vector<std::byte>>(std::move(cached->body));
    return makeError(describe(url, r));
  }

  Result<std::optional<std::vector<std::byte>>> readWholeImmutable(const std::string& name,
                                                                   size_t maxBytes) override {
    if (cache_ && !options_.offline) {
      const std::string url = locationOf(name);
      std::optional<CacheEntry> cached = cache_->get("get " + url);
      if (cached && cached->body.size() <= maxBytes) {
        return std::optional<std::vector<std::byte>>(std::move(cached->body));
      }
      // Its 404 too: that version of the data has no such file.
      if (cache_->get("absent " + url)) return std::optional<std::vector<std::byte>>();
    }
    return readWhole(name, maxBytes);
  }

  Result<OpenedFile> open(const std::string& name, size_t headBytes) override {
    const std::string url = locationOf(name);
    const std::string key = rangeKey(url, 0, headBytes);
    std::optional<CacheEntry> cached = cache_ ? cache_->get(key) : std::nullopt;
    auto fromCache = [&]() {
      OpenedFile opened;
      opened.file = std::make_shared<const HttpFile>(shared_from_this(), url, cached->fileBytes,
                                                     cached->validator);
      opened.head = std::move(cached->body);
      return opened;
    };
    if (options_.offline) {
      if (!cached) return makeError(url + ": not in the disk cache (offline)");
      return fromCache();
    }
    if (cached && headsTrusted_) return fromCache();  // no round trip per pack on a warm start
    HttpRequest q;
    q.url = url;
    q.ranged = headBytes > 0;
    q.rangeOffset = 0;
    q.rangeBytes = headBytes;
    q.maxBodyBytes = headBytes;
    if (cached) q.ifNoneMatch = cached->validator;
    HttpResponse r = fetch(q);
    if (r.status == 304 && cached) return fromCache();
    uint64_t first = 0;
    uint64_t last = 0;
    uint64_t total = 0;
    OpenedFile opened;
    if (r.status == 206) {
      if (!parseContentRange(r.contentRange, &first, &last, &total) || first != 0 ||
          r.body.size() != last + 1 || (last + 1 != headBytes && last + 1 != total)) {
        return makeError(url + ": a wrong Content-Range (\"" + r.contentRange + "\" for bytes 0-" +
                         std::to_string(headBytes - 1) + ", " + std::to_string(r.body.size()) +
                         " bytes sent)");
      }
    } else if (r.status == 200 && !r.bodyTooLong) {
      total = r.body.size();  // a whole file no longer than the head: nothing more to ask for
    } else if (r.status == 200 && r.bodyTooLong) {
      return makeError(ignoresRanges(url));
    } else if (r.status == 416) {
      total = 0;  // an empty file
      r.body.clear();
    } else {
      if (cached && r.status == 0) return fromCache();
      return makeError(describe(url, r));
    }
    store(key, r.etag, total, r.body);
    opened.file = std::make_shared<const HttpFile>(shared_from_this(), url, total, r.etag);
    opened.head = std::move(r.body);
    return opened;
  }

  Result<void> readRange(const std::string& url, const std::string& validator, uint64_t sizeBytes,
                         std::span<std::byte> out, uint64_t offset) {
    const uint32_t whole[] = {static_cast<uint32_t>(out.size())};
    if (out.size() > UINT32_MAX) return fetchRange(url, validator, sizeBytes, out, offset, {});
    return readPieces(url, validator, sizeBytes, out, offset, whole);
  }

  // Each piece from the cache when it holds it; the span from the first piece it lacks to the
  // last by one request, each of those pieces then cached under its own key.
  Result<void> readPieces(const std::string& url, const std::string& validator, uint64_t sizeBytes,
                          std::span<std::byte> out, uint64_t offset,
                          std::span<const uint32_t> pieceBytes) {
    if (out.empty()) return {};
    const std::string span =
        "bytes " + std::to_string(offset) + "-" + std::to_string(offset + out.size() - 1);
    if (offset + out.size() > sizeBytes) {
      return makeError(url + ": " + span + " lie beyond its end (" + std::to_string(sizeBytes) +
                       " bytes)");
    }
    std::vector<uint64_t> starts;  // of each piece in out
    uint64_t total = 0;
    for (uint32_t bytes : pieceBytes) {
      starts.push_back(total);
      total += bytes;
    }
    if (total != out.size()) return makeError(url + ": " + span + ": pieces do not add up");
    std::optional<size_t> firstMissing;
    size_t lastMissing = 0;
    for (size_t i = 0; i < pieceBytes.size(); ++i) {
      const std::span<std::byte> piece = out.subspan(starts[i], pieceBytes[i]);
      if (cached(rangeKey(url, offset + starts[i], piece.size()), validator, piece)) continue;
      if (!firstMissing) firstMissing = i;
      lastMissing = i;
    }
    if (!firstMissing) return {};
    const uint64_t from = starts[*firstMissing];
    const uint64_t to = starts[lastMissing] + pieceBytes[lastMissing];
    const std::span<std::byte> missing = out.subspan(from, to - from);
    if (options_.offline) {
      return makeError(url + ": bytes " + std::to_string(offset + from) + "-" +
                       std::to_string(offset + to - 1) + " not in the disk cache (offline)");
    }
    std::string etag;
    if (auto fetched = fetchRange(url, validator, sizeBytes, missing, offset + from, &etag);
        !fetched) {
      return fetched;
    }
    for (size_t i = *firstMissing; i <= lastMissing; ++i) {
      const std::span<const std::byte> piece = out.subspan(starts[i], pieceBytes[i]);
      store(rangeKey(url, offset + starts[i], piece.size()), etag, sizeBytes,
            std::vector<std::byte>(piece.begin(), piece.end()));
    }
    return {};
  }

  std::string locationOf(const std::string& name) const override { return url_ + "/" + name; }
  const std::string& location() const override { return url_; }
  bool remote() const override { return true; }

 private:
  // A cached range counts only when served with the same ETag as the head read this session.
  bool cached(const std::string& key, const std::string& validator, std::span<std::byte> out) {
    if (!cache_) return false;
    std::optional<CacheEntry> entry = cache_->get(key);
    if (!entry || entry->body.size() != out.size() ||
        !(options_.offline || (!validator.empty() && entry->validator == validator))) {
      return false;
    }
    std::memcpy(out.data(), entry->body.data(), out.size());
    return true;
  }

  // One range request, checked against the file's size and ETag; *etag (when asked) the
  // response's.
  Result<void> fetchRange(const std::string& url, const std::string& validator, uint64_t sizeBytes,
                          std::span<std::byte> out, uint64_t offset, std::string* etag) {
    const std::string span =
        "bytes " + std::to_string(offset) + "-" + std::to_string(offset + out.size() - 1);
    HttpRequest q;
    q.url = url;
    q.ranged = true;
    q.rangeOffset = offset;
    q.rangeBytes = out.size();
    q.maxBodyBytes = out.size();
    HttpResponse r = fetch(q);
    if (r.status == 200) return makeError(ignoresRanges(url));
    if (r.status != 206) return makeError(describe(url, r));
    uint64_t first = 0;
    uint64_t last = 0;
    uint64_t total = 0;
    if (!parseContentRange(r.contentRange, &first, &last, &total) || first != offset ||
        last + 1 != offset + out.size() || r.body.size() != out.size()) {
      return makeError(url + ": a wrong Content-Range (\"" + r.contentRange + "\" for " + span +
                       ", " + std::to_string(r.body.size()) + " bytes sent)");
    }
    if (total != sizeBytes || (!validator.empty() && !r.etag.empty() && r.etag != validator)) {
      return makeError(url + ": changed on the server since its index was read (re-open it)");
    }
    std::memcpy(out.data(), r.body.data(), out.size());
    if (etag) *etag = r.etag;
    return {};
  }

  // Retries are bounded three ways: `attempts` per request, one retry for a timeout (a server
  // that stalled once mostly stalls again: a stalled server fails a request in about two stall
  // times), and kRetriesPerRun for the source, after which every request is tried once.
  HttpResponse fetch(const HttpRequest& q) {
    long delayMs = options_.firstRetryDelayMs;
    for (int attempt = 1;; ++attempt) {
      HttpResponse r = client_->perform(q);
      const int attempts = r.timedOut ? std::min(options_.attempts, 2) : options_.attempts;
      if (!retryable(r) || attempt >= attempts) return r;
      if (retriesLeft_.fetch_sub(1) <= 0) {
        r.transportError += " (not retried: this run's " + std::to_string(kRetriesPerRun) +
                            " retries on this server are spent)";
        return r;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(delayMs));
      delayMs *= 2;
    }
  }

  // When a whole file served with `etag` stops being fresh (unix seconds; 0: not known), kept
  // as its own small cache entry: the server's Cache-Control max-age from its last answer.
  std::time_t freshUntil(const std::string& url, const std::string& etag) {
    if (!cache_) return 0;
    std::optional<CacheEntry> fresh = cache_->get("fresh " + url);
    if (!fresh || fresh->validator != etag || fresh->body.size() != 8) return 0;
    return static_cast<std::time_t>(core::loadBigEndian64(fresh->body.data()));
  }
  void keepFresh(const std::string& url, const std::string& etag, long maxAgeSeconds) {
    if (!cache_ || etag.empty()) return;
    if (maxAgeSeconds <= 0) {
      cache_->erase("fresh " + url);
      return;
    }
    CacheEntry entry{etag, 0, std::vector<std::byte>(8)};
    core::storeBigEndian64(
        entry.body.data(),
        static_cast<uint64_t>(std::time(nullptr) + std::min(maxAgeSeconds, 86400L * 365)));
    (void)cache_->put("fresh " + url, entry);
  }

  void store(const std::string& key, const std::string& etag, uint64_t fileBytes,
             const std::vector<std::byte>& body) {
    if (!cache_ || etag.empty()) return;  // without a validator it could never be trusted again
    CacheEntry entry{etag, fileBytes, body};
    (void)cache_->put(key, entry);  // a full or read-only cache costs speed, never correctness
  }

  std::string url_;
  std::shared_ptr<HttpClient> client_;
  std::shared_ptr<DiskCache> cache_;
  RemoteOptions options_;
  // Set when the directory's manifest was revalidated unchanged (304) this session: cached pack
  // heads are then used without asking again. A republish rewrites the manifest (new ETag).
  std::atomic<bool> headsTrusted_{false};
  std::atomic<int> retriesLeft_{kRetriesPerRun};
};

Result<void> HttpFile::read(std::span<std::byte> out, uint64_t offset) const {
  return source_->readRange(url_, validator_, sizeBytes_, out, offset);
}

Result<void> HttpFile::readPieces(std::span<std::byte> out, uint64_t offset,
                                  std::span<const uint32_t> pieceBytes) const {
  return source_->readPieces(url_, validator_, sizeBytes_, out, offset, pieceBytes);
}

}  // namespace

std::shared_ptr<ByteSource> httpByteSource(std::string directoryUrl,
                                           std::shared_ptr<HttpClient> client,
                                           std::shared_ptr<DiskCache> cache,
                                           RemoteOptions options) {
  return std::make_shared<HttpByteSource>(std::move(directoryUrl), std::move(client),
                                          std::move(cache), options);
}

}  // namespace globe::transport
