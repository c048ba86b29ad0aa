#include "hlsl/blank_inclusions.h"

#include <charconv>

#include "hlsl/splice.h"

namespace kiln::hlsl {
namespace {

// A marked name, as the prologue's #line prints it: `"qKsPb<index>|<path>"`.
constexpr char kBlankTag = 'b';

}  // namespace

bool ServableAsBlank(std::string_view text, std::string_view path) {
    return text.size() >= kMinBlankInclusion && text.find_first_not_of('\n') == text.npos &&
           path.find_first_of("\"\n\\") == path.npos;
}

std::string MarkedName(char tag, size_t inclusion, std::string_view path) {
    std::string name(kSpliceMarker);
    name += tag;
    name += std::to_string(inclusion);
    name += kMarkedPathStart;
    name += path;
    return name;
}

std::string_view UnmarkedName(std::string_view name) {
    if (name.substr(0, kSpliceMarker.size()) != kSpliceMarker)
        return name;
    const size_t bar = name.find(kMarkedPathStart);
    return bar == std::string_view::npos ? name : name.substr(bar + 1);
}

bool InLineDirective(const std::string& text, size_t at) {
    const size_t start = text.rfind('\n', at) + 1;  // npos + 1 = 0
    constexpr std::string_view kLine = "#line ";
    if (at < start + kLine.size() + 2 || text.compare(start, kLine.size(), kLine) != 0 ||
        text[at - 1] != ' ')
        return false;
    for (size_t i = start + kLine.size(); i + 1 < at; ++i) {
        if (text[i] < '0' || text[i] > '9')
            return false;
    }
    return true;
}

std::string BlankInclusionName(size_t inclusion, std::string_view path) {
    return MarkedName(kBlankTag, inclusion, path);
}

bool RestoreBlankInclusions(std::string& text, const std::vector<uint32_t>& newlines) {
    const std::string marker = "\"" + std::string(kSpliceMarker) + kBlankTag;
    size_t next = 0;  // the next inclusion served blank is at or after `next`
    const auto skip_served_whole = [&] {
        while (next < newlines.size() && newlines[next] == 0)
            ++next;
    };
    size_t added = 0;  // the line breaks given back
    for (const uint32_t n : newlines)
        added += n;
    std::string out;
    size_t copied = 0;
    for (size_t p = text.find(marker); p != std::string::npos; p = text.find(marker, p + 1)) {
        skip_served_whole();
        size_t index = 0;
        const char* digits = text.data() + p + marker.size();
        const auto r = std::from_chars(digits, text.data() + text.size(), index);
        if (r.ec != std::errc() || r.ptr == digits || index != next || !InLineDirective(text, p))
            return false;
        const size_t path = r.ptr - text.data();
        if (path >= text.size() || text[path] != kMarkedPathStart)
            return false;
        const size_t end = text.find('"', path + 1);
        constexpr std::string_view kAfter = "\"\n\n#line ";
        if (end == std::string::npos || text.compare(end, kAfter.size(), kAfter) != 0)
            return false;
        if (out.empty())
            out.reserve(text.size() + added);
        out.append(text, copied, p + 1 - copied);
        out.append(text, path + 1, end - path - 1);
        out += "\"\n";
        out.append(newlines[next], '\n');
        copied = end + 3;
        p = copied - 1;
        ++next;
    }
    skip_served_whole();
    if (next != newlines.size())
        return false;  // one served blank was not found
    if (copied == 0)
        return true;
    out.append(text, copied);
    text = std::move(out);
    return true;
}

}  // namespace kiln::hlsl
