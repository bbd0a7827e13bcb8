// Where the loader's background work runs: an injected task runner (cesium-native's
// ITaskProcessor), so the viewer uses worker threads and tests run tasks inline, in order.
#pragma once

#include <functional>

namespace globe::core {

class TaskRunner {
 public:
  virtual ~TaskRunner() = default;
  // Runs the task some time later, on a thread of the runner's choosing. Tasks must not throw.
  virtual void post(std::function<void()> task) = 0;
};

}  // namespace globe::core
