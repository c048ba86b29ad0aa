// kiln::Result and kiln::Status as gtest assertions that print the error's code and message:
// ASSERT_TRUE(Into(Pack::Open(bytes), pack)), EXPECT_TRUE(Ok(renderer.AddPack(path))).
// Header-only, so that test binaries that do not link the compiler use it too.
#ifndef KILN_TESTS_SUPPORT_RESULT_ASSERTS_H_
#define KILN_TESTS_SUPPORT_RESULT_ASSERTS_H_

#include <gtest/gtest.h>

#include <utility>

#include "kiln/diagnostic.h"
#include "kiln/result.h"

namespace kiln::test {

inline ::testing::AssertionResult Ok(const Status& status) {
    if (status.ok()) {
        return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure()
           << FormatDiagCode(status.error().code) << ": " << status.error().message;
}

// Moves the value of `result` into `out`; fails with the error otherwise.
template <class T>
::testing::AssertionResult Into(Result<T> result, T& out) {
    if (!result) {
        return ::testing::AssertionFailure()
               << FormatDiagCode(result.error().code) << ": " << result.error().message;
    }
    out = std::move(result).value();
    return ::testing::AssertionSuccess();
}

}  // namespace kiln::test

#endif  // KILN_TESTS_SUPPORT_RESULT_ASSERTS_H_
