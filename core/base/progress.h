// Progress: a null-safe, throttled progress reporter that can also cancel a long computation.
//
// Wraps any callable bool(int percent, const char* message). The callable returning false means
// "cancel": report() then returns false and the algorithm returns StatusCode::Cancelled.
// report() is cheap to call in a hot loop: it forwards only when the integer percent changes.
#pragma once

#include <functional>
#include <utility>

namespace gr {

class Progress {
 public:
  using Callback = std::function<bool(int percent, const char* message)>;

  Progress() = default;
  explicit Progress(Callback cb) : cb_(std::move(cb)) {}

  /// Reports `fraction` in [0, 1] of the whole task; false if the user cancelled.
  bool report(double fraction, const char* message) {
    if (!cb_) return true;
    int percent = static_cast<int>(fraction * 100.0);
    percent = percent < 0 ? 0 : (percent > 100 ? 100 : percent);
    if (percent == lastPercent_) return true;
    lastPercent_ = percent;
    return cb_(percent, message);
  }

  /// A Progress whose [0,1] maps to [begin, end] of this one (for a step of a longer task).
  Progress sub(double begin, double end) const {
    if (!cb_) return {};
    Callback parent = cb_;
    return Progress([parent, begin, end](int percent, const char* msg) {
      return parent(static_cast<int>(100.0 * begin + (end - begin) * percent), msg);
    });
  }

 private:
  Callback cb_;
  int lastPercent_ = -1;
};

}  // namespace gr
