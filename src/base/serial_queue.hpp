// Tasks run one at a time, in the order pushed, on one thread of its own, while the pushing thread
// goes on: how a batch writes one scene's files while it draws the next. It does not run tasks in
// parallel with each other, and it drops the tasks after one that throws.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace twinraster {

class SerialQueue {
 public:
  // At most `waiting` tasks wait at once; Push blocks beyond that, which bounds the memory that
  // pushed work (whole images) holds.
  explicit SerialQueue(std::size_t waiting) : waiting_(waiting) {}
  // Runs what is queued, then joins; a task's exception is dropped here (call Finish to see it).
  ~SerialQueue() { Stop(); }
  SerialQueue(const SerialQueue&) = delete;
  SerialQueue& operator=(const SerialQueue&) = delete;

  // Queues `task`; rethrows a task's exception instead, once one has thrown.
  void Push(std::function<void()> task) {
    // The thread starts with the first task, not before: a batch forks its GPU child at its first
    // draw, and a thread starting at that moment may hold a lock of the allocator's that the child
    // inherits held (under ASan the child then hung).
    if (!worker_.joinable()) worker_ = std::thread([this] { Work(); });
    std::unique_lock lock(mutex_);
    room_.wait(lock, [&] { return tasks_.size() < waiting_ || failed_; });
    if (failed_) std::rethrow_exception(failed_);
    tasks_.push_back(std::move(task));
    work_.notify_one();
  }

  // Waits until every task pushed so far has run (or one threw): the thread is then idle, holding
  // no lock, so this process may fork (a child inherits whatever locks its threads held).
  void WaitIdle() {
    std::unique_lock lock(mutex_);
    room_.wait(lock, [&] { return (tasks_.empty() && !running_) || failed_; });
  }

  // Runs what is queued, joins, and rethrows a task's exception.
  void Finish() {
    Stop();
    if (failed_) std::rethrow_exception(failed_);
  }

 private:
  void Stop() {
    {
      const std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    work_.notify_one();
    if (worker_.joinable()) worker_.join();
  }

  void Work() {
    for (;;) {
      std::function<void()> task;
      {
        std::unique_lock lock(mutex_);
        work_.wait(lock, [&] { return !tasks_.empty() || stopping_; });
        if (tasks_.empty() || failed_) return;
        task = std::move(tasks_.front());
        tasks_.pop_front();
        running_ = true;
      }
      room_.notify_all();
      try {
        task();
      } catch (...) {
        const std::lock_guard lock(mutex_);
        failed_ = std::current_exception();
      }
      {
        const std::lock_guard lock(mutex_);
        running_ = false;
      }
      room_.notify_all();
    }
  }

  const std::size_t waiting_;
  std::mutex mutex_;
  std::condition_variable work_, room_;
  std::deque<std::function<void()>> tasks_;
  bool stopping_ = false;
  bool running_ = false;  // a task is being run
  std::exception_ptr failed_;
  std::thread worker_;  // started by the first Push
};

}  // namespace twinraster
