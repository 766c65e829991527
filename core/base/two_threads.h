// onTwoThreads: one piece of work split in two, the second share on a helper thread.
//
// work(true) runs on a helper thread when one is to be had (else here, first), work(false) here;
// an exception of either is carried to this thread and thrown after the helper is joined (an
// exception may not leave a thread). The two shares must not write the same data.
#pragma once

#include <exception>
#include <optional>
#include <system_error>
#include <thread>

namespace gr {

template <class Work>
void onTwoThreads(const Work& work) {
  std::exception_ptr failed;
  const auto helperShare = [&] {
    try {
      work(true);
    } catch (...) {
      failed = std::current_exception();
    }
  };
  std::optional<std::thread> helper;
  try {
    helper.emplace(helperShare);
  } catch (const std::system_error&) {
    helperShare();  // no thread to be had: its share here, first
  }
  std::exception_ptr failedHere;
  try {
    work(false);
  } catch (...) {
    failedHere = std::current_exception();
  }
  if (helper) helper->join();
  if (failedHere) std::rethrow_exception(failedHere);
  if (failed) std::rethrow_exception(failed);
}

}  // namespace gr
