// The runtime's Result and Status as gtest assertions that print the error's code and message.
#ifndef KILN_TESTS_RUNTIME_RUNTIME_ASSERTS_H_
#define KILN_TESTS_RUNTIME_RUNTIME_ASSERTS_H_

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <utility>

#include "kiln/diagnostic.h"
#include "kiln/result.h"
#include "kiln/runtime/color.h"
#include "kiln/runtime/renderer.h"
#include "kiln/runtime/scene.h"
#include "support/result_asserts.h"

namespace kiln::test {

// The runtime's Result/Status calls into existing objects, as assertions that print the error:
// ASSERT_TRUE(CreateInto(options, renderer)), EXPECT_TRUE(Ok(renderer.AddPack(path))).
using test::Into;
using test::Ok;

inline ::testing::AssertionResult CreateInto(const runtime::RendererOptions& options,
                                             runtime::Renderer& out) {
    return Into(runtime::Renderer::Create(options), out);
}
inline ::testing::AssertionResult CreateColorInto(const runtime::ColorOptions& options,
                                                  runtime::ColorPipeline& out) {
    return Into(runtime::ColorPipeline::Create(options), out);
}
inline ::testing::AssertionResult LoadInto(const std::string& path,
                                           runtime::Scene& out,
                                           DiagnosticList& warnings) {
    return Into(runtime::LoadGltf(path, warnings), out);
}
// Whether any warning's message holds `text`.
inline bool AnyWarning(const DiagnosticList& warnings, std::string_view text) {
    for (const Diagnostic& d : warnings.all()) {
        if (d.message.find(text) != std::string::npos) {
            return true;
        }
    }
    return false;
}

inline std::string RuntimeData(const std::string& name) {
    return std::string(KILN_RUNTIME_DATA_DIR) + "/" + name;
}

}  // namespace kiln::test

#endif  // KILN_TESTS_RUNTIME_RUNTIME_ASSERTS_H_
