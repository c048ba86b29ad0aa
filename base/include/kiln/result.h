// The one error convention at Kiln's API boundaries: a function that can fail returns
// Result<T> (a value or an Error) or Status (Result<void>: nothing or an Error). An Error has a
// stable code (kiln/diag_code.h) and one lower-case sentence naming what failed and where; no
// severity in the text. Nothing throws across a library boundary. Warnings and errors about
// positions in an input go into a DiagnosticList (kiln/diagnostic.h) instead.
#ifndef KILN_RESULT_H_
#define KILN_RESULT_H_

#include <cassert>
#include <optional>
#include <string>
#include <utility>
#include <variant>

#include "kiln/diag_code.h"

namespace kiln {

struct Error {
    DiagCode code = DiagCode::kInternalError;
    std::string message;  // lower-case, one sentence, no trailing period
};

template <typename T>
class [[nodiscard]] Result {
  public:
    Result(T value) : v_(std::move(value)) {}      // NOLINT(google-explicit-constructor)
    Result(Error error) : v_(std::move(error)) {}  // NOLINT(google-explicit-constructor)

    bool ok() const { return v_.index() == 0; }
    explicit operator bool() const { return ok(); }

    T& value() & {
        assert(ok());
        return std::get<0>(v_);
    }
    const T& value() const& {
        assert(ok());
        return std::get<0>(v_);
    }
    T&& value() && {
        assert(ok());
        return std::get<0>(std::move(v_));
    }
    const Error& error() const {
        assert(!ok());
        return std::get<1>(v_);
    }

  private:
    std::variant<T, Error> v_;
};

// Success, or an Error: `if (Status s = f(); !s.ok()) return s;`. It has no operator bool, so
// that `if (auto e = f())` (the std::optional<Error> idiom, true on failure) cannot compile
// with the opposite meaning.
template <>
class [[nodiscard]] Result<void> {
  public:
    Result() = default;
    Result(Error error) : error_(std::move(error)) {}  // NOLINT(google-explicit-constructor)

    bool ok() const { return !error_.has_value(); }
    const Error& error() const {
        assert(!ok());
        return *error_;
    }

  private:
    std::optional<Error> error_;
};

using Status = Result<void>;

}  // namespace kiln

#endif  // KILN_RESULT_H_
