// One view of globe regress after its snapshot process ended: an error (it did not render, drew
// nothing, has no reference), a pass or a failure against its reference by its tolerance, and
// with --update a new or rewritten reference.
#pragma once

#include <filesystem>
#include <string>

#include "apps/globe/snapshot_processes.hpp"
#include "regression/regression_report.hpp"
#include "regression/regression_suite.hpp"

namespace globe::app {

std::filesystem::path actualPath(const std::filesystem::path& outFolder, const std::string& name);

regression::ViewOutcome judgeView(const regression::RegressionSuite& suite,
                                  const regression::RegressionView& view,
                                  const std::filesystem::path& outFolder, const SnapshotExit& exit,
                                  bool update);

}  // namespace globe::app
