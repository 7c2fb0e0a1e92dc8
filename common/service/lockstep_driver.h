#pragma once
// Lockstep: the reproducible fast mode of a composed process. Every service keeps its own loop
// thread, but a driver moves all of them through the same steps on a virtual clock, so that sim
// time advances only when every service has handled everything of the current step:
//
//   setup      one service at a time, in the order added (who is subscribed to whom when a
//              setup publishes is then fixed); what setups published is discarded;
//   at time t  every loop runs its timers and deadlines due by t, then, while any message is
//              in flight, every loop collects what reached it and handles it (still at t);
//   then t jumps to the earliest timer or deadline of any loop.
//
// Collecting and handling are separate phases with a barrier between them, so what a service
// receives in a step never depends on how fast another thread ran. The results depend only on
// the team file, the seed and the code — not on machine load.

#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace hexplore::service {

// What the driver asks of one service; every call is made on that service's own thread.
class LockstepWorker {
 public:
  virtual ~LockstepWorker() = default;
  // Throws when setup fails.
  virtual void setup() = 0;
  virtual size_t collect() = 0;
  virtual void discard() = 0;
  // Throws when a callback fails.
  virtual void dispatch(int64_t now_ns, bool run_due) = 0;
  virtual std::optional<int64_t> next_due_ns() const = 0;
  virtual bool stop_requested() const = 0;
  // Last words and socket closing; must not throw.
  virtual void finish() = 0;
};

class LockstepDriver {
 public:
  // `workers` must outlive the driver. `after_step` (optional) runs on the driver thread after
  // every step, while no worker runs (the radio model schedules the step's messages there).
  explicit LockstepDriver(std::vector<LockstepWorker*> workers, std::function<void()> after_step = {});
  ~LockstepDriver();
  LockstepDriver(const LockstepDriver&) = delete;
  LockstepDriver& operator=(const LockstepDriver&) = delete;

  // Starts the threads and runs every setup; returns once they are done and stepping has begun.
  // Rethrows the first setup's exception (after finishing every worker and joining).
  void start();
  // Ends stepping after the current phase (also when a worker's loop asks to stop). Thread-safe.
  void stop();
  void join();
  // The exception that stopped a dispatch, if any.
  std::exception_ptr failure() const;
  // Virtual time reached, and how many collect/dispatch rounds it took (for logs and tests).
  int64_t now_ns() const;
  uint64_t rounds() const;

 private:
  enum class Phase { kSetup, kCollect, kDiscard, kDispatch, kFinish };
  void serve(size_t index);
  void drive();
  // Runs `phase` on the selected workers (all when `only` is empty) and waits for them.
  // Returns the sum of their collect counts.
  size_t run_phase(Phase phase, std::optional<size_t> only = std::nullopt, bool run_due = false);
  bool should_stop() const;

  std::vector<LockstepWorker*> workers_;
  std::function<void()> after_step_;
  std::vector<std::thread> threads_;
  std::thread driver_;

  mutable std::mutex mutex_;
  std::condition_variable work_;
  std::condition_variable done_;
  uint64_t generation_ = 0;
  Phase phase_ = Phase::kSetup;
  std::optional<size_t> only_;
  bool run_due_ = false;
  size_t pending_ = 0;
  size_t collected_ = 0;
  std::exception_ptr setup_error_;
  std::exception_ptr failure_;
  bool stop_ = false;
  bool setup_done_ = false;
  int64_t now_ns_ = 0;
  uint64_t rounds_ = 0;
};

}  // namespace hexplore::service
