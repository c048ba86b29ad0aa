#include "kiln/source.h"

#include <algorithm>
#include <memory>

#include "kiln/base/files.h"

namespace kiln {

SourceFile::SourceFile(std::string path, std::string text)
    : path_(std::move(path)), text_(std::move(text)) {
    line_starts_.push_back(0);
    for (size_t i = 0; i < text_.size(); ++i) {
        if (text_[i] == '\n') {
            line_starts_.push_back(static_cast<uint32_t>(i + 1));
        }
    }
}

SourceLoc SourceFile::LocAt(uint32_t offset) const {
    offset = std::min<uint32_t>(offset, static_cast<uint32_t>(text_.size()));
    auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
    const size_t line_index = static_cast<size_t>(it - line_starts_.begin()) - 1;
    return SourceLoc{offset, static_cast<uint32_t>(line_index + 1),
                     offset - line_starts_[line_index] + 1};
}

std::string_view SourceFile::Line(uint32_t line) const {
    if (line == 0 || line > line_starts_.size()) {
        return {};
    }
    const size_t begin = line_starts_[line - 1];
    size_t end = line < line_starts_.size() ? line_starts_[line] - 1 : text_.size();
    if (end > begin && text_[end - 1] == '\r') {
        --end;
    }
    return std::string_view(text_).substr(begin, end - begin);
}

Result<SourceFile> ReadSourceFile(const std::string& path, uint64_t max_bytes) {
    Result<std::string> text =
        base::ReadRegularFile(path, std::min(max_bytes, kMaxSourceFileBytes));
    if (!text)
        return text.error();
    return SourceFile(path, std::move(text).value());
}

}  // namespace kiln
