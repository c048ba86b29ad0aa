// libFuzzer target: the compile-worker protocol's decoders (worker/protocol.h) on arbitrary
// payloads, as a worker or a client that went wrong may send them. Every decoder answers a value
// or nullopt without reading past the end; a value encoded again decodes to the same.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "worker/protocol.h"

namespace {

using namespace kiln::worker;

void Check(bool ok) {
    if (!ok)
        std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view payload(reinterpret_cast<const char*>(data), size);
    const auto frame = SplitFrame(payload);
    const std::string_view fields = frame ? frame->payload : payload;
    if (const auto r = DecodeRequest(fields)) {
        const auto again = DecodeRequest(SplitWholeFrame(EncodeRequest(*r))->payload);
        Check(again && again->source == r->source && again->words == r->words &&
              again->include_dirs == r->include_dirs);
    }
    if (const auto r = DecodeResponse(fields)) {
        const auto again = DecodeResponse(SplitWholeFrame(EncodeResponse(*r))->payload);
        Check(again && again->text == r->text && again->files_read == r->files_read);
    }
    if (const auto f = DecodeFailure(fields)) {
        const auto again = DecodeFailure(
            SplitWholeFrame(EncodeFailure(f->reason, f->detail, f->component))->payload);
        Check(again && again->detail == f->detail && again->component == f->component);
    }
    if (const auto h = DecodeHello(fields)) {
        const auto again = DecodeHello(SplitWholeFrame(EncodeHello(*h))->payload);
        Check(again && again->protocol == h->protocol && again->producer == h->producer);
    }
    if (const auto path = DecodeNeedFile(fields))
        Check(DecodeNeedFile(SplitWholeFrame(EncodeNeedFile(*path))->payload) == path);
    if (const auto f = DecodeFile(fields)) {
        Check(!f->with_content || ContentHash(f->content) == f->hash);
        const auto again = DecodeFile(SplitWholeFrame(EncodeFile(*f))->payload);
        Check(again && again->path == f->path && again->content == f->content);
    }
    return 0;
}
