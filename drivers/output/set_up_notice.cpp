#include "drivers/output/set_up_notice.hpp"

#include <cstdio>

namespace ffp {

SetUpNotice::SetUpNotice(std::string what, std::chrono::milliseconds after)
    : waiter_([this, what = std::move(what), after] {
        std::unique_lock lock(mutex_);
        if (done_changed_.wait_for(lock, after, [this] { return done_; })) return;
        std::fprintf(stderr, "%s …\n", what.c_str());
        std::fflush(stderr);
      }) {}

SetUpNotice::~SetUpNotice() {
  {
    std::lock_guard lock(mutex_);
    done_ = true;
  }
  done_changed_.notify_one();
  waiter_.join();
}

}  // namespace ffp
