#include "worker/protocol.h"

#include <sys/socket.h>

#include <cerrno>
#include <charconv>
#include <cstdio>

#include <xxhash.h>

#include "kiln/base/bytes.h"

namespace kiln::worker {
namespace {

// Field tags. A string list repeats its tag once per element.
enum Tag : uint8_t {
    kKind = 1,
    kStage,
    kName,
    kSource,
    kEntry,
    kIncludeDir,
    kTemplatesDir,
    kDebugInfo,
    kOptLevel,
    kOptimize,
    kWords,
    kOk,
    kEntryMissing,
    kFailedIn,
    kText,
    kInfoLog,
    kMessages,
    kFileRead,
    kReason,
    kDetail,
    kRewritten,
    kFunction,
    kHalfArithmetic,
    kSecondEntry,
    kSecondOk,
    kSecondText,
    kSecondFunction,
    kUnityVersion,  // 28
    // The hello, the file exchange and the failure's component (protocol 2). The numbers are the
    // wire format: tests/fuzz/make_protocol_seeds.py and the pool test's stand-in worker use them.
    kProtocol = 29,
    kProducer = 30,
    kPath = 31,
    kFound = 32,
    kHash = 33,
    kContent = 34,
    kComponent = 35,
    kPinned = 36,
    kKeepDeclarations = 37,
};

// Builds a whole frame: the length is patched in when it is taken.
class Writer {
  public:
    explicit Writer(FrameType type) {
        base::AppendLe32(out_, 0);
        base::AppendLe32(out_, uint32_t(type));
    }
    void Bytes(Tag tag, std::string_view bytes) {
        out_ += static_cast<char>(tag);
        base::AppendLe32(out_, static_cast<uint32_t>(bytes.size()));
        out_.append(bytes);
    }
    void U8(Tag tag, uint8_t v) { Bytes(tag, std::string_view(reinterpret_cast<char*>(&v), 1)); }
    void Words(Tag tag, const std::vector<uint32_t>& words) {
        std::string b;
        b.reserve(words.size() * 4);
        for (uint32_t w : words)
            base::AppendLe32(b, w);
        Bytes(tag, b);
    }
    std::string Take() {
        const auto n = static_cast<uint32_t>(out_.size() - 4);
        for (int i = 0; i < 4; ++i)
            out_[size_t(i)] = static_cast<char>(n >> (8 * i));
        return std::move(out_);
    }

  private:
    std::string out_;
};

// Calls fn(tag, bytes) for every field; false when a field runs past the end.
template <typename Fn>
bool ForEachField(std::string_view fields, Fn&& fn) {
    size_t at = 0;
    while (at < fields.size()) {
        if (fields.size() - at < 5)
            return false;
        const auto tag = static_cast<uint8_t>(fields[at]);
        const uint32_t size = base::LoadLe32(fields, at + 1);
        at += 5;
        if (size > fields.size() - at)
            return false;
        if (!fn(tag, fields.substr(at, size)))
            return false;
        at += size;
    }
    return true;
}

bool ToU8(std::string_view b, uint8_t& v) {
    if (b.size() != 1)
        return false;
    v = static_cast<uint8_t>(b[0]);
    return true;
}

bool ToBool(std::string_view b, bool& v) {
    uint8_t x = 0;
    if (!ToU8(b, x) || x > 1)
        return false;
    v = x == 1;
    return true;
}

bool ToWords(std::string_view b, std::vector<uint32_t>& words) {
    if (b.size() % 4 != 0)
        return false;
    words.resize(b.size() / 4);
    for (size_t i = 0; i < words.size(); ++i)
        words[i] = base::LoadLe32(b, i * 4);
    return true;
}

bool ToComponent(std::string_view b, Component& c) {
    uint8_t x = 0;
    if (!ToU8(b, x) || x > uint8_t(Component::kKilnReduction))
        return false;
    c = static_cast<Component>(x);
    return true;
}

}  // namespace

const char* ComponentName(Component c) {
    switch (c) {
        case Component::kNone:
            return "the compile worker";
        case Component::kGlslangPreprocessor:
            return "glslang's preprocessor";
        case Component::kGlslang:
            return "glslang";
        case Component::kSpirvOpt:
            return "SPIRV-Tools' optimizer";
        case Component::kSpirvVal:
            return "SPIRV-Tools' validator";
        case Component::kKilnReduction:
            return "Kiln's rewrite and reduction of the preprocessed text";
    }
    return "the compile worker";
}

Component FirstComponent(RequestKind kind) {
    switch (kind) {
        case RequestKind::kPreprocess:
            return Component::kGlslangPreprocessor;
        case RequestKind::kCompile:
            return Component::kGlslang;
        case RequestKind::kFinish:
            return Component::kSpirvOpt;
        case RequestKind::kValidate:
            return Component::kSpirvVal;
        case RequestKind::kSelfTest:
            return Component::kNone;
    }
    return Component::kNone;
}

std::string EncodeRequest(const Request& r) {
    Writer w(FrameType::kRequest);
    w.U8(kKind, uint8_t(r.kind));
    w.U8(kStage, uint8_t(r.stage));
    w.Bytes(kName, r.name);
    w.Bytes(kSource, r.source);
    w.Bytes(kEntry, r.entry);
    w.Bytes(kSecondEntry, r.second_entry);
    for (const std::string& name : r.pinned)
        w.Bytes(kPinned, name);
    for (const std::string& d : r.include_dirs)
        w.Bytes(kIncludeDir, d);
    w.Bytes(kTemplatesDir, r.templates_dir);
    if (r.unity_version != 0)
        w.Bytes(kUnityVersion, std::to_string(r.unity_version));
    w.U8(kDebugInfo, r.debug_info);
    w.U8(kOptLevel, r.opt_level);
    w.U8(kOptimize, r.optimize);
    w.U8(kHalfArithmetic, r.half_arithmetic);
    if (r.keep_declarations)
        w.U8(kKeepDeclarations, true);
    w.Words(kWords, r.words);
    return w.Take();
}

std::string EncodeResponse(const Response& r) {
    Writer w(FrameType::kResponse);
    w.U8(kOk, r.ok);
    w.U8(kEntryMissing, r.entry_missing);
    w.U8(kFailedIn, uint8_t(r.failed_in));
    w.Bytes(kText, r.text);
    w.Bytes(kInfoLog, r.info_log);
    w.Bytes(kMessages, r.messages);
    w.Words(kWords, r.words);
    for (const std::string& f : r.files_read)
        w.Bytes(kFileRead, f);
    w.Bytes(kRewritten, r.rewritten);
    for (const std::string& f : r.functions)
        w.Bytes(kFunction, f);
    w.U8(kSecondOk, r.second_ok);
    w.Bytes(kSecondText, r.second_text);
    for (const std::string& f : r.second_functions)
        w.Bytes(kSecondFunction, f);
    return w.Take();
}

std::string EncodeFailure(std::string_view reason, std::string_view detail, Component component) {
    Writer w(FrameType::kFailure);
    w.Bytes(kReason, reason);
    w.Bytes(kDetail, detail);
    w.U8(kComponent, uint8_t(component));
    return w.Take();
}

std::string ContentHash(std::string_view content) {
    const XXH128_hash_t h = XXH3_128bits(content.data(), content.size());
    char hex[33];
    std::snprintf(hex, sizeof hex, "%016llx%016llx", static_cast<unsigned long long>(h.high64),
                  static_cast<unsigned long long>(h.low64));
    return hex;
}

std::string EncodeHello(const Hello& h) {
    Writer w(FrameType::kHello);
    std::string v;
    base::AppendLe32(v, h.protocol);
    w.Bytes(kProtocol, v);
    w.Bytes(kProducer, h.producer);
    return w.Take();
}

std::string EncodeNeedFile(std::string_view path) {
    Writer w(FrameType::kNeedFile);
    w.Bytes(kPath, path);
    return w.Take();
}

std::string EncodeFile(const FileAnswer& f) {
    Writer w(FrameType::kFile);
    w.Bytes(kPath, f.path);
    w.U8(kFound, f.found);
    if (f.found)
        w.Bytes(kHash, f.hash);
    if (f.with_content)
        w.Bytes(kContent, f.content);
    return w.Take();
}

std::optional<Frame> SplitFrame(std::string_view payload) {
    if (payload.size() < 4)
        return std::nullopt;
    const uint32_t type = base::LoadLe32(payload, 0);
    switch (static_cast<FrameType>(type)) {
        case FrameType::kRequest:
        case FrameType::kResponse:
        case FrameType::kFailure:
        case FrameType::kHello:
        case FrameType::kNeedFile:
        case FrameType::kFile:
            return Frame{static_cast<FrameType>(type), payload.substr(4)};
    }
    return std::nullopt;
}

std::optional<Frame> SplitWholeFrame(std::string_view frame) {
    if (frame.size() < 4 || base::LoadLe32(frame, 0) != frame.size() - 4)
        return std::nullopt;
    return SplitFrame(frame.substr(4));
}

std::optional<Request> DecodeRequest(std::string_view fields) {
    Request r;
    const bool ok = ForEachField(fields, [&r](uint8_t tag, std::string_view b) {
        uint8_t x = 0;
        switch (tag) {
            case kKind:
                if (!ToU8(b, x) || x < uint8_t(RequestKind::kPreprocess) ||
                    x > uint8_t(RequestKind::kSelfTest))
                    return false;
                r.kind = static_cast<RequestKind>(x);
                return true;
            case kStage:
                if (!ToU8(b, x) || x >= pack::kStageCount)
                    return false;
                r.stage = static_cast<pack::Stage>(x);
                return true;
            case kName:
                r.name = b;
                return true;
            case kSource:
                r.source = b;
                return true;
            case kEntry:
                r.entry = b;
                return true;
            case kSecondEntry:
                r.second_entry = b;
                return true;
            case kIncludeDir:
                r.include_dirs.emplace_back(b);
                return true;
            case kPinned:
                r.pinned.emplace_back(b);
                return true;
            case kTemplatesDir:
                r.templates_dir = b;
                return true;
            case kUnityVersion: {
                const auto [end, error] =
                    std::from_chars(b.data(), b.data() + b.size(), r.unity_version);
                return error == std::errc() && end == b.data() + b.size() && r.unity_version > 0;
            }
            case kDebugInfo:
                return ToBool(b, r.debug_info);
            case kOptLevel:
                return ToU8(b, r.opt_level) && r.opt_level <= 3;
            case kOptimize:
                return ToBool(b, r.optimize);
            case kHalfArithmetic:
                return ToBool(b, r.half_arithmetic);
            case kKeepDeclarations:
                return ToBool(b, r.keep_declarations);
            case kWords:
                return ToWords(b, r.words);
            default:
                return true;  // a newer sender's field
        }
    });
    return ok ? std::optional<Request>(std::move(r)) : std::nullopt;
}

std::optional<Response> DecodeResponse(std::string_view fields) {
    Response r;
    const bool ok = ForEachField(fields, [&r](uint8_t tag, std::string_view b) {
        switch (tag) {
            case kOk:
                return ToBool(b, r.ok);
            case kEntryMissing:
                return ToBool(b, r.entry_missing);
            case kFailedIn:
                return ToComponent(b, r.failed_in);
            case kText:
                r.text = b;
                return true;
            case kInfoLog:
                r.info_log = b;
                return true;
            case kMessages:
                r.messages = b;
                return true;
            case kWords:
                return ToWords(b, r.words);
            case kFileRead:
                r.files_read.emplace_back(b);
                return true;
            case kRewritten:
                r.rewritten = b;
                return true;
            case kFunction:
                r.functions.emplace_back(b);
                return true;
            case kSecondOk:
                return ToBool(b, r.second_ok);
            case kSecondText:
                r.second_text = b;
                return true;
            case kSecondFunction:
                r.second_functions.emplace_back(b);
                return true;
            default:
                return true;
        }
    });
    return ok ? std::optional<Response>(std::move(r)) : std::nullopt;
}

std::optional<Failure> DecodeFailure(std::string_view fields) {
    Failure f;
    const bool ok = ForEachField(fields, [&f](uint8_t tag, std::string_view b) {
        if (tag == kReason)
            f.reason = b;
        else if (tag == kDetail)
            f.detail = b;
        else if (tag == kComponent)
            return ToComponent(b, f.component);
        return true;
    });
    return ok ? std::optional<Failure>(std::move(f)) : std::nullopt;
}

std::optional<Hello> DecodeHello(std::string_view fields) {
    Hello h;
    h.protocol = 0;
    bool has_protocol = false;
    const bool ok = ForEachField(fields, [&](uint8_t tag, std::string_view b) {
        if (tag == kProtocol) {
            if (b.size() != 4)
                return false;
            h.protocol = base::LoadLe32(b, 0);
            has_protocol = true;
        } else if (tag == kProducer) {
            h.producer = b;
        }
        return true;
    });
    return ok && has_protocol ? std::optional<Hello>(std::move(h)) : std::nullopt;
}

std::optional<std::string> DecodeNeedFile(std::string_view fields) {
    std::optional<std::string> path;
    const bool ok = ForEachField(fields, [&path](uint8_t tag, std::string_view b) {
        if (tag == kPath)
            path = std::string(b);
        return true;
    });
    return ok && path && !path->empty() ? path : std::nullopt;
}

std::optional<FileAnswer> DecodeFile(std::string_view fields) {
    FileAnswer f;
    bool has_path = false;
    const bool ok = ForEachField(fields, [&](uint8_t tag, std::string_view b) {
        switch (tag) {
            case kPath:
                f.path = b;
                has_path = true;
                return true;
            case kFound:
                return ToBool(b, f.found);
            case kHash:
                f.hash = b;
                return b.size() == 32;
            case kContent:
                f.content = b;
                f.with_content = true;
                return true;
            default:
                return true;
        }
    });
    // A file found names its content; content sent must be what the hash says.
    if (!ok || !has_path || (f.found && f.hash.empty()) || (!f.found && f.with_content) ||
        (f.with_content && ContentHash(f.content) != f.hash))
        return std::nullopt;
    return f;
}

bool SendFrame(int fd, const std::string& frame) {
    size_t at = 0;
    while (at < frame.size()) {
        const ssize_t n = send(fd, frame.data() + at, frame.size() - at, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        at += static_cast<size_t>(n);
    }
    return true;
}

std::span<char> FrameReader::Room() {
    if (header_have_ < 4)
        return {header_ + header_have_, 4 - header_have_};
    return {body_.data() + body_have_, body_.size() - body_have_};
}

bool FrameReader::Advance(size_t n) {
    if (header_have_ < 4) {
        header_have_ += n;
        if (header_have_ < 4)
            return false;
        const uint32_t size = base::LoadLe32(std::string_view(header_, 4), 0);
        if (size > kMaxFrameBytes) {
            bad_ = true;
            return false;
        }
        body_.assign(size, '\0');
        body_have_ = 0;
        return size == 0;
    }
    body_have_ += n;
    return body_have_ == body_.size();
}

std::string FrameReader::Take() {
    header_have_ = 0;
    body_have_ = 0;
    return std::move(body_);
}

}  // namespace kiln::worker
