#include "hlsl/output_memo.h"

#include <algorithm>
#include <charconv>

#include "hlsl/blank_inclusions.h"
#include "hlsl/identifier.h"
#include "hlsl/lean_text.h"
#include "hlsl/plan_memo.h"
#include "hlsl/pp_macros.h"
#include "hlsl/pp_skeleton.h"
#include "hlsl/splice.h"

namespace kiln::hlsl {
namespace {

// Whether the lines of a walk's file that glslang reads: those outside its blanked ranges.
class ReadLines {
  public:
    explicit ReadLines(const LineRanges& blank) : blank_(blank) {}
    // Lines must be asked in ascending order.
    bool Read(uint32_t line) {
        while (at_ < blank_.size() && blank_[at_].second < line)
            ++at_;
        return at_ == blank_.size() || line < blank_[at_].first;
    }

  private:
    const LineRanges& blank_;
    size_t at_ = 0;
};

struct Flattening {
    std::vector<const Pending*> by_index;  // the walk's files, by inclusion index
    size_t next = 1;                       // the next inclusion, in the order glslang reads
    WalkWords& out;
};

std::string_view LineOf(const LeanText& lean, uint32_t line) {
    const size_t begin = lean.line_starts[line];
    const size_t end =
        line + 1 < lean.line_starts.size() ? lean.line_starts[line + 1] : lean.text.size();
    return std::string_view(lean.text).substr(begin, end - begin);
}

// Adds the words of inclusion `index`'s read lines and its directives (with its nested
// inclusions', in the order glslang reads them) to `f.out`. False where the walk's output is not
// remembered.
bool Flatten(Flattening& f, size_t index) {
    const Pending& p = *f.by_index[index];
    const LeanText& lean = *p.lean;
    ReadLines words(p.blank);
    for (uint32_t line = 0; line < lean.line_starts.size(); ++line) {
        if (words.Read(line))
            ForEachWord(LineOf(lean, line), [&](std::string_view w) {
                f.out.words.Insert(w);
                f.out.names_file = f.out.names_file || w == "__FILE__";
            });
    }
    ReadLines directives(p.blank);
    for (const PpDirective& d : p.skeleton->directives) {
        if (!directives.Read(d.first_line))
            continue;
        switch (d.kind) {
            case PpKind::kIf:
            case PpKind::kIfdef:
            case PpKind::kIfndef:
            case PpKind::kElif:
            case PpKind::kElse:
            case PpKind::kEndif:
                break;  // decided: its branches are blanked or read
            case PpKind::kDefine:
            case PpKind::kUndef:
            case PpKind::kPragma:
                for (uint32_t line = d.first_line; line <= d.last_line; ++line)
                    f.out.directives += LineOf(lean, line);
                if (f.out.directives.empty() || f.out.directives.back() != '\n')
                    f.out.directives += '\n';
                break;
            case PpKind::kInclude:
                if (f.next >= f.by_index.size())
                    return false;
                f.out.nested.push_back(f.by_index[f.next]->file);
                if (!Flatten(f, f.next++))
                    return false;
                break;
            default:
                return false;  // #line, #error and the like
        }
    }
    return true;
}

std::shared_ptr<const WalkWords> MakeWalkWords(const IncludeWalk& walk) {
    auto words = std::make_shared<WalkWords>();
    if (walk.maybe_branches != 0 || walk.stopped || walk.names_unknown || walk.paths.empty() ||
        walk.pending.size() != walk.paths.size())
        return words;
    Flattening f{std::vector<const Pending*>(walk.paths.size(), nullptr), 1, *words};
    for (const Pending& p : walk.pending) {
        if (p.index >= f.by_index.size() || f.by_index[p.index] || !p.lean || !p.skeleton ||
            !p.skeleton->safe || p.lean->line_starts.size() != p.skeleton->line_starts.size())
            return words;
        f.by_index[p.index] = &p;
    }
    if (!Flatten(f, 0) || f.next != f.by_index.size() || words->names_file)
        return words;
    if (words->directives.empty())
        words->directives.assign(1, '\n');  // glslang reads the last character of what it is given
    words->usable = true;
    return words;
}

// The lines of `text`, each without its line break.
template <typename F>
void ForEachLine(std::string_view text, F f) {
    for (size_t at = 0; at < text.size();) {
        const size_t end = std::min(text.find('\n', at), text.size());
        if (!f(text.substr(at, end - at)))
            return;
        at = end + 1;
    }
}

bool IsPrinted(std::string_view line) {  // a directive glslang's callbacks print
    return line.substr(0, 6) == "#line " || line.substr(0, 8) == "#pragma ";
}

// Whether glslang's output `text` for a walk, after its prologue, spaces its tokens whatever
// token came before the walk: its first token follows an empty line, not a #line (nor a
// #pragma); and how its last token spaces the next (KeptOutput::last).
bool Spacing(std::string_view text, char& last) {
    bool follows_directive = true;  // the prologue
    bool independent = true;
    ForEachLine(text, [&](std::string_view line) {
        if (line.substr(0, 6) == "#line ") {
            follows_directive = true;
            return true;
        }
        if (line.empty()) {
            follows_directive = false;
            return true;
        }
        independent = !follows_directive && line[0] != '#';
        return false;
    });
    if (!independent)
        return false;
    last = 0;
    // The lines from the last: [start, end), end at a line break or the text's end.
    for (size_t end = text.size(); end > 0;) {
        const size_t before = text.rfind('\n', end - 1);
        const size_t start = before == std::string_view::npos ? 0 : before + 1;
        const std::string_view line = text.substr(start, end - start);
        const size_t c = line.find_last_not_of(" \t\r");
        if (c != std::string_view::npos && !IsPrinted(line)) {
            last = std::string_view(";()[]").find(line[c]) != std::string_view::npos ? ';' : '0';
            break;
        }
        if (before == std::string_view::npos)
            break;
        end = before;  // the line break before this line ends the one before it
    }
    return true;
}

// The start of the first line at or after `from` (a line's start, or just after one) that is a
// #line, or npos.
size_t NextLineDirective(const std::string& text, size_t from) {
    if (from < text.size() && (from == 0 || text[from - 1] == '\n') &&
        text.compare(from, 6, "#line ") == 0)
        return from;
    const size_t at = text.find("\n#line ", from);
    return at == std::string::npos ? at : at + 1;
}

}  // namespace

std::optional<OutputKey> OutputMemo::Key(const std::shared_ptr<const IncludeWalk>& walk,
                                         const PpMacros& macros) {
    std::shared_ptr<const WalkWords> words;
    {
        std::lock_guard<std::mutex> lock(mu_);
        if (const auto it = walks_.find(walk.get()); it != walks_.end())
            words = it->second.words;
        else if (bytes_ > kMaxBytes)
            return std::nullopt;
    }
    if (!words) {
        std::shared_ptr<const WalkWords> made = MakeWalkWords(*walk);
        std::lock_guard<std::mutex> lock(mu_);
        Entry& e = walks_[walk.get()];
        if (!e.words) {
            e.walk = walk;
            e.words = std::move(made);
            bytes_ += 256 + e.words->directives.size() + 16 * e.words->words.size();
        }
        words = e.words;
    }
    if (!words->usable)
        return std::nullopt;
    return macros.Fingerprint(words->words);
}

std::shared_ptr<const KeptOutput> OutputMemo::Find(const IncludeWalk* walk, const OutputKey& key) {
    std::lock_guard<std::mutex> lock(mu_);
    const auto it = walks_.find(walk);
    if (it == walks_.end())
        return nullptr;
    for (const auto& [k, output] : it->second.outputs) {
        if (k == key)
            return output;
    }
    return nullptr;
}

std::shared_ptr<const WalkWords> OutputMemo::Words(const IncludeWalk* walk) {
    std::lock_guard<std::mutex> lock(mu_);
    const auto it = walks_.find(walk);
    return it == walks_.end() ? nullptr : it->second.words;
}

void OutputMemo::Add(const OutputMark& mark, std::string output) {
    auto kept = std::make_shared<KeptOutput>();
    if (!Spacing(output, kept->last))
        return;
    kept->text = std::move(output);
    std::lock_guard<std::mutex> lock(mu_);
    const auto it = walks_.find(mark.walk.get());
    if (it == walks_.end() || it->second.outputs.size() >= kMaxOutputsPerWalk ||
        bytes_ + kept->text.size() > kMaxBytes)
        return;
    for (const auto& entry : it->second.outputs) {
        if (entry.first == mark.key)
            return;  // kept meanwhile by another program
    }
    bytes_ += kept->text.size() + 64;
    it->second.outputs.emplace_back(mark.key, std::move(kept));
}

std::string ReplayedText(const WalkWords& words, const KeptOutput& output) {
    std::string text = words.directives;
    if (output.last != 0) {
        text += output.last;
        text += '\n';
    }
    return text;
}

std::string OutputMarkName(size_t inclusion, std::string_view path) {
    return MarkedName(kOutputMarkTag, inclusion, path);
}

bool RestoreOutputs(std::string& text, const std::vector<OutputMark>& marks, OutputMemo* memo) {
    if (marks.empty())
        return true;
    const std::string prefix = "\"" + std::string(kSpliceMarker) + kOutputMarkTag;
    size_t added = 0;
    for (const OutputMark& m : marks)
        added += m.output ? m.output->text.size() : 0;
    std::string out;
    out.reserve(text.size() + added);
    std::vector<size_t> starts(marks.size(), std::string::npos);  // a recorded output's, in `out`
    std::vector<char> seen(marks.size(), 0);
    size_t copied = 0;
    for (size_t p = text.find(prefix); p != std::string::npos; p = text.find(prefix, p + 1)) {
        size_t index = 0;
        const char* digits = text.data() + p + prefix.size();
        const auto r = std::from_chars(digits, text.data() + text.size(), index);
        if (r.ec != std::errc() || r.ptr == digits || !InLineDirective(text, p))
            return false;
        const size_t path = r.ptr - text.data();
        const size_t end = path < text.size() && text[path] == kMarkedPathStart
                               ? text.find('"', path + 1)
                               : std::string::npos;
        if (end == std::string::npos || end + 1 >= text.size() || text[end + 1] != '\n')
            return false;
        const auto m =
            std::lower_bound(marks.begin(), marks.end(), index,
                             [](const OutputMark& x, size_t i) { return x.inclusion < i; });
        if (m == marks.end() || m->inclusion != index)
            return false;
        const size_t k = static_cast<size_t>(m - marks.begin());
        out.append(text, copied, p + 1 - copied);
        out.append(text, path + 1, end - path - 1);
        out += "\"\n";
        copied = end + 2;
        p = end;
        if (seen[k])
            continue;  // a return to a recorded walk's root from a file it includes
        seen[k] = 1;   // its prologue: glslang prints it before any return to it
        if (!m->output) {
            starts[k] = out.size();
            continue;
        }
        // What glslang printed for the served directives: empty lines and #pragma lines, up to
        // the return's #line.
        const size_t back = NextLineDirective(text, end + 2);
        if (back == std::string::npos)
            return false;
        out += m->output->text;
        copied = back;
        p = back;
    }
    out.append(text, copied);
    for (size_t k = 0; k < marks.size(); ++k) {
        if (!seen[k])
            return false;
    }
    if (memo != nullptr) {
        for (size_t k = 0; k < marks.size(); ++k) {
            if (starts[k] == std::string::npos)
                continue;
            // Each file the walk includes prints a prologue and a return; then its own return.
            size_t at = starts[k];
            for (size_t lines = 2 * (marks[k].count - 1) + 1; lines > 0 && at != std::string::npos;
                 --lines) {
                at = NextLineDirective(out, at);
                if (lines > 1 && at != std::string::npos)
                    ++at;
            }
            if (at != std::string::npos)
                memo->Add(marks[k], out.substr(starts[k], at - starts[k]));
        }
    }
    text.swap(out);
    return true;
}

}  // namespace kiln::hlsl
