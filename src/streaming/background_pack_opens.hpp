// Pack indexes read on a task runner for a render thread that must not wait on a server (the
// terrain scene and the imagery layers of a remote pyramid or layer): each pack queued once at a
// time. The bookkeeping is shared with the tasks, so its owner may go while one still runs (the
// task must then hold whatever its `open` uses).
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <set>
#include <utility>

#include "core/task_runner.hpp"
#include "formats/pack_format.hpp"

namespace globe::streaming {

class BackgroundPackOpens {
 public:
  // Posts open() to the runner unless `pack` is already queued or being read.
  void post(core::TaskRunner& runner, const formats::PackId& pack, std::function<void()> open) {
    {
      std::lock_guard lock(state_->mutex);
      if (!state_->packs.insert(pack).second) return;
    }
    ++state_->pending;
    runner.post([state = state_, pack, open = std::move(open)] {
      open();
      {
        std::lock_guard lock(state->mutex);
        state->packs.erase(pack);
      }
      ++state->finished;
      --state->pending;
    });
  }
  // Queued or being read.
  int pending() const { return state_->pending.load(); }
  // Read since the last call: a reason to draw again.
  int takeFinished() { return state_->finished.exchange(0); }

 private:
  struct State {
    std::mutex mutex;
    std::set<formats::PackId> packs;  // queued or being read; guarded by mutex
    std::atomic<int> pending{0};
    std::atomic<int> finished{0};
  };
  std::shared_ptr<State> state_ = std::make_shared<State>();
};

}  // namespace globe::streaming
