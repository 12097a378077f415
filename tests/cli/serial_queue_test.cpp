// The queue a batch writes its scenes through: order, bounded waiting, and failures.
#include "base/serial_queue.hpp"

#include "support/catch.hpp"

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace twinraster;

TEST_CASE("SerialQueue runs tasks one at a time, in the order pushed, off the pushing thread", "[base][queue]") {
  std::vector<int> order;
  std::atomic<int> running{0}, most{0};
  const std::thread::id pusher = std::this_thread::get_id();
  bool elsewhere = true;
  SerialQueue queue(2);
  for (int i = 0; i < 50; ++i) {
    queue.Push([&, i] {
      most = std::max(most.load(), ++running);
      elsewhere = elsewhere && std::this_thread::get_id() != pusher;
      std::this_thread::sleep_for(std::chrono::microseconds(i % 3 * 100));
      order.push_back(i);
      --running;
    });
  }
  queue.Finish();
  REQUIRE(order.size() == 50);
  for (int i = 0; i < 50; ++i) CHECK(order[std::size_t(i)] == i);
  CHECK(most == 1);
  CHECK(elsewhere);
}

TEST_CASE("SerialQueue: a task that throws ends the queue, and its exception reaches the pusher", "[base][queue]") {
  std::vector<int> ran;
  SerialQueue queue(1);
  queue.Push([&] { ran.push_back(1); });
  queue.Push([] { throw std::runtime_error("disk full"); });
  // Later pushes are refused with that exception once the worker has met it; Finish rethrows it.
  bool refused = false;
  for (int i = 0; i < 1000 && !refused; ++i) {
    try {
      queue.Push([&] { ran.push_back(2); });
    } catch (const std::runtime_error& e) {
      CHECK(std::string(e.what()) == "disk full");
      refused = true;
    }
  }
  CHECK(refused);
  CHECK_THROWS_WITH(queue.Finish(), "disk full");
  CHECK(ran == std::vector<int>{1});
}

TEST_CASE("SerialQueue's destructor runs what was queued before it joins", "[base][queue]") {
  std::vector<int> ran;
  {
    SerialQueue queue(4);
    for (int i = 0; i < 4; ++i) {
      queue.Push([&, i] {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        ran.push_back(i);
      });
    }
  }  // as when the pushing thread unwinds from an exception of its own
  CHECK(ran == std::vector<int>{0, 1, 2, 3});
}

TEST_CASE("SerialQueue::WaitIdle returns once every task pushed has run, the one running included", "[base][queue]") {
  SerialQueue queue(4);
  queue.WaitIdle();  // nothing pushed: idle at once, no thread started
  std::atomic<int> done = 0;
  for (int i = 0; i < 3; ++i) {
    queue.Push([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      ++done;
    });
  }
  queue.WaitIdle();  // what a batch does before it forks its GPU process
  CHECK(done == 3);
  queue.Push([&] { ++done; });
  queue.Finish();
  CHECK(done == 4);
}
