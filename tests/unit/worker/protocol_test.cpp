// The worker protocol: what one side encodes the other decodes, and nothing a broken worker can
// send (a truncated frame, a field running past the end, an oversized length) is read past its end.
#include <gtest/gtest.h>

#include <algorithm>

#include "worker/protocol.h"

namespace kiln::worker {
namespace {

// A whole frame's payload: what follows its length.
std::string_view Payload(const std::string& frame) {
    EXPECT_GE(frame.size(), 4u);
    uint32_t n = 0;
    for (int i = 0; i < 4; ++i)
        n |= uint32_t(uint8_t(frame[size_t(i)])) << (8 * i);
    EXPECT_EQ(n, frame.size() - 4);
    return std::string_view(frame).substr(4);
}

Request SampleRequest() {
    Request r;
    r.kind = RequestKind::kCompile;
    r.stage = pack::Stage::kFragment;
    r.name = "dir/a.shader";
    r.source = std::string("float4 frag() : SV_Target { return 1; }\0tail", 44);
    r.entry = "frag";
    r.second_entry = "vert";
    r.include_dirs = {"inc1", "inc2"};
    r.templates_dir = "/t";
    r.unity_version = 201840;
    r.debug_info = true;
    r.opt_level = 2;
    r.optimize = false;
    r.half_arithmetic = true;
    r.keep_declarations = true;
    r.words = {0x07230203, 0x00010300, 7, 42, 0};
    return r;
}

TEST(WorkerProtocol, RequestsRoundTrip) {
    const Request r = SampleRequest();
    const std::string bytes = EncodeRequest(r);
    const auto frame = SplitFrame(Payload(bytes));
    ASSERT_TRUE(frame);
    EXPECT_EQ(frame->type, FrameType::kRequest);
    const auto back = DecodeRequest(frame->payload);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->kind, r.kind);
    EXPECT_EQ(back->stage, r.stage);
    EXPECT_EQ(back->name, r.name);
    EXPECT_EQ(back->source, r.source);  // NUL bytes included
    EXPECT_EQ(back->entry, r.entry);
    EXPECT_EQ(back->second_entry, r.second_entry);
    EXPECT_EQ(back->include_dirs, r.include_dirs);
    EXPECT_EQ(back->templates_dir, r.templates_dir);
    EXPECT_EQ(back->unity_version, r.unity_version);
    EXPECT_EQ(back->debug_info, r.debug_info);
    EXPECT_EQ(back->opt_level, r.opt_level);
    EXPECT_EQ(back->optimize, r.optimize);
    EXPECT_EQ(back->half_arithmetic, r.half_arithmetic);
    EXPECT_EQ(back->keep_declarations, r.keep_declarations);
    EXPECT_EQ(back->words, r.words);
}

TEST(WorkerProtocol, ResponsesRoundTrip) {
    Response r;
    r.ok = true;
    r.entry_missing = true;
    r.failed_in = Component::kSpirvVal;
    r.text = "text";
    r.info_log = "ERROR: a.shader:3: 'x' : undeclared identifier\n";
    r.messages = "bad";
    r.words = {1, 2, 3};
    r.files_read = {"a.cginc", "b.cginc"};
    r.second_ok = true;
    r.second_text = "second";
    r.second_functions = {"vert", "frag"};
    const std::string bytes = EncodeResponse(r);
    const auto frame = SplitFrame(Payload(bytes));
    ASSERT_TRUE(frame);
    EXPECT_EQ(frame->type, FrameType::kResponse);
    const auto back = DecodeResponse(frame->payload);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->ok, r.ok);
    EXPECT_EQ(back->entry_missing, r.entry_missing);
    EXPECT_EQ(back->failed_in, r.failed_in);
    EXPECT_EQ(back->text, r.text);
    EXPECT_EQ(back->info_log, r.info_log);
    EXPECT_EQ(back->messages, r.messages);
    EXPECT_EQ(back->words, r.words);
    EXPECT_EQ(back->files_read, r.files_read);
    EXPECT_EQ(back->second_ok, r.second_ok);
    EXPECT_EQ(back->second_text, r.second_text);
    EXPECT_EQ(back->second_functions, r.second_functions);

    const std::string failure_bytes = EncodeFailure("memory", "an allocation failed");
    const auto failure = SplitFrame(Payload(failure_bytes));
    ASSERT_TRUE(failure && failure->type == FrameType::kFailure);
    ASSERT_TRUE(DecodeFailure(failure->payload));
    EXPECT_EQ(DecodeFailure(failure->payload)->reason, "memory");
}

// A strict prefix of a request's fields decodes only when it ends exactly between two fields
// (a shorter request); every other prefix ends inside a field and must be rejected, never read
// past.
TEST(WorkerProtocol, EveryTruncatedPrefixIsRejectedUnlessItEndsBetweenFields) {
    const std::string bytes = EncodeRequest(SampleRequest());
    const auto full = SplitFrame(Payload(bytes));
    ASSERT_TRUE(full);
    size_t accepted = 0;
    for (size_t n = 0; n < full->payload.size(); ++n)
        accepted += DecodeRequest(full->payload.substr(0, n)) ? 1 : 0;
    // Fields: kind, stage, name, source, entry, second entry, 2 include dirs, templates, Unity
    // version, debug, opt level, optimize, half arithmetic, keep declarations, words: 16
    // boundaries before the end, the empty prefix included.
    EXPECT_EQ(accepted, 16u);
    for (size_t n = 0; n < 4; ++n)
        EXPECT_FALSE(SplitFrame(Payload(bytes).substr(0, n)));
}

// The hello, the file exchange and the failure's component: round trips, and no prefix of a frame
// is read past its end or taken for the whole (a file's content is checked against its hash).
TEST(WorkerProtocol, HellosFilesAndFailuresRoundTripAndTheirPrefixesAreSafe) {
    const std::string hello = EncodeHello({kProtocolVersion, "kiln 9.9.9; glslang 1"});
    auto h = SplitFrame(Payload(hello));
    ASSERT_TRUE(h && h->type == FrameType::kHello);
    ASSERT_TRUE(DecodeHello(h->payload));
    EXPECT_EQ(DecodeHello(h->payload)->protocol, kProtocolVersion);
    EXPECT_EQ(DecodeHello(h->payload)->producer, "kiln 9.9.9; glslang 1");
    EXPECT_FALSE(DecodeHello(""));  // a hello names its protocol

    const std::string need = EncodeNeedFile("/client/Assets/Lib.cginc");
    auto n = SplitFrame(Payload(need));
    ASSERT_TRUE(n && n->type == FrameType::kNeedFile);
    EXPECT_EQ(DecodeNeedFile(n->payload), "/client/Assets/Lib.cginc");

    FileAnswer a;
    a.path = "/client/Assets/Lib.cginc";
    a.found = true;
    a.content = std::string("float3 Lit();\0bytes", 19);
    a.hash = ContentHash(a.content);
    a.with_content = true;
    const std::string file = EncodeFile(a);
    auto f = SplitFrame(Payload(file));
    ASSERT_TRUE(f && f->type == FrameType::kFile);
    const auto back = DecodeFile(f->payload);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->content, a.content);
    EXPECT_EQ(back->hash, a.hash);
    EXPECT_EQ(a.hash.size(), 32u);
    EXPECT_NE(ContentHash("a"), ContentHash("b"));
    // Content that is not what its hash says, and content for a file not found, are refused.
    FileAnswer forged = a;
    forged.content += "x";
    EXPECT_FALSE(DecodeFile(SplitFrame(Payload(EncodeFile(forged)))->payload));
    FileAnswer absent;
    absent.path = "/client/none.cginc";
    EXPECT_TRUE(DecodeFile(SplitFrame(Payload(EncodeFile(absent)))->payload));
    EXPECT_FALSE(DecodeFile(SplitFrame(Payload(EncodeFile(absent)))->payload)->found);

    const std::string failure =
        EncodeFailure("memory", "an allocation failed", Component::kGlslang);
    EXPECT_EQ(DecodeFailure(SplitFrame(Payload(failure))->payload)->component, Component::kGlslang);

    // Every strict prefix: the file answer needs its path, and its hash and content whole.
    for (size_t k = 0; k < f->payload.size(); ++k) {
        const auto part = DecodeFile(f->payload.substr(0, k));
        EXPECT_TRUE(!part || !part->with_content) << k;
    }
    for (size_t k = 0; k < h->payload.size(); ++k) {
        const auto part = DecodeHello(h->payload.substr(0, k));
        EXPECT_TRUE(!part || part->producer.size() < 21) << k;
    }
    for (size_t k = 0; k < n->payload.size(); ++k)
        EXPECT_FALSE(DecodeNeedFile(n->payload.substr(0, k))) << k;
}

TEST(WorkerProtocol, BadValuesAndUnknownTagsAreHandled) {
    // kind 9 does not exist; stage 7 does not exist; a bool of 2; words not a multiple of 4.
    auto field = [](uint8_t tag, std::string bytes) {
        std::string f(1, char(tag));
        const uint32_t n = uint32_t(bytes.size());
        for (int i = 0; i < 4; ++i)
            f += char(n >> (8 * i));
        return f + bytes;
    };
    EXPECT_FALSE(DecodeRequest(field(1, std::string(1, '\x09'))));
    EXPECT_FALSE(DecodeRequest(field(2, std::string(1, '\x07'))));
    EXPECT_FALSE(DecodeRequest(field(8, std::string(1, '\x02'))));
    EXPECT_FALSE(DecodeRequest(field(11, "abc")));
    EXPECT_FALSE(DecodeResponse(field(14, std::string(1, '\x40'))));
    // A field of an unknown tag (a newer sender's) is skipped.
    const auto r = DecodeRequest(field(200, "future") + field(5, "frag"));
    ASSERT_TRUE(r);
    EXPECT_EQ(r->entry, "frag");
    // A size that runs past the end.
    std::string past = field(5, "frag");
    past[1] = '\x7f';
    EXPECT_FALSE(DecodeRequest(past));
}

// Feeds `bytes` to a reader in pieces of at most `step`; the payloads of the frames completed.
std::vector<std::string> Feed(FrameReader& reader, const std::string& bytes, size_t step) {
    std::vector<std::string> out;
    for (size_t at = 0; at < bytes.size() && !reader.bad();) {
        const std::span<char> room = reader.Room();
        const size_t n = std::min({room.size(), step, bytes.size() - at});
        std::copy_n(bytes.data() + at, n, room.data());
        at += n;
        if (reader.Advance(n))
            out.push_back(reader.Take());
    }
    return out;
}

TEST(WorkerProtocol, FramesArriveWholeWhateverThePiecesAndOversizedOnesAreRefused) {
    const std::string a = EncodeFailure("memory", "an allocation failed");
    const std::string b = EncodeResponse(Response{});
    for (size_t step : {size_t(1), size_t(3), size_t(7), size_t(1000)}) {
        FrameReader reader;
        const auto frames = Feed(reader, a + b + a.substr(0, 5), step);
        ASSERT_EQ(frames.size(), 2u) << step;
        EXPECT_EQ(frames[0], Payload(a));
        EXPECT_EQ(frames[1], Payload(b));
        EXPECT_FALSE(reader.bad());
    }
    FrameReader reader;
    EXPECT_TRUE(Feed(reader, std::string("\xff\xff\xff\x7f", 4) + "x", 1).empty());
    EXPECT_TRUE(reader.bad());
}

}  // namespace
}  // namespace kiln::worker
