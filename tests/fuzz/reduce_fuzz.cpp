// libFuzzer target: the reduction to entry points (hlsl/reduce.h) on arbitrary text, as a worker
// runs it over glslang's output. The reduced text keeps every line break (line numbers hold), the
// tokens it returns are the tokenizer's for it (the rewrite reads them instead of tokenizing
// again), and reducing to both entry points at once gives what reducing to each alone gives.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "hlsl/reduce.h"
#include "hlsl/tokens.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const std::vector<std::string> entries = {"vert", "frag"};
    const std::vector<kiln::hlsl::Reduced> both =
        kiln::hlsl::ReduceToEntryPoints(text, kiln::hlsl::Tokenize(text), entries);
    if (both.size() != entries.size())
        std::abort();
    const auto lines = std::count(text.begin(), text.end(), '\n');
    for (size_t e = 0; e < both.size(); ++e) {
        const kiln::hlsl::Reduced& r = both[e];
        if (std::count(r.text.begin(), r.text.end(), '\n') != lines)
            std::abort();
        if (!kiln::hlsl::SameTokens(r.tokens, kiln::hlsl::Tokenize(r.text)))
            std::abort();
        if (kiln::hlsl::ReduceToEntryPoint(text, entries[e]).text != r.text)
            std::abort();
    }
    return 0;
}
