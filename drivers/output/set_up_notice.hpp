#pragma once
/// "<what> …" on stderr when the work that follows this notice's construction
/// (a run's set-up: reading the scene, building a model of millions of
/// particles, probing its cost) lasts beyond a few seconds, so that a run is
/// never silent at its start; nothing when it ends sooner. One waiting thread,
/// joined when the notice is destroyed.
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace ffp {

class SetUpNotice {
 public:
  explicit SetUpNotice(std::string what, std::chrono::milliseconds after = std::chrono::seconds(3));
  ~SetUpNotice();
  SetUpNotice(const SetUpNotice&) = delete;
  SetUpNotice& operator=(const SetUpNotice&) = delete;

 private:
  std::mutex mutex_;
  std::condition_variable done_changed_;
  bool done_ = false;
  std::thread waiter_;
};

}  // namespace ffp
