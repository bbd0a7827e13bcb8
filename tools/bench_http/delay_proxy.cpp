// globe-delay-proxy: a TCP proxy on 127.0.0.1 that holds every chunk for a fixed delay in each
// direction, so a loopback server behaves like one RTT milliseconds away (what `tc netem` would
// do, without needing a network namespace or the netem module). It exits by itself after
// LIFETIME seconds.
//
//   globe-delay-proxy LISTEN_PORT TARGET_PORT RTT_MS LIFETIME_S
#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

// One direction of a connection: a reader queues chunks stamped with their due time, a writer
// sends each when due, in order.
struct Pipe {
  int from;
  int to;
  std::chrono::microseconds delay;
  std::mutex mutex;
  std::condition_variable ready;
  std::deque<std::pair<Clock::time_point, std::vector<char>>> chunks;
  bool closed = false;

  void read() {
    std::vector<char> buffer(64 * 1024);
    for (;;) {
      const ssize_t n = ::recv(from, buffer.data(), buffer.size(), 0);
      std::lock_guard lock(mutex);
      if (n <= 0) {
        closed = true;
        ready.notify_one();
        return;
      }
      chunks.emplace_back(Clock::now() + delay,
                          std::vector<char>(buffer.begin(), buffer.begin() + n));
      ready.notify_one();
    }
  }

  void write() {
    for (;;) {
      std::unique_lock lock(mutex);
      ready.wait(lock, [&] { return closed || !chunks.empty(); });
      if (chunks.empty()) {
        ::shutdown(to, SHUT_WR);
        return;
      }
      auto [due, data] = std::move(chunks.front());
      chunks.pop_front();
      lock.unlock();
      std::this_thread::sleep_until(due);
      size_t sent = 0;
      while (sent < data.size()) {
        const ssize_t n = ::send(to, data.data() + sent, data.size() - sent, MSG_NOSIGNAL);
        if (n <= 0) return;
        sent += static_cast<size_t>(n);
      }
    }
  }
};

int connectTo(int port) {
  const int s = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(static_cast<uint16_t>(port));
  if (::connect(s, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
    ::close(s);
    return -1;
  }
  return s;
}

void serve(int client, int targetPort, std::chrono::microseconds oneWay) {
  const int server = connectTo(targetPort);
  if (server < 0) {
    ::close(client);
    return;
  }
  const int one = 1;
  ::setsockopt(client, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  ::setsockopt(server, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  // The connection's own set-up costs one round trip, as it would far away.
  std::this_thread::sleep_for(2 * oneWay);
  auto up = std::make_shared<Pipe>();
  auto down = std::make_shared<Pipe>();
  up->from = client;
  up->to = server;
  down->from = server;
  down->to = client;
  up->delay = down->delay = oneWay;
  std::thread a([up] { up->read(); });
  std::thread b([up] { up->write(); });
  std::thread c([down] { down->read(); });
  std::thread d([down] { down->write(); });
  a.join();
  b.join();
  c.join();
  d.join();
  ::close(client);
  ::close(server);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: globe-delay-proxy LISTEN_PORT TARGET_PORT RTT_MS LIFETIME_S\n");
    return 2;
  }
  const int listenPort = std::atoi(argv[1]);
  const int targetPort = std::atoi(argv[2]);
  const auto oneWay = std::chrono::microseconds(static_cast<long>(std::atof(argv[3]) * 500));
  const int lifetime = std::atoi(argv[4]);
  const int listener = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  const int one = 1;
  ::setsockopt(listener, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);  // never another address
  address.sin_port = htons(static_cast<uint16_t>(listenPort));
  if (::bind(listener, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
      ::listen(listener, 64) != 0) {
    std::perror("globe-delay-proxy: 127.0.0.1");
    return 1;
  }
  std::thread([lifetime] {
    std::this_thread::sleep_for(std::chrono::seconds(lifetime));
    std::_Exit(0);
  }).detach();
  for (;;) {
    const int client = ::accept4(listener, nullptr, nullptr, SOCK_CLOEXEC);
    if (client < 0) continue;
    std::thread(serve, client, targetPort, oneWay).detach();
  }
}
