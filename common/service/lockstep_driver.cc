#include "common/service/lockstep_driver.h"

#include <algorithm>

#include "common/core/clock.h"
#include "common/core/log.h"

namespace hexplore::service {

namespace {
// Rounds of "collect and drop" after the setups: ZeroMQ finishes connecting inproc pipes and
// registering subscriptions through commands between sockets, and a chain of them can take
// more than one round to settle.
constexpr int kSettleRounds = 3;
}  // namespace

LockstepDriver::LockstepDriver(std::vector<LockstepWorker*> workers, std::function<void()> after_step)
    : workers_(std::move(workers)), after_step_(std::move(after_step)) {}

LockstepDriver::~LockstepDriver() {
  stop();
  join();
}

void LockstepDriver::start() {
  for (size_t i = 0; i < workers_.size(); ++i) threads_.emplace_back([this, i] { serve(i); });
  driver_ = std::thread([this] { drive(); });
  std::unique_lock lock(mutex_);
  done_.wait(lock, [this] { return setup_done_; });
  if (setup_error_) {
    const std::exception_ptr error = setup_error_;
    lock.unlock();
    join();
    std::rethrow_exception(error);
  }
}

void LockstepDriver::stop() {
  std::lock_guard lock(mutex_);
  stop_ = true;
}

void LockstepDriver::join() {
  if (driver_.joinable()) driver_.join();
  for (auto& t : threads_)
    if (t.joinable()) t.join();
}

std::exception_ptr LockstepDriver::failure() const {
  std::lock_guard lock(mutex_);
  return failure_;
}

int64_t LockstepDriver::now_ns() const {
  std::lock_guard lock(mutex_);
  return now_ns_;
}

uint64_t LockstepDriver::rounds() const {
  std::lock_guard lock(mutex_);
  return rounds_;
}

void LockstepDriver::serve(size_t index) {
  LockstepWorker& worker = *workers_[index];
  uint64_t seen = 0;
  for (;;) {
    std::unique_lock lock(mutex_);
    work_.wait(lock, [&] { return generation_ != seen; });
    seen = generation_;
    if (only_ && *only_ != index) continue;
    const Phase phase = phase_;
    const int64_t now = now_ns_;
    const bool run_due = run_due_;
    lock.unlock();

    size_t collected = 0;
    std::exception_ptr error;
    try {
      switch (phase) {
        case Phase::kSetup: worker.setup(); break;
        case Phase::kCollect: collected = worker.collect(); break;
        case Phase::kDiscard:
          worker.collect();
          worker.discard();
          break;
        case Phase::kDispatch: worker.dispatch(now, run_due); break;
        case Phase::kFinish: worker.finish(); break;
      }
    } catch (...) {
      error = std::current_exception();
    }

    lock.lock();
    collected_ += collected;
    if (error && phase == Phase::kSetup && !setup_error_) setup_error_ = error;
    if (error && phase != Phase::kSetup && !failure_) failure_ = error;
    if (--pending_ == 0) done_.notify_all();
    if (phase == Phase::kFinish) return;
  }
}

size_t LockstepDriver::run_phase(Phase phase, std::optional<size_t> only, bool run_due) {
  std::unique_lock lock(mutex_);
  phase_ = phase;
  only_ = only;
  run_due_ = run_due;
  pending_ = only ? 1 : workers_.size();
  collected_ = 0;
  ++generation_;
  work_.notify_all();
  done_.wait(lock, [this] { return pending_ == 0; });
  return collected_;
}

bool LockstepDriver::should_stop() const {
  {
    std::lock_guard lock(mutex_);
    if (stop_ || failure_) return true;
  }
  return std::any_of(workers_.begin(), workers_.end(), [](const LockstepWorker* w) { return w->stop_requested(); });
}

void LockstepDriver::drive() {
  for (size_t i = 0; i < workers_.size(); ++i) {
    run_phase(Phase::kSetup, i);
    std::lock_guard lock(mutex_);
    if (setup_error_) break;
  }
  bool setup_failed = false;
  {
    std::lock_guard lock(mutex_);
    setup_failed = setup_error_ != nullptr;
  }
  if (!setup_failed)
    for (int i = 0; i < kSettleRounds; ++i) run_phase(Phase::kDiscard);
  {
    std::lock_guard lock(mutex_);
    setup_done_ = true;
  }
  done_.notify_all();

  if (!setup_failed) {
    int64_t now = 0;
    while (!should_stop()) {
      run_phase(Phase::kDispatch, std::nullopt, true);
      uint64_t rounds = 1;
      while (!should_stop() && run_phase(Phase::kCollect) > 0) {
        run_phase(Phase::kDispatch, std::nullopt, false);
        ++rounds;
      }
      if (should_stop()) break;
      if (after_step_) after_step_();
      std::optional<int64_t> next;
      for (const LockstepWorker* w : workers_)
        if (auto due = w->next_due_ns(); due && (!next || *due < *next)) next = due;
      if (!next) {
        core::LogLine(core::LogLevel::kError, "lockstep") << "no timer or deadline left in any service; stopping";
        break;
      }
      std::lock_guard lock(mutex_);
      rounds_ += rounds;
      now = std::max(*next, now + 1);
      now_ns_ = now;
    }
  }
  core::LogLine(core::LogLevel::kInfo, "lockstep") << "stepped " << core::ns_to_s(now_ns()) << " s of sim time in "
                                                    << rounds() << " rounds";
  run_phase(Phase::kFinish);
}

}  // namespace hexplore::service
