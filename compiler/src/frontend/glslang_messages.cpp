#include "frontend/glslang_messages.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <regex>
#include <sstream>

#include "hlsl/identifier.h"
#include "hlsl/unity_versions.h"
#include "kiln/pack/names.h"

namespace kiln::frontend {
namespace {

bool IsIdentChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

bool IsIdentifier(const std::string& s) {
    return !s.empty() && !std::isdigit(static_cast<unsigned char>(s[0])) &&
           std::all_of(s.begin(), s.end(), IsIdentChar);
}

// Finds "<digits>: " after a ':' and splits "file:line: rest".
bool SplitLocation(const std::string& s, std::string& file, uint32_t& line, std::string& rest) {
    for (size_t colon = s.find(':'); colon != std::string::npos; colon = s.find(':', colon + 1)) {
        size_t i = colon + 1;
        uint64_t n = 0;
        while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])) && n < 1u << 30) {
            n = n * 10 + uint64_t(s[i] - '0');
            ++i;
        }
        if (i > colon + 1 && i < s.size() && s[i] == ':') {
            file = s.substr(0, colon);
            line = static_cast<uint32_t>(n);
            rest = s.substr(std::min(s.size(), i + 2));
            return true;
        }
    }
    return false;
}

std::string Trim(std::string s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back())))
        s.pop_back();
    size_t b = 0;
    while (b < s.size() && std::isspace(static_cast<unsigned char>(s[b])))
        ++b;
    return s.substr(b);
}

uint32_t FindToken(std::string_view line, const std::string& token) {
    if (token.empty())
        return 0;
    // A token that starts (ends) with a word character starts (ends) a word: `_Tint.rg` is not
    // the start of `_Tint.rgb`.
    const bool word_start = IsIdentChar(token.front()), word_end = IsIdentChar(token.back());
    for (size_t at = line.find(token); at != std::string_view::npos;
         at = line.find(token, at + 1)) {
        const bool left_ok = !word_start || at == 0 || !IsIdentChar(line[at - 1]);
        const size_t end = at + token.size();
        const bool right_ok = !word_end || end >= line.size() || !IsIdentChar(line[end]);
        if (left_ok && right_ok)
            return static_cast<uint32_t>(at + 1);
    }
    return 0;
}

// glslang names types as "temp 3-component vector of float"; the user wrote float3. Scalars and
// vectors are respelled in HLSL, storage qualifiers dropped; matrices keep glslang's spelling.
std::string HlslTypeSpellings(const std::string& text) {
    static const std::regex kQualifiers(
        "'((?:temp|const|uniform|in|out|inout|global|smooth|flat) )+");
    static const std::regex kVector("'([1-4])-component vector of (float|int|uint|bool|double)'");
    std::string t = std::regex_replace(text, kQualifiers, "'");
    return std::regex_replace(t, kVector, "'$2$1'");
}

// For a write to a uniform, glslang points past the statement: the column of the last
// assignment target ("name", "name.xyz", "name[i]" before "=", "+=", ...) before that point.
uint32_t AssignedGlobal(const GlslangMessage& m, std::string_view line, uint32_t& width) {
    if (m.text.find("can't modify a uniform") == std::string::npos) {
        return 0;
    }
    static const std::regex kTarget(
        R"(([A-Za-z_][A-Za-z0-9_]*)(\s*(\.[A-Za-z_][A-Za-z0-9_]*|\[[^\]]*\]))*\s*([-+*/%&|^]?=)(?!=))");
    const std::string text(
        line.substr(0, m.column > 0 ? std::min<size_t>(m.column, line.size()) : line.size()));
    uint32_t col = 0;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), kTarget);
         it != std::sregex_iterator(); ++it) {
        col = static_cast<uint32_t>(it->position(1) + 1);
        width = static_cast<uint32_t>(it->length(1));
    }
    return col;
}

// HLSL's intrinsic functions (Microsoft's "Intrinsic Functions" list, the ones glslang's HLSL front
// end knows), plus the legacy sampler functions Unity's shaders call.
const char* const kHlslIntrinsics[] = {"abort",
                                       "abs",
                                       "acos",
                                       "all",
                                       "AllMemoryBarrier",
                                       "AllMemoryBarrierWithGroupSync",
                                       "any",
                                       "asdouble",
                                       "asfloat",
                                       "asin",
                                       "asint",
                                       "asuint",
                                       "atan",
                                       "atan2",
                                       "ceil",
                                       "clamp",
                                       "clip",
                                       "cos",
                                       "cosh",
                                       "countbits",
                                       "cross",
                                       "ddx",
                                       "ddx_coarse",
                                       "ddx_fine",
                                       "ddy",
                                       "ddy_coarse",
                                       "ddy_fine",
                                       "degrees",
                                       "determinant",
                                       "DeviceMemoryBarrier",
                                       "DeviceMemoryBarrierWithGroupSync",
                                       "distance",
                                       "dot",
                                       "dst",
                                       "EvaluateAttributeAtCentroid",
                                       "EvaluateAttributeAtSample",
                                       "EvaluateAttributeSnapped",
                                       "exp",
                                       "exp2",
                                       "f16tof32",
                                       "f32tof16",
                                       "faceforward",
                                       "firstbithigh",
                                       "firstbitlow",
                                       "floor",
                                       "fma",
                                       "fmod",
                                       "frac",
                                       "frexp",
                                       "fwidth",
                                       "GetRenderTargetSampleCount",
                                       "GetRenderTargetSamplePosition",
                                       "GroupMemoryBarrier",
                                       "GroupMemoryBarrierWithGroupSync",
                                       "InterlockedAdd",
                                       "InterlockedAnd",
                                       "InterlockedCompareExchange",
                                       "InterlockedCompareStore",
                                       "InterlockedExchange",
                                       "InterlockedMax",
                                       "InterlockedMin",
                                       "InterlockedOr",
                                       "InterlockedXor",
                                       "isfinite",
                                       "isinf",
                                       "isnan",
                                       "ldexp",
                                       "length",
                                       "lerp",
                                       "lit",
                                       "log",
                                       "log10",
                                       "log2",
                                       "mad",
                                       "max",
                                       "min",
                                       "modf",
                                       "msad4",
                                       "mul",
                                       "noise",
                                       "normalize",
                                       "pow",
                                       "radians",
                                       "rcp",
                                       "reflect",
                                       "refract",
                                       "reversebits",
                                       "round",
                                       "rsqrt",
                                       "saturate",
                                       "sign",
                                       "sin",
                                       "sincos",
                                       "sinh",
                                       "smoothstep",
                                       "sqrt",
                                       "step",
                                       "tan",
                                       "tanh",
                                       "tex1D",
                                       "tex1Dbias",
                                       "tex1Dgrad",
                                       "tex1Dlod",
                                       "tex1Dproj",
                                       "tex2D",
                                       "tex2Dbias",
                                       "tex2Dgrad",
                                       "tex2Dlod",
                                       "tex2Dproj",
                                       "tex3D",
                                       "tex3Dbias",
                                       "tex3Dgrad",
                                       "tex3Dlod",
                                       "tex3Dproj",
                                       "texCUBE",
                                       "texCUBEbias",
                                       "texCUBEgrad",
                                       "texCUBElod",
                                       "texCUBEproj",
                                       "transpose",
                                       "trunc"};

bool IsHlslIntrinsic(const std::string& name) {
    return std::find(std::begin(kHlslIntrinsics), std::end(kHlslIntrinsics), name) !=
           std::end(kHlslIntrinsics);
}

// Where glslang's HLSL front end rejects what Unity's compiler (FXC) accepts, and a source
// rewrite would not be safe, the diagnostic says what Unity does and how to write it portably.
void ExplainUnityDifference(const GlslangMessage& m, Diagnostic& d) {
    if (m.text.find("can't modify a uniform") != std::string::npos) {
        d.message =
            "cannot write to a shader global: globals are uniforms, and uniforms are "
            "read-only";
        d.notes.push_back({d.file, d.range,
                           "Unity's compiler accepts this write and keeps the value private to "
                           "the invocation; copy the global into a local variable, or declare it "
                           "'static' if neither materials nor the engine set it"});
    } else if (m.text.find("no matching overloaded function found") != std::string::npos) {
        d.notes.push_back({d.file, d.range,
                           "if an argument is a vector where the parameter is a scalar or a "
                           "shorter vector: Unity's compiler truncates it (warning X3206), "
                           "glslang does not; pass the components, as in 'f(v.x)'"});
    }
}

}  // namespace

std::vector<GlslangMessage> ParseInfoLog(const std::string& log) {
    std::vector<GlslangMessage> out;
    std::istringstream in(log);
    std::string raw;
    while (std::getline(in, raw)) {
        const std::string line = Trim(raw);
        if (line.empty())
            continue;
        // "file(12): error at column 7, HLSL parsing failed."
        const size_t at_col = line.find("): error at column ");
        if (at_col != std::string::npos) {
            const size_t open = line.rfind('(', at_col);
            const uint32_t col =
                static_cast<uint32_t>(std::strtoul(line.c_str() + at_col + 19, nullptr, 10));
            if (open != std::string::npos) {
                const std::string file = line.substr(0, open);
                const uint32_t ln =
                    static_cast<uint32_t>(std::strtoul(line.c_str() + open + 1, nullptr, 10));
                bool attached = false;
                for (auto it = out.rbegin(); it != out.rend(); ++it) {
                    if (it->file == file && it->line == ln && it->column == 0) {
                        it->column = col;
                        attached = true;
                        break;
                    }
                }
                if (!attached) {
                    // The only message of some parse failures (a stray top-level '}'): it is
                    // the error itself.
                    GlslangMessage m;
                    m.file = file;
                    m.line = ln;
                    m.column = col;
                    m.text = "syntax error";
                    out.push_back(std::move(m));
                }
            }
            continue;
        }
        GlslangMessage m;
        std::string body;
        if (line.rfind("ERROR: ", 0) == 0) {
            body = line.substr(7);
        } else if (line.rfind("WARNING: ", 0) == 0) {
            m.severity = Severity::kWarning;
            body = line.substr(9);
        } else {
            continue;  // informational lines
        }
        if (body.find("compilation errors.") != std::string::npos &&
            body.find("No code generated") != std::string::npos) {
            continue;
        }
        std::string rest;
        if (!SplitLocation(body, m.file, m.line, rest)) {
            m.text = body;  // "Linking fragment stage: ..."
            out.push_back(std::move(m));
            continue;
        }
        // "'token' : message"
        if (rest.size() > 1 && rest[0] == '\'') {
            const size_t close = rest.find("' :");
            if (close != std::string::npos) {
                m.token = rest.substr(1, close - 1);
                rest = rest.substr(close + 3);
            }
        }
        m.text = Trim(rest);
        out.push_back(std::move(m));
    }
    // After the first error glslang's recovery produces cascades: "'declaration' : Expected",
    // "'' : Could not perform requested binary operation", and preprocessor errors ("'#' :
    // preprocessor directive cannot be preceded by another token", "missing #endif") caused by
    // the abandoned parse. Only errors with a real token survive after the first one.
    std::vector<GlslangMessage> kept;
    bool seen_error = false;
    for (const GlslangMessage& m : out) {
        const bool cascade_token = m.token.empty() || m.token == "declaration" || m.token == "#";
        if (m.severity == Severity::kError && seen_error && cascade_token && !m.file.empty()) {
            continue;
        }
        if (m.severity == Severity::kError)
            seen_error = true;
        kept.push_back(m);
    }
    return kept;
}

std::string RewordMessage(const std::string& token, const std::string& text) {
    std::string t;
    // Collapse whitespace and glslang's "' const float'" quoting.
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (std::isspace(static_cast<unsigned char>(c))) {
            if (!t.empty() && t.back() != ' ')
                t += ' ';
            continue;
        }
        t += c;
        if (c == '\'' && (i == 0 || text[i - 1] == ' ')) {
            while (i + 1 < text.size() && text[i + 1] == ' ')
                ++i;
        }
    }
    t = HlslTypeSpellings(Trim(t));
    while (!t.empty() && t.back() == '.')
        t.pop_back();
    if (t == "Expected" || t.empty()) {
        return token.empty() ? "syntax error" : "expected '" + token + "'";
    }
    if (t.size() > 1 && std::isupper(static_cast<unsigned char>(t[0])) &&
        !std::isupper(static_cast<unsigned char>(t[1]))) {
        t[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(t[0])));
    }
    if (IsIdentifier(token) && t.find("'" + token + "'") == std::string::npos &&
        token != "declaration") {
        t += " '" + token + "'";
    }
    return t;
}

namespace {

// glslang reports a missing ';' at the token after it; when that token starts a line, the ';' is
// missing at the end of the previous token (clang's position). Returns the offset just after
// that token, or npos.
size_t MissingSemicolonAt(std::string_view text, size_t at) {
    while (at > 0 && hlsl::IdentChar(text[at - 1]))
        --at;  // to the start of the token glslang stopped at
    size_t prev = at;
    bool newline = false;
    while (prev > 0 && std::isspace(static_cast<unsigned char>(text[prev - 1]))) {
        newline |= text[prev - 1] == '\n';
        --prev;
    }
    return newline && prev > 0 ? prev : std::string_view::npos;
}

void Improve(const GlslangMessage& m,
             const SourceFile* file,
             const MessageContext& context,
             Diagnostic& d) {
    if (d.message == "expected ';'" && file != nullptr) {
        const size_t at = MissingSemicolonAt(file->text(), d.range.begin.offset + 1);
        if (at != std::string_view::npos) {
            d.range.begin = file->LocAt(static_cast<uint32_t>(at));
            d.range.end = file->LocAt(static_cast<uint32_t>(at));
            d.range.end.column += 1;
            d.message = "expected ';' at the end of this line";
        }
        return;
    }
    const std::string include_error = "could not process include directive for header name:";
    if (d.message.rfind(include_error, 0) == 0) {
        const std::string name = Trim(d.message.substr(include_error.size()));
        d.message = "cannot find include file '" + name + "'";
        if (file != nullptr) {
            const std::string_view line = file->Line(d.range.begin.line);
            const size_t found = line.find(name);
            if (found != std::string_view::npos) {
                const uint32_t start = static_cast<uint32_t>(line.data() - file->text().data());
                d.range.begin = file->LocAt(start + static_cast<uint32_t>(found));
                d.range.end = file->LocAt(start + static_cast<uint32_t>(found + name.size()));
            }
        }
        if (name.rfind("Assets/", 0) == 0 || name.rfind("Packages/", 0) == 0) {
            d.notes.push_back({d.file, kNoPosition,
                               "Unity resolves \"" + name.substr(0, name.find('/')) +
                                   "/...\" from the project's root folder: Kiln finds it above "
                                   "the Assets folder the including file is in; otherwise pass "
                                   "--project-root DIR"});
        }
        if (context.unity_version != 0) {
            if (std::optional<std::string> note =
                    hlsl::MissingIncludeNote(name, context.unity_version)) {
                d.notes.push_back({d.file, kNoPosition, *note});
            }
        }
        if (!context.include_search.empty()) {
            std::string dirs;
            for (const std::string& dir : context.include_search)
                dirs += (dirs.empty() ? "" : ", ") + dir;
            d.notes.push_back({d.file, kNoPosition, "searched, in order: " + dirs});
        }
        return;
    }
    // A call of a name that is neither a function of the program nor an HLSL intrinsic: an
    // unknown function, whose suggestion is the closest function (never a variable), and no
    // overload note.
    if (d.message.find("no matching overloaded function") != std::string::npos &&
        IsIdentifier(m.token) && context.functions) {
        std::vector<std::string> names = context.functions();
        const bool declared = std::find(names.begin(), names.end(), m.token) != names.end();
        if (!declared && !IsHlslIntrinsic(m.token)) {
            d.message = "unknown function '" + m.token + "'";
            d.notes.clear();
            names.insert(names.end(), std::begin(kHlslIntrinsics), std::end(kHlslIntrinsics));
            d.message += pack::DidYouMean(m.token, names);
        }
        return;
    }
    const bool unknown_name = d.message.find("unknown variable") != std::string::npos ||
                              d.message.find("undeclared identifier") != std::string::npos;
    if (unknown_name && IsIdentifier(m.token) && context.identifiers) {
        std::vector<std::string> names = context.identifiers();
        names.erase(std::remove(names.begin(), names.end(), m.token), names.end());
        d.message += pack::DidYouMean(m.token, names);
    }
}

}  // namespace

Diagnostic ToDiagnostic(const GlslangMessage& m,
                        const SourceLookup& lookup,
                        const MessageContext& context) {
    Diagnostic d;
    d.severity = m.severity;
    d.code = m.severity == Severity::kWarning ? DiagCode::kHlslWarning : DiagCode::kHlslError;
    d.file = m.file;
    d.message = RewordMessage(m.token, m.text);
    if (m.file.empty())
        return d;
    std::shared_ptr<const SourceFile> file = lookup ? lookup(m.file) : nullptr;
    const uint32_t line = std::max<uint32_t>(m.line, 1);
    if (file && line > file->line_count())
        file = nullptr;
    uint32_t col = 0, width = 1;
    if (file) {
        const std::string_view text = file->Line(line);
        if (const uint32_t target = AssignedGlobal(m, text, width); target > 0) {
            col = target;
        } else if (m.column > 0 && (m.text == "Expected" || m.token.empty())) {
            col = std::min<uint32_t>(m.column, static_cast<uint32_t>(text.size()) + 1);
        } else if (const uint32_t found = FindToken(text, m.token); found > 0) {
            col = found;
            width = static_cast<uint32_t>(m.token.size());
        } else if (m.column > 0) {
            col = std::min<uint32_t>(m.column, static_cast<uint32_t>(text.size()) + 1);
        } else {
            const size_t first = text.find_first_not_of(" \t");
            col = first == std::string_view::npos ? 1 : static_cast<uint32_t>(first + 1);
            width =
                static_cast<uint32_t>(text.size() - (first == std::string_view::npos ? 0 : first));
        }
        const uint32_t line_start = static_cast<uint32_t>(text.data() - file->text().data());
        d.range.begin = file->LocAt(line_start + col - 1);
        d.range.end = file->LocAt(line_start + col - 1 + std::max<uint32_t>(width, 1));
    } else {
        d.range.begin = SourceLoc{0, line, std::max<uint32_t>(m.column, 1)};
        d.range.end = d.range.begin;
        d.range.end.column += 1;
    }
    ExplainUnityDifference(m, d);
    Improve(m, file.get(), context, d);
    return d;
}

}  // namespace kiln::frontend
