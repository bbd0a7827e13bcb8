// The suite file of globe regress: named views, each the argument list of `globe snapshot`
// without -o, and the tolerances a view must stay within. docs/regression.md shows one:
//   {"tolerance": {"channel": 16, "fraction": 0.001, "ssim": 0.99}, "timeoutSeconds": 120,
//    "views": [{"name": "summit", "snapshot": ["pyramid", "--camera", "138.7,35.3,6000"],
//               "tolerance": {"fraction": 0.01}}]}
// Paths in the arguments are relative to the suite file's folder (the views run there); the
// references are that folder's references/NAME.png.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/result.hpp"

namespace globe::regression {

// A view fails when more than `differingFraction` of its pixels differ by more than
// `channelThreshold` in a channel, or when its mean structural similarity is under `minimumSsim`.
// The defaults are strict (a renderer is deterministic on one machine); docs/regression.md says
// what to allow across Mesa versions and GPUs.
struct Tolerance {
  int channelThreshold = 16;
  double differingFraction = 0.001;
  double minimumSsim = 0.99;
};

struct RegressionView {
  std::string name;  // letters, digits, '_', '-', '.': it names files
  std::vector<std::string> snapshotArguments;
  Tolerance tolerance;
};

struct RegressionSuite {
  std::filesystem::path folder;  // the suite file's: where views run and references live
  int timeoutSeconds = 120;      // each view's --timeout (its tiles' wait)
  std::vector<RegressionView> views;
};

inline constexpr size_t kMaxSuiteBytes = size_t{16} << 20;
inline constexpr size_t kMaxSuiteViews = 10000;

// Reads and checks a suite; errors name the file, the view and the field.
Result<RegressionSuite> loadRegressionSuite(const std::filesystem::path& file);

// The same from text (`file` names it in errors and gives the folder).
Result<RegressionSuite> parseRegressionSuite(const std::string& text,
                                             const std::filesystem::path& file);

std::filesystem::path referencePath(const RegressionSuite& suite, const std::string& viewName);

}  // namespace globe::regression
