// Value-or-error used by every stage. Errors are plain text with context,
// e.g. "model.npz: 'shapedirs' has shape (6890,3,10); expected (N,3,B) with N=6890".
// One channel for failures keeps readers, the pipeline and the CLI simple:
// nothing throws across a module boundary.
#pragma once

#include <string>
#include <utility>
#include <variant>

namespace smpl {

// What kind of failure an error is, for the exit code of a command-line
// program (cli/exit_code.h). Readers and the math leave it Unspecified; the
// stage that knows (argument checks, loading, exporting, writing) sets it.
enum class ErrorKind { Unspecified, Usage, Load, Export, Write };

struct Error {
  std::string message;
  ErrorKind kind = ErrorKind::Unspecified;
};

inline Error makeError(std::string message, ErrorKind kind = ErrorKind::Unspecified) {
  return Error{std::move(message), kind};
}

// [[nodiscard]]: a Result or Status that is dropped is a compile warning
// (-Wunused-result), so an error cannot be ignored by accident; cast to
// (void) where dropping one is the intent, with a comment saying why.
template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : v_(std::move(value)) {}      // NOLINT: implicit by design
  Result(Error error) : v_(std::move(error)) {}  // NOLINT
  bool ok() const { return v_.index() == 0; }
  explicit operator bool() const { return ok(); }
  T& value() & { return std::get<0>(v_); }
  const T& value() const& { return std::get<0>(v_); }
  T&& value() && { return std::get<0>(std::move(v_)); }
  T* operator->() { return &std::get<0>(v_); }
  const T* operator->() const { return &std::get<0>(v_); }
  T& operator*() { return value(); }
  const T& operator*() const { return value(); }
  const Error& error() const { return std::get<1>(v_); }
  const std::string& message() const { return std::get<1>(v_).message; }
  ErrorKind kind() const { return std::get<1>(v_).kind; }

 private:
  std::variant<T, Error> v_;
};

// Result for operations with no value.
class [[nodiscard]] Status {
 public:
  Status() = default;
  Status(Error error) : error_(std::move(error)), failed_(true) {}  // NOLINT
  static Status success() { return Status(); }
  bool ok() const { return !failed_; }
  explicit operator bool() const { return ok(); }
  const std::string& message() const { return error_.message; }
  ErrorKind kind() const { return error_.kind; }
  Error error() const { return error_; }

 private:
  Error error_;
  bool failed_ = false;
};

}  // namespace smpl
