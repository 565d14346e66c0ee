#pragma once
// Typed errors across the core boundary (STYLE 5): a computation that cannot be
// done returns an Error saying what and where; views turn it into tr() text.

#include <cassert>
#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace mozzi::core {

enum class ErrorCode {
  InvalidArgument,   // caller gave a value outside the domain (empty record, rate 0, NaN)
  ParseError,        // a file or string does not follow its format
  IoError,           // the operating system refused a read or write
  NumericalFailure,  // singular fit, no convergence, ill-conditioned geometry
  NotFound,          // a requested item (file, dataset, mode, DOF) is absent
  Unsupported,       // valid input this version does not handle
  Corrupt,           // stored data fails an integrity check
  Locked,            // the resource is held by another process
  Cancelled,         // the user or a device stopped the operation
};

// Short stable name of an error code, e.g. "parse error".
const char* errorCodeName(ErrorCode code);

struct Error {
  ErrorCode code = ErrorCode::InvalidArgument;
  std::string message;  // what is wrong, in words a user can act on
  std::string where;    // file:line, dataset, channel, DOF, parameter name...

  // "parse error: <message> (<where>)"
  std::string describe() const;
};

inline Error makeError(ErrorCode code, std::string message, std::string where = {}) {
  return Error{code, std::move(message), std::move(where)};
}

// Either a value or an Error. Minimal by design: construct from either, test
// with ok(), read with value() / error().
template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : state_(std::in_place_index<0>, std::move(value)) {}
  Result(Error error) : state_(std::in_place_index<1>, std::move(error)) {}

  bool ok() const { return state_.index() == 0; }
  explicit operator bool() const { return ok(); }

  const T& value() const& {
    assert(ok());
    return std::get<0>(state_);
  }
  T& value() & {
    assert(ok());
    return std::get<0>(state_);
  }
  T&& value() && {
    assert(ok());
    return std::get<0>(std::move(state_));
  }
  const T& operator*() const& { return value(); }
  T& operator*() & { return value(); }
  const T* operator->() const { return &value(); }
  T* operator->() { return &value(); }

  const Error& error() const {
    assert(!ok());
    return std::get<1>(state_);
  }

 private:
  std::variant<T, Error> state_;
};

template <>
class [[nodiscard]] Result<void> {
 public:
  Result() = default;
  Result(Error error) : error_(std::move(error)) {}

  bool ok() const { return !error_.has_value(); }
  explicit operator bool() const { return ok(); }
  const Error& error() const {
    assert(!ok());
    return *error_;
  }

 private:
  std::optional<Error> error_;
};

}  // namespace mozzi::core

// Error propagation, the one way (issue 24). Inside a function returning any
// Result<U>:
//   MOZZI_TRY(expr);                 // expr is a Result<T>; on error, return it
//   MOZZI_TRY_ASSIGN(decl, expr);    // on success, `decl = std::move(value)`
// e.g. `MOZZI_TRY(tx.begun());` and
//      `MOZZI_TRY_ASSIGN(const std::int64_t id, stmt.insert("cannot store the hit", where));`
// Each evaluates expr exactly once. MOZZI_TRY_ASSIGN declares a hidden local
// named after the line, so it is a statement, not an expression: one per line.
// Where the error needs more context (a different code or `where`), write the
// test by hand.
#define MOZZI_TRY(...)                                                                               \
  do {                                                                                               \
    if (auto mozziTryResult_ = (__VA_ARGS__); !mozziTryResult_.ok()) return mozziTryResult_.error(); \
  } while (false)

#define MOZZI_TRY_CONCAT_INNER_(a, b) a##b
#define MOZZI_TRY_CONCAT_(a, b) MOZZI_TRY_CONCAT_INNER_(a, b)
#define MOZZI_TRY_ASSIGN_IMPL_(tmp, decl, ...) \
  auto tmp = (__VA_ARGS__);                    \
  if (!tmp.ok()) return tmp.error();           \
  decl = std::move(tmp).value()
#define MOZZI_TRY_ASSIGN(decl, ...) \
  MOZZI_TRY_ASSIGN_IMPL_(MOZZI_TRY_CONCAT_(mozziTryValue_, __LINE__), decl, __VA_ARGS__)
