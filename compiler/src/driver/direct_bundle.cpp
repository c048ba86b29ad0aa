#include "driver/direct_bundle.h"

#include <charconv>
#include <iterator>

namespace kiln::driver {
namespace {

constexpr std::string_view kHeader = "kiln-direct 2";

std::vector<std::string_view> Split(std::string_view s, char sep) {
    std::vector<std::string_view> out;
    size_t at = 0;
    for (size_t next; (next = s.find(sep, at)) != std::string_view::npos; at = next + 1)
        out.push_back(s.substr(at, next - at));
    out.push_back(s.substr(at));
    return out;
}

bool IsKey(std::string_view s) {
    return s.size() == 32 && s.find_first_not_of("0123456789abcdef") == std::string_view::npos;
}

std::optional<uint32_t> Number(std::string_view s, size_t below) {
    uint32_t n = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), n);
    if (s.empty() || ec != std::errc() || end != s.data() + s.size() || n >= below ||
        (s.size() > 1 && s[0] == '0'))
        return std::nullopt;  // not a number below `below`, or not written as one (leading 0)
    return n;
}

// "3,7,9" (each below `below`), or "" for none.
std::optional<std::vector<uint32_t>> Numbers(std::string_view s, size_t below) {
    std::vector<uint32_t> out;
    if (s.empty())
        return out;
    for (std::string_view part : Split(s, ',')) {
        const std::optional<uint32_t> n = Number(part, below);
        if (!n)
            return std::nullopt;
        out.push_back(*n);
    }
    return out;
}

void AppendNumbers(std::string& out, const std::vector<uint32_t>& numbers) {
    for (size_t i = 0; i < numbers.size(); ++i) {
        if (i)
            out += ',';
        out += std::to_string(numbers[i]);
    }
}

// One line after its kind: false when it is not well formed.
bool ParseLine(DirectBundle& b, std::string_view kind, const std::vector<std::string_view>& f) {
    if (kind == "file" && f.size() == 3 && IsKey(f[1]) && !f[2].empty()) {
        b.files.push_back(std::string(f[1]) + "\t" + std::string(f[2]));
    } else if (kind == "include" && f.size() == 5 && (f[1] == "0" || f[1] == "1") &&
               !f[2].empty() && !f[3].empty()) {
        b.includes.push_back(std::string(f[1]) + "\t" + std::string(f[2]) + "\t" +
                             std::string(f[3]) + "\t" + std::string(f[4]));
    } else if (kind == "set" && f.size() == 3) {
        auto files = Numbers(f[1], b.files.size());
        auto includes = Numbers(f[2], b.includes.size());
        if (!files || !includes)
            return false;
        b.sets.push_back({std::move(*files), std::move(*includes)});
    } else if (kind == "entry" && f.size() == 4 && IsKey(f[1]) && IsKey(f[2])) {
        const std::optional<uint32_t> set = Number(f[3], b.sets.size());
        if (!set)
            return false;
        b.entries.push_back({std::string(f[1]), std::string(f[2]), *set});
    } else {
        return false;
    }
    return true;
}

}  // namespace

std::vector<std::string_view> SplitDirectFields(std::string_view line) {
    return Split(line, '\t');
}

bool DirectStorable(std::string_view field) {
    return field.find_first_of("\t\n\r") == std::string_view::npos;
}

std::optional<DirectBundle> ParseDirectBundle(std::string_view text) {
    DirectBundle b;
    const std::vector<std::string_view> lines = Split(text, '\n');
    if (lines.size() < 2 || lines[0] != kHeader || !lines.back().empty())
        return std::nullopt;  // no header, or cut short
    static constexpr std::string_view kKinds[] = {"file", "include", "set", "entry"};
    size_t kind = 0;  // lines come in the order of kKinds
    for (size_t i = 1; i + 1 < lines.size(); ++i) {
        const std::vector<std::string_view> f = SplitDirectFields(lines[i]);
        while (kind < std::size(kKinds) && f[0] != kKinds[kind])
            ++kind;
        if (kind == std::size(kKinds) || !ParseLine(b, f[0], f))
            return std::nullopt;
    }
    return b;
}

std::string SerializeDirectBundle(const DirectBundle& b) {
    std::string out(kHeader);
    out += '\n';
    for (const std::string& f : b.files)
        out.append("file\t").append(f).append(1, '\n');
    for (const std::string& i : b.includes)
        out.append("include\t").append(i).append(1, '\n');
    for (const DirectBundle::Set& s : b.sets) {
        out += "set\t";
        AppendNumbers(out, s.files);
        out += '\t';
        AppendNumbers(out, s.includes);
        out += '\n';
    }
    for (const DirectBundle::Entry& e : b.entries) {
        out.append("entry\t").append(e.direct).append(1, '\t').append(e.result);
        out.append(1, '\t').append(std::to_string(e.set)).append(1, '\n');
    }
    return out;
}

}  // namespace kiln::driver
