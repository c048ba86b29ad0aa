#include "image/stb_guards.h"

#include <algorithm>
#include <cstdint>

namespace kiln::runtime::image {
namespace {

uint8_t At(std::string_view b, size_t i) {
    return uint8_t(b[i]);
}

// The tables of a DHT segment as stb_image 2.27 reads them: class/id, 16 counts, as many symbols,
// for as long as the segment's length is above 0, so a last table may run past the segment (and
// bytes past the end of the file read as 0). Advances `at` to where stb_image goes on reading.
std::string CheckHuffmanTables(std::string_view b, size_t& at, long left) {
    while (left > 0) {
        size_t codes = 0;
        for (size_t i = 1; i <= 16 && at + i < b.size(); ++i)
            codes += At(b, at + i);
        if (codes > 256) {
            return "a JPEG Huffman table of " + std::to_string(codes) +
                   " codes (at most 256 are valid)";
        }
        at += 17 + codes;
        left -= long(17 + codes);
    }
    return "";
}

// The JPEG's marker segments, and the markers between its scans, in one pass.
std::string CheckJpeg(std::string_view b, size_t at, bool& progressive) {
    while (at + 4 <= b.size()) {
        if (At(b, at) != 0xFF) {
            // Entropy-coded data: up to the next marker (0xFF then neither 0 nor a restart).
            while (at + 1 < b.size() &&
                   !(At(b, at) == 0xFF && At(b, at + 1) != 0 &&
                     !(At(b, at + 1) >= 0xD0 && At(b, at + 1) <= 0xD7) && At(b, at + 1) != 0xFF))
                ++at;
            if (at + 4 > b.size())
                return "";
        }
        const uint8_t marker = At(b, at + 1);
        if (marker == 0xFF) {
            ++at;  // fill byte
            continue;
        }
        if (marker == 0xD9)
            return "";  // EOI
        if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD8)) {
            at += 2;  // no length
            continue;
        }
        const size_t length = size_t(At(b, at + 2)) << 8 | At(b, at + 3);
        if (length < 2)
            return "";
        progressive = progressive || marker == 0xC2;
        if (marker == 0xC4) {
            at += 4;
            if (std::string bad = CheckHuffmanTables(b, at, long(length) - 2); !bad.empty())
                return bad;
            continue;
        }
        at = std::min(b.size(), at + 2 + length);
    }
    return "";
}

// PNG chunks: a length past the end of the file is a truncated file, which stb_image would first
// allocate in full (an IDAT chunk declaring 2 GiB in a 100-byte file).
std::string CheckPng(std::string_view b) {
    for (size_t at = 8; at + 8 <= b.size();) {
        const uint64_t length = uint64_t(At(b, at)) << 24 | uint64_t(At(b, at + 1)) << 16 |
                                uint64_t(At(b, at + 2)) << 8 | At(b, at + 3);
        if (length > b.size() - at - 8) {
            return "the file is truncated: a PNG chunk of " + std::to_string(length) +
                   " bytes where " + std::to_string(b.size() - at - 8) + " are left";
        }
        if (b.substr(at + 4, 4) == "IEND")
            return "";
        at += 12 + length;  // length, type, data, CRC
    }
    return "";
}

}  // namespace

size_t JpegStart(std::string_view bytes) {
    // As stb_image finds the SOI marker: 0xFF, any number of fill bytes 0xFF, then 0xD8.
    if (bytes.empty() || At(bytes, 0) != 0xFF)
        return 0;
    size_t at = 1;
    while (at < bytes.size() && At(bytes, at) == 0xFF)
        ++at;
    return at < bytes.size() && At(bytes, at) == 0xD8 ? at + 1 : 0;
}

std::string StbHazard(std::string_view bytes) {
    bool progressive = false;
    if (const size_t jpeg = JpegStart(bytes); jpeg != 0)
        return CheckJpeg(bytes, jpeg, progressive);
    if (bytes.substr(0, 8) == std::string_view("\x89PNG\r\n\x1a\n", 8))
        return CheckPng(bytes);
    return "";
}

std::string TooShortFor(std::string_view bytes, uint64_t texels) {
    bool progressive = false;
    const size_t jpeg = JpegStart(bytes);
    if (jpeg != 0)
        (void)CheckJpeg(bytes, jpeg, progressive);
    // How many texels a byte can hold at most, with a factor of 2 to spare: baseline JPEG codes
    // every 8x8 block in at least 2 bits (a DC difference and an end of block); 1-bit PNG rows
    // through deflate at its 1,032:1 limit hold 8,256 (GIF's LZW, run-length TGA and PSD, BMP
    // fewer). Progressive JPEG codes runs of empty blocks in a few bits: no bound.
    const uint64_t per_byte = jpeg != 0 ? 2 * 256 : 2 * 8256;
    if (progressive || texels / per_byte <= bytes.size())
        return "";
    return "the file is truncated: " + std::to_string(bytes.size()) +
           " bytes cannot hold that many texels";
}

}  // namespace kiln::runtime::image
