// Result<T> and Status: the way recoverable failures (a file, a decode, a preset) travel
// between layers. The error is a message a person can act on, naming the file and the problem;
// no exception crosses a layer boundary.
#pragma once

#include <cassert>
#include <optional>
#include <string>
#include <utility>

namespace relief::core::inline base {

// A failure message; wraps a string so that Result<std::string> stays unambiguous.
struct Error {
  std::string message;
};

inline Error makeError(std::string message) {
  return Error{std::move(message)};
}

template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : m_value(std::move(value)) {}              // NOLINT: implicit by design
  Result(Error error) : m_error(std::move(error.message)) {}  // NOLINT: implicit by design

  bool ok() const { return m_value.has_value(); }
  explicit operator bool() const { return ok(); }

  const T& value() const& {
    assert(ok());
    return *m_value;
  }
  T& value() & {
    assert(ok());
    return *m_value;
  }
  T&& value() && {
    assert(ok());
    return std::move(*m_value);
  }
  const T* operator->() const { return &value(); }
  T* operator->() { return &value(); }

  const std::string& error() const { return m_error; }

 private:
  std::optional<T> m_value;
  std::string m_error;
};

// Success or a failure message, for operations that return nothing.
class [[nodiscard]] Status {
 public:
  Status() = default;
  Status(Error error) : m_error(std::move(error.message)), m_failed(true) {}  // NOLINT

  static Status success() { return {}; }

  bool ok() const { return !m_failed; }
  explicit operator bool() const { return ok(); }
  const std::string& error() const { return m_error; }

 private:
  std::string m_error;
  bool m_failed = false;
};

}  // namespace relief::core::inline base
