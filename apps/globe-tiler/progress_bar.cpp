#include "apps/globe-tiler/progress_bar.hpp"

#include <algorithm>
#include <cmath>

namespace globe::tiler_app {

ProgressBar::ProgressBar(bool enabled, std::FILE* out) : enabled_(enabled), out_(out) {}

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

void ProgressBar::report(const tiling::Progress& progress) {
  if (!enabled_) return;
  // The rate counts from the first report: the tiler reports once its tiles start.
  if (!started_) start_ = std::chrono::steady_clock::now();
  started_ = true;
  if (progress.finished) {
    draw(progress);
    std::fputc('\n', out_);
    return;
  }
  const auto now = std::chrono::steady_clock::now();
  if (now - lastDraw_ < std::chrono::milliseconds(200)) return;
  lastDraw_ = now;
  draw(progress);
}

void ProgressBar::draw(const tiling::Progress& progress) {
  constexpr int kWidth = 30;
  const uint64_t done = progress.tilesDone, total = progress.tilesTotal;
  const double fraction = total == 0 ? 1.0 : static_cast<double>(done) / static_cast<double>(total);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = elapsed > 0 ? static_cast<double>(done) / elapsed : 0;
  const std::string eta =
      rate > 0 ? formatDuration(static_cast<double>(total - done) / rate) : std::string("--:--");
  std::string bar(kWidth, ' ');
  std::fill_n(bar.begin(), static_cast<int>(fraction * kWidth), '#');
  std::fprintf(out_, "\r%-14s [%s] %5.1f%%  %llu/%llu tiles  %.0f tiles/s  ETA %s ",
               progress.label.c_str(), bar.c_str(), 100.0 * fraction,
               static_cast<unsigned long long>(done), static_cast<unsigned long long>(total), rate,
               eta.c_str());
  std::fflush(out_);
}

}  // namespace globe::tiler_app
