// Source text and positions. Every AST node and diagnostic carries a SourceRange into a
// SourceFile; lines and columns are 1-based, columns count bytes.
#ifndef KILN_SOURCE_H_
#define KILN_SOURCE_H_

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "kiln/result.h"

namespace kiln {

struct SourceLoc {
    uint32_t offset = 0;  // byte offset into the file
    uint32_t line = 1;
    uint32_t column = 1;

    friend bool operator==(const SourceLoc&, const SourceLoc&) = default;
};

// Half-open byte range [begin, end).
struct SourceRange {
    SourceLoc begin;
    SourceLoc end;

    friend bool operator==(const SourceRange&, const SourceRange&) = default;
};

// For diagnostics about a whole file or the command line: line 0, printed without a position.
inline constexpr SourceRange kNoPosition{{0, 0, 0}, {0, 0, 0}};

// An immutable source file with a line index built on construction.
class SourceFile {
  public:
    SourceFile(std::string path, std::string text);

    const std::string& path() const { return path_; }
    const std::string& text() const { return text_; }

    // Location of a byte offset (clamped to the end of the file).
    SourceLoc LocAt(uint32_t offset) const;
    // The text of 1-based line `line` without its line terminator; empty when out of range.
    std::string_view Line(uint32_t line) const;
    uint32_t line_count() const { return static_cast<uint32_t>(line_starts_.size()); }

  private:
    std::string path_;
    std::string text_;
    std::vector<uint32_t> line_starts_;
};

// Largest file Kiln reads; sizes past this are rejected before reading (the offsets are 32-bit).
inline constexpr uint64_t kMaxSourceFileBytes = 256u * 1024u * 1024u;

// Reads a file from disk (base::ReadRegularFile: regular files of at most `max_bytes`). Errors are
// plain messages (the caller turns them into diagnostics).
Result<SourceFile> ReadSourceFile(const std::string& path,
                                  uint64_t max_bytes = kMaxSourceFileBytes);

}  // namespace kiln

#endif  // KILN_SOURCE_H_
