// libFuzzer target: the reduction to entry points (hlsl/reduce.h) on arbitrary text, as a worker
// runs it over glslang's output. The reduced text keeps every line break (line numbers hold), the
// tokens it returns are the tokenizer's for it (the rewrite reads them instead of tokenizing
// again), reducing to both entry points at once gives what reducing to each alone gives, and
// reducing from the split of a start of the text that ends before a line break (a pass's
// preamble) gives what splitting the whole text gives; keeping every declaration keeps at least
// as much, with the same guarantees.
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
    // Keeping every declaration (the driver's names for a suggestion) keeps at least as much.
    const std::vector<kiln::hlsl::Reduced> kept =
        kiln::hlsl::ReduceToEntryPoints(text, kiln::hlsl::Tokenize(text), entries, nullptr, false);
    for (size_t e = 0; e < kept.size(); ++e) {
        if (std::count(kept[e].text.begin(), kept[e].text.end(), '\n') != lines ||
            kept[e].text.size() < both[e].text.size() ||
            !kiln::hlsl::SameTokens(kept[e].tokens, kiln::hlsl::Tokenize(kept[e].text)))
            std::abort();
    }
    const size_t cut = text.find('\n', text.size() / 2);
    if (cut == std::string::npos)
        return 0;
    const std::string start = text.substr(0, cut);
    const std::vector<kiln::hlsl::Token> head = kiln::hlsl::Tokenize(start);
    const std::vector<kiln::hlsl::Token> after = kiln::hlsl::TokenizeAfter(text, cut, head);
    if (!kiln::hlsl::SameTokens(after, kiln::hlsl::Tokenize(text)))
        return 0;  // the start ends inside a token (a comment or string across the line break)
    const auto prefix = kiln::hlsl::MakeReducePrefix(start, head);
    const std::vector<kiln::hlsl::Reduced> from_prefix =
        kiln::hlsl::ReduceToEntryPoints(text, after, entries, prefix.get());
    for (size_t e = 0; e < both.size(); ++e) {
        if (from_prefix[e].text != both[e].text ||
            !kiln::hlsl::SameTokens(from_prefix[e].tokens,
                                    kiln::hlsl::Tokenize(from_prefix[e].text)))
            std::abort();
    }
    return 0;
}
