#include "kiln/pack/reader.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <utility>

#include <xxhash.h>

#include "kiln/base/files.h"
#include "kiln/base/text.h"
#include "kiln/pack/names.h"

#include "kiln/pack/pass_id.h"

namespace kiln::pack {

MappedFile::MappedFile(MappedFile&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)) {}

MappedFile& MappedFile::operator=(MappedFile&& other) noexcept {
    if (this != &other) {
        this->~MappedFile();
        data_ = std::exchange(other.data_, nullptr);
        size_ = std::exchange(other.size_, 0);
    }
    return *this;
}

MappedFile::~MappedFile() {
    if (data_ != nullptr && size_ > 0) {
        munmap(const_cast<uint8_t*>(data_), size_);
    }
}

Result<MappedFile> MappedFile::Map(const std::string& path) {
    if (path == base::kStandardStream) {
        // Standard input (kiln info -): its bytes copied into an anonymous mapping, which is
        // page-aligned as a file's is and unmapped the same way.
        Result<std::string> read = base::ReadRegularFile(path, uint64_t{4} << 30);
        if (!read)
            return read.error();
        MappedFile out;
        if (read.value().empty())
            return out;
        void* p = mmap(nullptr, read.value().size(), PROT_READ | PROT_WRITE,
                       MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (p == MAP_FAILED) {
            return Error{DiagCode::kCannotReadFile,
                         std::string("cannot hold standard input: ") + std::strerror(errno)};
        }
        std::memcpy(p, read.value().data(), read.value().size());
        out.data_ = static_cast<const uint8_t*>(p);
        out.size_ = read.value().size();
        return out;
    }
    // O_NONBLOCK: opening a FIFO must not wait for a writer (fstat then refuses it).
    const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) {
        return Error{DiagCode::kCannotReadFile,
                     "cannot open '" + path + "': " + std::strerror(errno)};
    }
    struct stat st {};
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(fd);
        return Error{DiagCode::kCannotReadFile, "'" + path + "' is not a regular file"};
    }
    base::NoteInputFile(path);
    MappedFile out;
    if (st.st_size == 0) {
        close(fd);
        return out;  // an empty mapping; Pack::Open reports it as truncated
    }
    void* p = mmap(nullptr, static_cast<size_t>(st.st_size), PROT_READ, MAP_PRIVATE, fd, 0);
    close(fd);
    if (p == MAP_FAILED) {
        return Error{DiagCode::kCannotReadFile,
                     "cannot map '" + path + "': " + std::strerror(errno)};
    }
    out.data_ = static_cast<const uint8_t*>(p);
    out.size_ = static_cast<size_t>(st.st_size);
    return out;
}

std::string_view Pack::String(StrRef ref) const {
    const SectionEntry& s = sections_[Index(SectionTag::kStrings)];
    if (ref.offset > s.size || ref.length > s.size - ref.offset)
        return {};
    return {reinterpret_cast<const char*>(bytes_.data() + s.offset + ref.offset), ref.length};
}

Result<std::string_view> Pack::Keyword(uint32_t i) const {
    if (i >= Count(SectionTag::kKeywords)) {
        return OutOfRange(SectionTag::kKeywords, i);
    }
    return KeywordAt(i);
}

Error Pack::OutOfRange(SectionTag tag, uint32_t index) const {
    const uint32_t t = uint32_t(tag);
    const std::string name{char(t), char(t >> 8), char(t >> 16), char(t >> 24)};
    return Error{DiagCode::kIndexOutOfRange, "record " + std::to_string(index) + " of section " +
                                                 name + " is out of range (the pack has " +
                                                 std::to_string(Count(tag)) + ")"};
}

std::span<const uint32_t> Pack::SpirvWords(const ModuleRec& module) const {
    static_assert(std::endian::native == std::endian::little, "SPIR-V words are little-endian");
    const std::span<const uint8_t> bytes = Spirv(module);
    if (reinterpret_cast<uintptr_t>(bytes.data()) % alignof(uint32_t) != 0) {
        return {};
    }
    return {reinterpret_cast<const uint32_t*>(bytes.data()), bytes.size() / 4};
}

std::span<const uint8_t> Pack::Spirv(const ModuleRec& module) const {
    const SectionEntry& s = sections_[Index(SectionTag::kSpirv)];
    if (module.spirv_offset > s.size || module.spirv_size > s.size - module.spirv_offset)
        return {};
    const std::span<const uint8_t> out =
        bytes_.subspan(s.offset + module.spirv_offset, module.spirv_size);
    // Checked on every read when the variant data is checked on first use (about 0.1 ms per
    // megabyte, where a pipeline's creation costs far more).
    if (deferred_ != nullptr && XXH64(out.data(), out.size(), 0) != module.hash)
        return {};
    return out;
}

std::optional<uint32_t> Pack::FindShader(std::string_view name) const {
    for (uint32_t i = 0; i < Count(SectionTag::kShaders); ++i) {
        if (String(Record<ShaderRec>(SectionTag::kShaders, i).name) == name)
            return i;
    }
    return std::nullopt;
}

std::optional<uint32_t> Pack::FindPass(uint32_t shader, std::string_view name) const {
    if (shader >= Count(SectionTag::kShaders))
        return std::nullopt;
    const ShaderRec s = Record<ShaderRec>(SectionTag::kShaders, shader);
    for (uint32_t i = s.first_pass; i < s.first_pass + s.pass_count; ++i) {
        if (base::EqualsIgnoreCase(PassLabel(*this, i), name))
            return i;  // the pass's one name (kiln/pack/pass_id.h)
    }
    for (uint32_t i = s.first_pass; i < s.first_pass + s.pass_count; ++i) {
        if (base::EqualsIgnoreCase(String(Record<PassRec>(SectionTag::kPasses, i).name), name))
            return i;
    }
    for (uint32_t i = s.first_pass; i < s.first_pass + s.pass_count; ++i) {
        if (base::EqualsIgnoreCase(LightModeOf(*this, i), name))
            return i;
    }
    return std::nullopt;
}

std::optional<std::string_view> Pack::GrabTexture(uint32_t pass) const {
    uint32_t lo = 0, hi = Count(SectionTag::kGrabPasses);  // sorted by pass
    while (lo < hi) {
        const uint32_t mid = lo + (hi - lo) / 2;
        const GrabRec g = Record<GrabRec>(SectionTag::kGrabPasses, mid);
        if (g.pass == pass)
            return String(g.texture);
        if (g.pass < pass) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    return std::nullopt;
}

uint32_t Pack::AliasOf(uint32_t keyword_set, uint32_t index) const {
    const uint32_t n = Count(SectionTag::kKeywordAliases);
    uint32_t lo = 0, hi = n;  // sorted by (set, from): a binary search
    while (lo < hi) {
        const uint32_t mid = lo + (hi - lo) / 2;
        const auto a = Record<KeywordAliasRec>(SectionTag::kKeywordAliases, mid);
        if (a.keyword_set == keyword_set && a.from == index)
            return a.to;
        if (a.keyword_set < keyword_set || (a.keyword_set == keyword_set && a.from < index)) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    return index;
}

std::optional<uint32_t> Pack::FindVariant(uint32_t pass, VariantKey key) const {
    if (pass >= Count(SectionTag::kPasses) || !CheckVariantData().ok())
        return std::nullopt;
    const PassRec p = Record<PassRec>(SectionTag::kPasses, pass);
    if (Count(SectionTag::kKeywordAliases) > 0) {
        for (uint32_t s = p.first_keyword_set; s < p.first_keyword_set + p.keyword_set_count; ++s) {
            const KeywordSetRec set = Record<KeywordSetRec>(SectionTag::kKeywordSets, s);
            key.Set(set.key_shift, set.key_bits, AliasOf(s, key.Get(set.key_shift, set.key_bits)));
        }
    }
    uint32_t lo = p.first_variant, hi = p.first_variant + p.variant_count;
    while (lo < hi) {
        const uint32_t mid = lo + (hi - lo) / 2;
        const uint64_t k = Record<VariantRec>(SectionTag::kVariants, mid).key;
        if (k == key.bits())
            return mid;
        if (k < key.bits()) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    return std::nullopt;
}

VariantKey Pack::KeyFor(uint32_t pass, const std::vector<std::string>& enabled) const {
    VariantKey key;
    if (pass >= Count(SectionTag::kPasses))
        return key;
    const PassRec p = Record<PassRec>(SectionTag::kPasses, pass);
    for (uint32_t s = p.first_keyword_set; s < p.first_keyword_set + p.keyword_set_count; ++s) {
        const KeywordSetRec set = Record<KeywordSetRec>(SectionTag::kKeywordSets, s);
        for (uint32_t k = 0; k < set.keyword_count; ++k) {
            const std::string_view kw = KeywordAt(set.first_keyword + k);
            if (!kw.empty() && std::find(enabled.begin(), enabled.end(), kw) != enabled.end()) {
                key.Set(set.key_shift, set.key_bits, k);
                break;
            }
        }
    }
    return key;
}

Status Pack::CheckKeywords(uint32_t pass, const std::vector<std::string>& enabled) const {
    if (pass >= Count(SectionTag::kPasses))
        return OutOfRange(SectionTag::kPasses, pass);
    std::vector<std::string> declared;
    const PassRec p = Record<PassRec>(SectionTag::kPasses, pass);
    for (uint32_t s = p.first_keyword_set; s < p.first_keyword_set + p.keyword_set_count; ++s) {
        const KeywordSetRec set = Record<KeywordSetRec>(SectionTag::kKeywordSets, s);
        for (uint32_t k = 0; k < set.keyword_count; ++k) {
            const std::string_view kw = KeywordAt(set.first_keyword + k);
            if (!kw.empty())
                declared.emplace_back(kw);
        }
    }
    for (const std::string& name : enabled) {
        if (std::find(declared.begin(), declared.end(), name) == declared.end()) {
            return Error{
                DiagCode::kUnknownKeyword,
                "keyword '" + name + "' is not declared by the pass" + DidYouMean(name, declared)};
        }
    }
    return {};
}

std::vector<std::string> Pack::KeywordsOf(uint32_t pass, VariantKey key) const {
    std::vector<std::string> out;
    if (pass >= Count(SectionTag::kPasses))
        return out;
    const PassRec p = Record<PassRec>(SectionTag::kPasses, pass);
    for (uint32_t s = p.first_keyword_set; s < p.first_keyword_set + p.keyword_set_count; ++s) {
        const KeywordSetRec set = Record<KeywordSetRec>(SectionTag::kKeywordSets, s);
        const uint32_t index = key.Get(set.key_shift, set.key_bits);
        if (index < set.keyword_count) {
            const std::string_view kw = KeywordAt(set.first_keyword + index);
            if (!kw.empty())
                out.emplace_back(kw);
        }
    }
    return out;
}

}  // namespace kiln::pack
