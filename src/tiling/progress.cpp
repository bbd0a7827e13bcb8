#include "tiling/progress.hpp"

#include <algorithm>
#include <cmath>

namespace globe::tiling {

ProgressBar::ProgressBar(uint64_t total, bool enabled, std::FILE* out)
    : total_(total), enabled_(enabled), out_(out), start_(std::chrono::steady_clock::now()) {}

std::string formatDuration(double seconds) {
  const auto s = static_cast<long>(std::max(0.0, std::round(seconds)));
  char text[32];
  if (s >= 3600) {
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  } else {
    std::snprintf(text, sizeof text, "%02ld:%02ld", s / 60, s % 60);
  }
  return text;
}

void ProgressBar::update(uint64_t done, const std::string& label) {
  const auto now = std::chrono::steady_clock::now();
  if (!enabled_ || now - lastDraw_ < std::chrono::milliseconds(200)) return;
  lastDraw_ = now;
  draw(done, label);
}

void ProgressBar::finish(uint64_t done, const std::string& label) {
  if (!enabled_) return;
  draw(done, label);
  std::fputc('\n', out_);
}

void ProgressBar::draw(uint64_t done, const std::string& label) {
  constexpr int kWidth = 30;
  const double fraction =
      total_ == 0 ? 1.0 : static_cast<double>(done) / static_cast<double>(total_);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = elapsed > 0 ? static_cast<double>(done) / elapsed : 0;
  const std::string eta =
      rate > 0 ? formatDuration(static_cast<double>(total_ - done) / rate) : std::string("--:--");
  std::string bar(kWidth, ' ');
  std::fill_n(bar.begin(), static_cast<int>(fraction * kWidth), '#');
  std::fprintf(out_, "\r%-14s [%s] %5.1f%%  %llu/%llu tiles  %.0f tiles/s  ETA %s ", label.c_str(),
               bar.c_str(), 100.0 * fraction, static_cast<unsigned long long>(done),
               static_cast<unsigned long long>(total_), rate, eta.c_str());
  std::fflush(out_);
}

void waitForLevel(ProgressBar& progress, std::mutex& mutex, std::condition_variable& finished,
                  const unsigned& running, const std::atomic<uint64_t>& done, uint32_t level,
                  uint32_t maxLevel) {
  const std::string label = "level " + std::to_string(level) + "/" + std::to_string(maxLevel);
  std::unique_lock lock(mutex);
  while (running > 0) {
    finished.wait_for(lock, std::chrono::milliseconds(100));
    lock.unlock();
    progress.update(done, label);
    lock.lock();
  }
}

}  // namespace globe::tiling
