// Point counts for the numerical stress tests: at least 10^7 in a normal build, a twentieth under
// ASan or TSan (CI runs the whole suite a second time under ASan+UBSan, where time is short).
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <string>

#include <gtest/gtest.h>

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define GLOBE_STRESS_UNDER_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define GLOBE_STRESS_UNDER_SANITIZER 1
#endif
#endif

namespace globe::stress {

inline constexpr bool kUnderSanitizer =
#ifdef GLOBE_STRESS_UNDER_SANITIZER
    true;
#else
    false;
#endif

// The issue asks for >= 10^7 points per stress test.
inline constexpr uint64_t kStressPoints = 10'000'000;

// normalCount in a normal build, normalCount / 20 under a sanitizer.
constexpr uint64_t stressCount(uint64_t normalCount) {
  return kUnderSanitizer ? normalCount / 20 : normalCount;
}

// Wall-clock and process CPU time since construction, as "W s wall, C s CPU" (the CPU time is
// what a loaded machine does not inflate).
class Stopwatch {
 public:
  std::string elapsed() const {
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart_).count();
    const double cpu = static_cast<double>(std::clock() - cpuStart_) / CLOCKS_PER_SEC;
    char text[64];
    std::snprintf(text, sizeof text, "%.2f s wall, %.2f s CPU", wall, cpu);
    return text;
  }

 private:
  std::chrono::steady_clock::time_point wallStart_ = std::chrono::steady_clock::now();
  std::clock_t cpuStart_ = std::clock();
};

// Prints one summary line and records it as a test property (visible in the XML report).
inline void reportStress(const std::string& name, const std::string& summary) {
  std::printf("[ stress %s ] %s\n", name.c_str(), summary.c_str());
  std::string key = "stress_" + name;
  for (char& c : key) c = c == ' ' ? '_' : c;
  ::testing::Test::RecordProperty(key, summary);
}

}  // namespace globe::stress
