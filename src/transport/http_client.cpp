#include "transport/http_client.hpp"

#include <curl/curl.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <condition_variable>
#include <deque>
#include <future>
#include <mutex>
#include <thread>
#include <unordered_map>
#include <utility>

#include "core/ascii_case.hpp"
#include "globe_version.hpp"

namespace globe::transport {
namespace http_detail {

// Named, not anonymous: HttpClient::Impl holds these, and a class with external linkage may not
// have members of an internal type once this file is compiled inside a unity build.
struct Transfer {
  HttpRequest request;
  HttpResponse response;
  std::promise<HttpResponse> done;
  CURL* easy = nullptr;
  curl_slist* headers = nullptr;
  char errorText[CURL_ERROR_SIZE] = {};
};

}  // namespace http_detail
using http_detail::Transfer;

namespace {

std::once_flag curlInitialised;

std::string trim(std::string_view text) {
  size_t begin = 0;
  size_t end = text.size();
  while (begin < end && std::isspace(static_cast<unsigned char>(text[begin])) != 0) ++begin;
  while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1])) != 0) --end;
  return std::string(text.substr(begin, end - begin));
}

bool startsWithNoCase(std::string_view text, std::string_view prefix) {
  if (text.size() < prefix.size()) return false;
  for (size_t i = 0; i < prefix.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(text[i])) !=
        std::tolower(static_cast<unsigned char>(prefix[i]))) {
      return false;
    }
  }
  return true;
}

// "max-age=300, public" -> 300; no-cache / no-store -> 0; otherwise -1.
long parseMaxAge(const std::string& value) {
  const std::string lower = core::asciiLower(value);
  if (lower.find("no-cache") != std::string::npos || lower.find("no-store") != std::string::npos) {
    return 0;
  }
  const size_t at = lower.find("max-age=");
  if (at == std::string::npos) return -1;
  long seconds = -1;
  const char* first = lower.data() + at + 8;
  auto [next, ec] = std::from_chars(first, lower.data() + lower.size(), seconds);
  return ec == std::errc() && next != first && seconds >= 0 ? seconds : -1;
}

size_t onBody(char* data, size_t size, size_t count, void* user) {
  auto* transfer = static_cast<Transfer*>(user);
  const size_t bytes = size * count;
  auto& body = transfer->response.body;
  if (body.size() + bytes > transfer->request.maxBodyBytes) {
    transfer->response.bodyTooLong = true;
    return 0;  // aborts the transfer
  }
  const auto* first = reinterpret_cast<const std::byte*>(data);
  body.insert(body.end(), first, first + bytes);
  return bytes;
}

// A number of decimal digits after optional blanks; -1 when there is none or it overflows.
long long parseCount(std::string_view text) {
  const std::string value = trim(text);
  long long n = -1;
  auto [next, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
  return ec == std::errc() && next == value.data() + value.size() ? n : -1;
}

size_t onHeader(char* data, size_t size, size_t count, void* user) {
  auto* transfer = static_cast<Transfer*>(user);
  const std::string_view line(data, size * count);
  HttpResponse& r = transfer->response;
  if (startsWithNoCase(line, "HTTP/")) {  // a new response (after a redirect or a 100)
    const size_t space = line.find(' ');  // "HTTP/1.1 200 OK": the status, for Content-Length
    r.status = space == std::string_view::npos
                   ? 0
                   : static_cast<long>(parseCount(line.substr(space, 4)));
    r.etag.clear();
    r.lastModified.clear();
    r.contentRange.clear();
    r.maxAgeSeconds = -1;
  } else if (startsWithNoCase(line, "etag:")) {
    r.etag = trim(line.substr(5));
  } else if (startsWithNoCase(line, "last-modified:")) {
    r.lastModified = trim(line.substr(14));
  } else if (startsWithNoCase(line, "content-range:")) {
    r.contentRange = trim(line.substr(14));
  } else if (startsWithNoCase(line, "cache-control:")) {
    r.maxAgeSeconds = parseMaxAge(trim(line.substr(14)));
  } else if (startsWithNoCase(line, "content-length:") && r.status >= 200 && r.status < 300) {
    // A body announced longer than the caller takes is refused before a byte of it comes (a
    // server that says 10^12 bytes and then stalls costs nothing).
    const long long announced = parseCount(line.substr(15));
    if (announced > 0 && static_cast<unsigned long long>(announced) >
                             transfer->request.maxBodyBytes) {
      r.bodyTooLong = true;
      return 0;  // aborts the transfer
    }
  }
  return size * count;
}

}  // namespace

struct HttpClient::Impl {
  HttpSettings settings;
  // Names the program and its version to tile servers, as their usage policies ask
  // (OpenStreetMap's: a User-Agent that identifies the application, not a library's default).
  std::string userAgent = std::string("globe/") + kVersion + " (open-source virtual globe viewer)";
  CURLM* multi = nullptr;
  std::mutex mutex;
  std::deque<std::unique_ptr<Transfer>> queued;                  // guarded by mutex
  bool stopping = false;                                         // guarded by mutex
  std::unordered_map<CURL*, std::unique_ptr<Transfer>> running;  // loop thread only
  std::thread loop;

  void start(Transfer& t) {
    const HttpRequest& q = t.request;
    t.easy = curl_easy_init();
    CURL* e = t.easy;
    curl_easy_setopt(e, CURLOPT_URL, q.url.c_str());
    curl_easy_setopt(e, CURLOPT_PROTOCOLS_STR, "http,https");
    // A redirect may not change the scheme (https → http would drop TLS; file:// is never spoken).
    curl_easy_setopt(e, CURLOPT_REDIR_PROTOCOLS_STR,
                     q.url.compare(0, 6, "https:") == 0 ? "https" : "http");
    curl_easy_setopt(e, CURLOPT_FOLLOWLOCATION, 1L);
    curl_easy_setopt(e, CURLOPT_MAXREDIRS, 5L);
    curl_easy_setopt(e, CURLOPT_USERAGENT, userAgent.c_str());
    curl_easy_setopt(e, CURLOPT_NOSIGNAL, 1L);
    curl_easy_setopt(e, CURLOPT_CONNECTTIMEOUT_MS, settings.connectTimeoutMs);
    curl_easy_setopt(e, CURLOPT_TIMEOUT_MS, settings.totalTimeoutMs);
    // Below 16 bytes/s for the stall time: the server stalled.
    curl_easy_setopt(e, CURLOPT_LOW_SPEED_LIMIT, 16L);
    curl_easy_setopt(e, CURLOPT_LOW_SPEED_TIME, std::max(1L, settings.stallTimeoutMs / 1000));
    curl_easy_setopt(e, CURLOPT_SSL_VERIFYPEER, settings.verifyTls ? 1L : 0L);
    curl_easy_setopt(e, CURLOPT_SSL_VERIFYHOST, settings.verifyTls ? 2L : 0L);
    if (!settings.caFile.empty()) curl_easy_setopt(e, CURLOPT_CAINFO, settings.caFile.c_str());
    curl_easy_setopt(e, CURLOPT_HTTP_VERSION, static_cast<long>(CURL_HTTP_VERSION_2TLS));
    curl_easy_setopt(e, CURLOPT_PIPEWAIT, 1L);  // wait for a multiplexed connection over a new one
    curl_easy_setopt(e, CURLOPT_ACCEPT_ENCODING, nullptr);  // ranges are of the stored bytes
    curl_easy_setopt(e, CURLOPT_WRITEFUNCTION, onBody);
    curl_easy_setopt(e, CURLOPT_WRITEDATA, &t);
    curl_easy_setopt(e, CURLOPT_HEADERFUNCTION, onHeader);
    curl_easy_setopt(e, CURLOPT_HEADERDATA, &t);
    curl_easy_setopt(e, CURLOPT_ERRORBUFFER, t.errorText);
    curl_easy_setopt(e, CURLOPT_PRIVATE, &t);
    if (q.ranged) {
      const std::string range =
          std::to_string(q.rangeOffset) + "-" + std::to_string(q.rangeOffset + q.rangeBytes - 1);
      curl_easy_setopt(e, CURLOPT_RANGE, range.c_str());  // copied by curl
    }
    if (!q.ifNoneMatch.empty()) {
      t.headers = curl_slist_append(t.headers, ("If-None-Match: " + q.ifNoneMatch).c_str());
    }
    if (!q.accept.empty()) {
      t.headers = curl_slist_append(t.headers, ("Accept: " + q.accept).c_str());
    }
    if (t.headers != nullptr) curl_easy_setopt(e, CURLOPT_HTTPHEADER, t.headers);
    curl_multi_add_handle(multi, e);
  }

  void finish(CURL* easy, CURLcode code) {
    auto it = running.find(easy);
    if (it == running.end()) return;
    std::unique_ptr<Transfer> t = std::move(it->second);
    running.erase(it);
    curl_multi_remove_handle(multi, easy);
    HttpResponse& r = t->response;
    curl_easy_getinfo(easy, CURLINFO_RESPONSE_CODE, &r.status);
    if (code != CURLE_OK && !r.bodyTooLong) {
      r.transportError = t->errorText[0] != '\0' ? t->errorText : curl_easy_strerror(code);
      r.timedOut = code == CURLE_OPERATION_TIMEDOUT;
      if (code == CURLE_PARTIAL_FILE || r.timedOut) r.status = 0;  // no complete response
    }
    curl_easy_cleanup(easy);
    curl_slist_free_all(t->headers);
    t->done.set_value(std::move(r));
  }

  void run() {
    for (;;) {
      {
        std::lock_guard lock(mutex);
        if (stopping) break;
        while (!queued.empty()) {
          std::unique_ptr<Transfer> t = std::move(queued.front());
          queued.pop_front();
          start(*t);
          CURL* easy = t->easy;
          running.emplace(easy, std::move(t));
        }
      }
      int stillRunning = 0;
      curl_multi_perform(multi, &stillRunning);
      int left = 0;
      while (CURLMsg* message = curl_multi_info_read(multi, &left)) {
        if (message->msg == CURLMSG_DONE) finish(message->easy_handle, message->data.result);
      }
      curl_multi_poll(multi, nullptr, 0, 1000, nullptr);
    }
    // Abandoned: every caller still waiting gets an answer.
    for (auto& [easy, t] : running) {
      curl_multi_remove_handle(multi, easy);
      curl_easy_cleanup(easy);
      curl_slist_free_all(t->headers);
      t->response.transportError = "the HTTP client was shut down";
      t->done.set_value(std::move(t->response));
    }
    running.clear();
    std::lock_guard lock(mutex);
    for (auto& t : queued) {
      t->response.transportError = "the HTTP client was shut down";
      t->done.set_value(std::move(t->response));
    }
    queued.clear();
  }
};

HttpClient::HttpClient(HttpSettings settings) : impl_(std::make_unique<Impl>()) {
  std::call_once(curlInitialised, [] { curl_global_init(CURL_GLOBAL_DEFAULT); });
  impl_->settings = settings;
  impl_->multi = curl_multi_init();
  curl_multi_setopt(impl_->multi, CURLMOPT_PIPELINING, CURLPIPE_MULTIPLEX);
  curl_multi_setopt(impl_->multi, CURLMOPT_MAX_HOST_CONNECTIONS, settings.maxConnectionsPerHost);
  curl_multi_setopt(impl_->multi, CURLMOPT_MAX_TOTAL_CONNECTIONS,
                    4 * settings.maxConnectionsPerHost);
  impl_->loop = std::thread([impl = impl_.get()] { impl->run(); });
}

HttpClient::~HttpClient() {
  {
    std::lock_guard lock(impl_->mutex);
    impl_->stopping = true;
  }
  curl_multi_wakeup(impl_->multi);
  impl_->loop.join();
  curl_multi_cleanup(impl_->multi);
}

const HttpSettings& HttpClient::settings() const { return impl_->settings; }

HttpResponse HttpClient::perform(const HttpRequest& request) {
  auto transfer = std::make_unique<Transfer>();
  transfer->request = request;
  std::future<HttpResponse> answer = transfer->done.get_future();
  {
    std::lock_guard lock(impl_->mutex);
    if (impl_->stopping) {
      HttpResponse r;
      r.transportError = "the HTTP client was shut down";
      return r;
    }
    impl_->queued.push_back(std::move(transfer));
  }
  curl_multi_wakeup(impl_->multi);
  return answer.get();
}

bool isHttpUrl(const std::string& location) {
  return startsWithNoCase(location, "http://") || startsWithNoCase(location, "https://");
}

bool parseContentRange(const std::string& value, uint64_t* first, uint64_t* last, uint64_t* total) {
  const std::string_view v(value);
  if (!startsWithNoCase(v, "bytes ")) return false;
  const char* p = v.data() + 6;
  const char* end = v.data() + v.size();
  auto number = [&](uint64_t* out, char stop) {
    auto [next, ec] = std::from_chars(p, end, *out);
    if (ec != std::errc() || next == p) return false;
    p = next;
    if (stop == '\0') return p == end;
    if (p == end || *p != stop) return false;
    ++p;
    return true;
  };
  return number(first, '-') && number(last, '/') && number(total, '\0') && *first <= *last &&
         *last < *total;
}

}  // namespace globe::transport
