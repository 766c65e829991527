// Status and Expected<T>: how the core reports errors (never prints, never throws to callers).
//
// Every public core function that can fail returns a Status or an Expected<T>. The message
// names the culprit ("vertex 12 has a non-finite coordinate"), so a filter can show it as is.
#pragma once

#include <string>
#include <utility>
#include <variant>

namespace gr {

enum class StatusCode {
  Ok,
  InvalidInput,  ///< empty mesh, no faces, bad indices, NaN, bad parameters or fields
  NonManifold,   ///< the algorithm needs a manifold and the input is not
  Degenerate,    ///< faces that repeat a vertex, or geometry the algorithm cannot use
  NotConverged,  ///< an iteration stopped before reaching its tolerance
  Cancelled,     ///< the user asked to stop (progress callback returned false)
  OutOfMemory,   ///< an allocation failed (std::bad_alloc)
  Internal,      ///< a broken invariant: a bug, not a property of the input
};

/// Short name of a code, for logs ("InvalidInput").
const char* toString(StatusCode code);

struct Status {
  StatusCode code = StatusCode::Ok;
  std::string message;

  static Status ok() { return {}; }
  bool isOk() const { return code == StatusCode::Ok; }
  explicit operator bool() const { return isOk(); }
};

inline Status invalidInput(std::string msg) { return {StatusCode::InvalidInput, std::move(msg)}; }
inline Status nonManifold(std::string msg) { return {StatusCode::NonManifold, std::move(msg)}; }
inline Status degenerate(std::string msg) { return {StatusCode::Degenerate, std::move(msg)}; }
inline Status cancelled(std::string msg = "cancelled by the user") { return {StatusCode::Cancelled, std::move(msg)}; }
inline Status outOfMemory(std::string msg = "out of memory") { return {StatusCode::OutOfMemory, std::move(msg)}; }
inline Status internalError(std::string msg) { return {StatusCode::Internal, std::move(msg)}; }

/// A value of type T, or the Status saying why there is none. An Expected made from a Status is
/// always an error: given an OK status (no value and no error, a bug in the caller) it holds
/// {Internal, "an Expected was given an OK status and no value (a bug)"}.
template <class T>
class Expected {
 public:
  Expected(T value) : data_(std::move(value)) {}  // NOLINT: implicit on purpose
  Expected(Status status)                         // NOLINT: implicit on purpose
      : data_(status.isOk() ? internalError("an Expected was given an OK status and no value (a bug)")
                            : std::move(status)) {}

  bool hasValue() const { return std::holds_alternative<T>(data_); }
  explicit operator bool() const { return hasValue(); }

  T& value() & { return std::get<T>(data_); }
  const T& value() const& { return std::get<T>(data_); }
  T&& value() && { return std::get<T>(std::move(data_)); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }

  /// The error; Status::ok() when a value is held.
  Status status() const { return hasValue() ? Status::ok() : std::get<Status>(data_); }

 private:
  std::variant<T, Status> data_;
};

}  // namespace gr
