// Tests for runTogether: both stages run, at the same time when asked, one
// after the other otherwise, and a throw of either reaches the caller only
// after both are done.
#include "core/parallel.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>

namespace smpl {
namespace {

// True once `flag` is set, waiting at most two seconds.
bool waitFor(const std::atomic<bool>& flag) {
  for (int i = 0; i < 2000 && !flag; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  return flag;
}

TEST(RunTogether, TogetherRunsBothAtOnce) {
  std::atomic<bool> first_started{false}, second_started{false};
  bool first_saw_second = false, second_saw_first = false;
  runTogether(
      true,
      [&] {
        first_started = true;
        first_saw_second = waitFor(second_started);
      },
      [&] {
        second_started = true;
        second_saw_first = waitFor(first_started);
      });
  EXPECT_TRUE(first_saw_second);  // each saw the other running: not one after the other
  EXPECT_TRUE(second_saw_first);
}

TEST(RunTogether, NotTogetherRunsFirstThenSecondOnTheCallingThread) {
  std::string order;
  const std::thread::id caller = std::this_thread::get_id();
  bool same_thread = true;
  runTogether(
      false,
      [&] {
        order += "1";
        same_thread = same_thread && std::this_thread::get_id() == caller;
      },
      [&] {
        order += "2";
        same_thread = same_thread && std::this_thread::get_id() == caller;
      });
  EXPECT_EQ(order, "12");
  EXPECT_TRUE(same_thread);
}

TEST(RunTogether, ThrowOfSecondReachesTheCallerAfterFirstFinished) {
  for (const bool together : {false, true}) {
    std::atomic<bool> first_done{false};
    EXPECT_THROW(runTogether(
                     together,
                     [&] {
                       std::this_thread::sleep_for(std::chrono::milliseconds(20));
                       first_done = true;
                     },
                     [] { throw std::runtime_error("second"); }),
                 std::runtime_error);
    EXPECT_TRUE(first_done);
  }
}

TEST(RunTogether, ThrowOfFirstWaitsForSecond) {
  std::atomic<bool> second_done{false};
  EXPECT_THROW(runTogether(
                   true, [] { throw std::runtime_error("first"); },
                   [&] {
                     std::this_thread::sleep_for(std::chrono::milliseconds(20));
                     second_done = true;
                   }),
               std::runtime_error);
  EXPECT_TRUE(second_done);  // joined before the throw went on
}

}  // namespace
}  // namespace smpl
