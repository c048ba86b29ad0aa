// The compile-worker protocol: one request (a program's text and options) in, one response
// (SPIR-V, glslang's log, SPIRV-Tools' messages) out. The same messages serve the in-process
// executor, the worker processes (worker/pool.h) and, later, distributed compilation.
//
// A connection opens with a hello each way (protocol and producer versions; a worker of another
// version is refused, since its SPIR-V would not be what the cache keys promise). The worker
// reads no file of the client's: while it preprocesses, it asks for each file it looks for
// (kNeedFile, by the client's path) and the client answers with the file's hash and, unless it
// sent that content on this connection before, its bytes (kFile); the worker keeps contents by
// hash. So a worker needs no access to the client's folders (worker/file_exchange.h).
//
// A frame on the wire is u32 length (little-endian) + payload; Encode* return whole frames. A
// payload is a u32 frame type then fields: u8 tag, u32 size, bytes. Unknown tags are skipped; every
// read is bounds-checked, since a worker that went wrong may send anything.
#ifndef KILN_WORKER_PROTOCOL_H_
#define KILN_WORKER_PROTOCOL_H_

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "kiln/pack/format.h"

namespace kiln::worker {

// Bumped with every change a peer of the previous version would misread.
inline constexpr uint32_t kProtocolVersion = 2;

// The largest frame either side accepts (a preprocessed Unity shader is well under 8 MiB).
inline constexpr uint32_t kMaxFrameBytes = 256u << 20;

enum class RequestKind : uint8_t {
    // glslang's preprocessor over `source` (includes resolved by the worker), then Kiln's
    // rewrites for glslang and the reduction to what `entry` reaches (hlsl/rewrite.h, reduce.h).
    kPreprocess = 1,
    kCompile = 2,   // glslang HLSL -> SPIR-V, then SPIRV-Tools legalization and -O/-Os
    kFinish = 3,    // SPIRV-Tools: strip reflection info from `words`, then spirv-val
    kValidate = 4,  // spirv-val over `words` (a compile-cache entry)
    kSelfTest = 5,  // tests of the isolation itself: `source` is crash|hang|allocate|exit
};

// The component a request was in when it ended (for diagnostics): a third-party one, or Kiln's
// own rewrite and reduction, which run in the worker right after glslang's preprocessor.
enum class Component : uint8_t {
    kNone,
    kGlslangPreprocessor,
    kGlslang,
    kSpirvOpt,
    kSpirvVal,
    kKilnReduction,
};
const char* ComponentName(Component c);
// The component a request starts in.
Component FirstComponent(RequestKind kind);

struct Request {
    RequestKind kind = RequestKind::kCompile;
    pack::Stage stage = pack::Stage::kVertex;
    std::string name;    // the main file's name: its folder is searched for `#include "x"`
    std::string source;  // program text
    std::string entry;   // kCompile: the entry point
    // kPreprocess: also reduce to this entry point of the other stage, when the preprocessed text
    // cannot depend on the stage (driver/preprocess.cpp pairs a variant's two stages).
    std::string second_entry;
    // kPreprocess: the pass's keywords (every name its variants may define), whose include
    // prefix is then shared (hlsl/preamble.h) when no keyword can change its output.
    std::vector<std::string> pinned;
    std::vector<std::string> include_dirs;  // -I, in order
    std::string templates_dir;              // the built-in include library
    int unity_version = 0;    // --unity-version: the layer serves that release's files (0: any)
    bool debug_info = false;  // kCompile/kFinish: keep debug info (-g)
    uint8_t opt_level = 1;    // kCompile: spirv::OptLevel
    bool optimize = true;     // kCompile: run SPIRV-Tools after glslang
    bool half_arithmetic = false;  // kCompile: RelaxedPrecision arithmetic as binary16
    // kPreprocess: reduce to what the entry point reaches but keep every declaration (the
    // names a "did you mean" after an error reads; hlsl/reduce.h).
    bool keep_declarations = false;
    std::vector<uint32_t> words;  // kFinish/kValidate
};

struct Response {
    bool ok = false;
    bool entry_missing = false;  // kCompile: no function named like the entry point
    Component failed_in = Component::kNone;
    std::string text;       // kPreprocess: the text reduced to the entry point
    std::string rewritten;  // kPreprocess: the preprocessed text, when a rewrite changed it
    std::vector<std::string> functions;  // kPreprocess: every function, when `entry` is none
    // kPreprocess with second_entry: true when the text was reduced to it as well (no file read,
    // and nothing in the source but the stage's own #define, names SHADER_STAGE_*).
    bool second_ok = false;
    std::string second_text;
    std::vector<std::string> second_functions;
    std::string info_log;  // glslang's messages (frontend/glslang_messages.h reads them)
    std::string messages;  // SPIRV-Tools' messages when it failed
    std::vector<uint32_t> words;
    std::vector<std::string> files_read;  // every include served, for diagnostics and depfiles
};

// Frame types.
enum class FrameType : uint32_t {
    kRequest = 0x4b525131,   // "1QRK"
    kResponse = 0x4b525331,  // a Response
    kFailure = 0x4b524631,   // the worker cannot go on (reason: "memory", "exception", ...)
    kHello = 0x4b524831,     // each side's versions, first on a connection
    kNeedFile = 0x4b524e31,  // worker -> client: the file at a client path, please
    kFile = 0x4b524331,      // client -> worker: that file's hash and (maybe) its bytes
};

struct Hello {
    uint32_t protocol = kProtocolVersion;
    std::string producer;  // kiln::ProducerVersion(): Kiln's, glslang's and SPIRV-Tools' versions
};

struct FileAnswer {
    std::string path;
    bool found = false;
    std::string hash;           // ContentHash(content), when found
    bool with_content = false;  // false: the worker has it (sent before on this connection)
    std::string content;
};

// 32 hex digits (XXH3, 128 bits) naming a file's content.
std::string ContentHash(std::string_view content);

std::string EncodeRequest(const Request& r);
std::string EncodeResponse(const Response& r);
std::string EncodeFailure(std::string_view reason,
                          std::string_view detail,
                          Component component = Component::kNone);
std::string EncodeHello(const Hello& h);
std::string EncodeNeedFile(std::string_view path);
std::string EncodeFile(const FileAnswer& f);

// A frame's payload (what follows the length) split into its type and fields; nullopt when
// malformed.
struct Frame {
    FrameType type{};
    std::string_view payload;  // fields, after the type
};
std::optional<Frame> SplitFrame(std::string_view payload);
// The same for a whole frame as Encode* return it: its length first, which must be its size.
std::optional<Frame> SplitWholeFrame(std::string_view frame);
std::optional<Request> DecodeRequest(std::string_view fields);
std::optional<Response> DecodeResponse(std::string_view fields);
struct Failure {
    std::string reason, detail;
    Component component = Component::kNone;  // where the worker was when it gave up
};
std::optional<Failure> DecodeFailure(std::string_view fields);
std::optional<Hello> DecodeHello(std::string_view fields);
std::optional<std::string> DecodeNeedFile(std::string_view fields);
std::optional<FileAnswer> DecodeFile(std::string_view fields);

// Sends a whole frame on a socket (no SIGPIPE when the peer is gone); false when it is gone.
bool SendFrame(int fd, const std::string& frame);

// Frames arriving on a socket, each read straight into its own string: Room() is where the next
// bytes go, Advance(n) says n arrived there; once it returns true, Take() gives the payload.
class FrameReader {
  public:
    std::span<char> Room();
    bool Advance(size_t n);
    // The length announced is over kMaxFrameBytes: the peer is not speaking the protocol.
    bool bad() const { return bad_; }
    std::string Take();

  private:
    char header_[4] = {};
    size_t header_have_ = 0;
    std::string body_;
    size_t body_have_ = 0;
    bool bad_ = false;
};

}  // namespace kiln::worker

#endif  // KILN_WORKER_PROTOCOL_H_
