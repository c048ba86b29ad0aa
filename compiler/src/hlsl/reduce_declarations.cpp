#include "hlsl/reduce_declarations.h"

#include <cstdint>
#include <string_view>

namespace kiln::hlsl {
namespace {

constexpr size_t kNone = SIZE_MAX;

struct Reader {
    std::string_view text;
    const std::vector<Token>& tok;
    size_t end;

    std::string_view At(size_t k) const {
        return k < end ? text.substr(tok[k].begin, tok[k].end - tok[k].begin) : std::string_view();
    }
    bool Ident(size_t k) const { return k < end && tok[k].ident; }
};

bool IsResourceType(std::string_view w) {
    static constexpr std::string_view kTypes[] = {"Texture1D",
                                                  "Texture1DArray",
                                                  "Texture2D",
                                                  "Texture2DArray",
                                                  "Texture2DMS",
                                                  "Texture2DMSArray",
                                                  "Texture3D",
                                                  "TextureCube",
                                                  "TextureCubeArray",
                                                  "RWTexture1D",
                                                  "RWTexture1DArray",
                                                  "RWTexture2D",
                                                  "RWTexture2DArray",
                                                  "RWTexture3D",
                                                  "Buffer",
                                                  "RWBuffer",
                                                  "StructuredBuffer",
                                                  "RWStructuredBuffer",
                                                  "ByteAddressBuffer",
                                                  "RWByteAddressBuffer",
                                                  "SamplerState",
                                                  "SamplerComparisonState",
                                                  "sampler",
                                                  "sampler1D",
                                                  "sampler2D",
                                                  "sampler3D",
                                                  "samplerCUBE",
                                                  "sampler2D_half",
                                                  "sampler2D_float",
                                                  "sampler3D_half",
                                                  "sampler3D_float",
                                                  "samplerCUBE_half",
                                                  "samplerCUBE_float"};
    for (std::string_view t : kTypes) {
        if (w == t)
            return true;
    }
    return false;
}

// The token after the ( [ { group that opens at k, or kNone when it does not close in the item.
size_t AfterGroup(const Reader& r, size_t k) {
    int depth = 0;
    for (; k < r.end; ++k) {
        const std::string_view w = r.At(k);
        if (w == "(" || w == "[" || w == "{") {
            ++depth;
        } else if (w == ")" || w == "]" || w == "}") {
            if (--depth == 0)
                return k + 1;
        }
    }
    return kNone;
}

// The token after a template argument list `<...>` opening at k, or kNone.
size_t AfterAngles(const Reader& r, size_t k) {
    int depth = 0;
    for (; k < r.end; ++k) {
        const std::string_view w = r.At(k);
        if (w == "<")
            ++depth;
        else if (w == ">")
            --depth;
        else if (w == ">>")
            depth -= 2;
        else if (w == ";" || w == "{" || w == "(")
            return kNone;
        if (depth <= 0)
            return depth == 0 ? k + 1 : kNone;
    }
    return kNone;
}

// Past every `[...]` group from k on (attributes, array sizes); kNone when one does not close.
size_t AfterBrackets(const Reader& r, size_t k) {
    while (k != kNone && r.At(k) == "[")
        k = AfterGroup(r, k);
    return k;
}

// Past a `: register(...)` starting at k (k itself without one); kNone when it is not that shape.
size_t AfterRegister(const Reader& r, size_t k) {
    if (r.At(k) != ":")
        return k;
    if (!r.Ident(k + 1) || r.At(k + 2) != "(")
        return kNone;
    return AfterGroup(r, k + 2);
}

// The names tokens [b, e) declare at their own nesting level: each identifier followed by one of
// ; , [ : = < (or by e); `<` for a cbuffer member's annotation (`float4 x < string n = "X"; >;`).
// Groups in ( ) and [ ] are skipped, and so are { } groups where `braces` (a static's brace
// initializer); elsewhere a `{` (a nested definition) gives false. A word read as a name that is
// not one (a template type's, a word of an initializer) is only one more name that keeps the
// item.
bool Declarators(const Reader& r,
                 size_t b,
                 size_t e,
                 bool braces,
                 std::vector<std::string_view>& names) {
    for (size_t k = b; k < e;) {
        const std::string_view w = r.At(k);
        if (w == "{" && !braces)
            return false;
        if (w == "(" || w == "[" || w == "{") {
            k = AfterGroup(r, k);
            if (k == kNone || k > e)
                return false;
            continue;
        }
        const std::string_view next = k + 1 < e ? r.At(k + 1) : ";";
        if (r.Ident(k) && (next == ";" || next == "," || next == "[" || next == ":" ||
                           next == "=" || next == "<"))
            names.push_back(w);
        ++k;
    }
    return true;
}

// struct NAME { ... };
bool Struct(const Reader& r, size_t k, std::vector<std::string_view>& names) {
    if (r.At(k) != "struct" || !r.Ident(k + 1) || r.At(k + 2) != "{")
        return false;
    const size_t close = AfterGroup(r, k + 2);
    if (close == kNone || close + 1 != r.end || r.At(close) != ";")
        return false;
    names.push_back(r.At(k + 1));
    return true;
}

// [attributes] cbuffer NAME [: register(...)] { members } [;]
bool Cbuffer(const Reader& r, size_t k, std::vector<std::string_view>& names) {
    k = AfterBrackets(r, k);
    if (k == kNone || (r.At(k) != "cbuffer" && r.At(k) != "tbuffer") || !r.Ident(k + 1))
        return false;
    const std::string_view name = r.At(k + 1);
    k = AfterRegister(r, k + 2);
    if (k == kNone || r.At(k) != "{")
        return false;
    const size_t close = AfterGroup(r, k);
    if (close == kNone || !(close == r.end || (close + 1 == r.end && r.At(close) == ";")))
        return false;
    const size_t before = names.size();
    names.push_back(name);
    if (!Declarators(r, k + 1, close - 1, false, names)) {
        names.resize(before);
        return false;
    }
    return true;
}

// [uniform] TYPE[<...>] NAME [[N]...] [: register(...)];
bool Resource(const Reader& r, size_t k, std::vector<std::string_view>& names) {
    if (r.At(k) == "uniform")
        ++k;
    if (!IsResourceType(r.At(k)))
        return false;
    ++k;
    if (r.At(k) == "<") {
        k = AfterAngles(r, k);
        if (k == kNone)
            return false;
    }
    if (!r.Ident(k))
        return false;
    const std::string_view name = r.At(k++);
    k = AfterBrackets(r, k);
    if (k != kNone)
        k = AfterRegister(r, k);
    if (k == kNone || r.At(k) != ";" || k + 1 != r.end)
        return false;
    names.push_back(name);
    return true;
}

// static [const] TYPE NAME [= initializer][, ...]; with no definition in it before an `=`.
bool Static(const Reader& r, size_t k, std::vector<std::string_view>& names) {
    if (r.At(k) != "static" || r.At(r.end - 1) != ";")
        return false;
    for (size_t i = k + 1; i < r.end && r.At(i) != "="; ++i) {
        const std::string_view w = r.At(i);
        if (w == "{" || w == "(" || w == "struct")
            return false;  // a definition or a function's declaration
    }
    const size_t before = names.size();
    if (!Declarators(r, k + 1, r.end, true, names)) {
        names.resize(before);
        return false;
    }
    return names.size() > before;
}

}  // namespace

bool DroppableDeclaration(std::string_view text,
                          const std::vector<Token>& tok,
                          size_t first,
                          size_t end,
                          std::vector<std::string_view>& names) {
    if (first >= end || end > tok.size())
        return false;
    const Reader r{text, tok, end};
    return Struct(r, first, names) || Cbuffer(r, first, names) || Resource(r, first, names) ||
           Static(r, first, names);
}

}  // namespace kiln::hlsl
