// status.h -- success or a message saying why not, for edits users can get wrong.
#pragma once

#include <cassert>
#include <optional>
#include <string>
#include <utility>

namespace procex {

// An edit that may be refused (link type mismatch, cycle, unknown parameter...).
// The message is written for the person who tried the edit.
class [[nodiscard]] Status {
 public:
  static Status ok() { return Status(); }
  static Status error(std::string message) { return Status(std::move(message)); }

  bool is_ok() const { return !message_; }
  explicit operator bool() const { return is_ok(); }
  // Empty when ok.
  const std::string& message() const {
    static const std::string kEmpty;
    return message_ ? *message_ : kEmpty;
  }

 private:
  Status() = default;
  explicit Status(std::string m) : message_(std::move(m)) {}
  std::optional<std::string> message_;
};

// A value or the reason there is none.
template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : value_(std::move(value)) {}  // NOLINT: implicit on purpose
  Result(Status failure) : failure_(std::move(failure)) {
    assert(!failure_.is_ok() && "Result: construct from a value, or from a failed Status");
  }

  bool is_ok() const { return value_.has_value(); }
  explicit operator bool() const { return is_ok(); }
  const T& value() const& {
    assert(value_ && "Result::value() on a failure: check is_ok() first");
    return *value_;
  }
  T& value() & {
    assert(value_ && "Result::value() on a failure: check is_ok() first");
    return *value_;
  }
  const T& operator*() const& { return value(); }
  const std::string& message() const { return failure_.message(); }
  Status status() const { return failure_; }

 private:
  std::optional<T> value_;
  Status failure_ = Status::ok();
};

}  // namespace procex
