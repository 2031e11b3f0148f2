#pragma once
/// A value or an error message, returned wherever user input can be wrong (files, settings, cases).
/// Programmer errors are asserts instead; see docs/design.md.

#include <cassert>
#include <optional>
#include <string>
#include <utility>

namespace shatter {

/// What an error is about: the input (a file, a flag, a setting, a request an algorithm documents it
/// cannot honour), or a fault of an algorithm's code that the host caught (an exception, a null, a
/// result that failed the host's output checks: harness/plugins/plugin_guard.h). The first is the
/// user's to fix (exit code 2); the second fails that algorithm's result (exit code 1).
enum class ErrorCause : unsigned char {
  input,            ///< the input cannot be used
  algorithm_fault,  ///< an algorithm's code misbehaved on an input that was accepted
};

/// An error meant for the user: one line that names the file, key or line and what is wrong.
struct Error {
  std::string message;                 ///< one line, no trailing newline
  ErrorCause cause = ErrorCause::input;  ///< whose the error is
};

/// Either a `T` or an `Error`.
template <class T>
class [[nodiscard]] Result {
 public:
  /// A successful result.
  Result(T value) : value_(std::move(value)) {}  // NOLINT(google-explicit-constructor)
  /// A failed result.
  Result(Error error) : error_(std::move(error)) {}  // NOLINT(google-explicit-constructor)

  /// True when the result holds a value.
  [[nodiscard]] bool ok() const { return value_.has_value(); }
  explicit operator bool() const { return ok(); }
  /// The value; only valid when ok().
  T& value() & { assert(ok()); return *value_; }
  const T& value() const& { assert(ok()); return *value_; }
  T&& value() && { assert(ok()); return std::move(*value_); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }
  /// The error; only valid when !ok().
  [[nodiscard]] const Error& error() const { assert(!ok()); return error_; }

 private:
  std::optional<T> value_;
  Error error_;
};

/// Success or an error, for operations without a value.
class [[nodiscard]] Status {
 public:
  Status() = default;
  Status(Error error) : error_(std::move(error)), failed_(true) {}  // NOLINT(google-explicit-constructor)
  [[nodiscard]] bool ok() const { return !failed_; }
  explicit operator bool() const { return ok(); }
  [[nodiscard]] const Error& error() const { assert(failed_); return error_; }

 private:
  Error error_;
  bool failed_ = false;
};

}  // namespace shatter
