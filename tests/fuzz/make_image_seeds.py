#!/usr/bin/env python3
"""Writes the seed inputs of the image-reader fuzz target (kiln_fuzz_image, issue 37).

Usage: make_image_seeds.py  (writes into corpus/image beside this script)
Small images in every format Kiln reads, written here byte by byte (PNG, BMP, TGA raw and
run-length, GIF, Radiance flat and run-length) or by stb_image_write (a JPEG; libstb-dev), and
the damaged shapes the readers must refuse: the truncated run-length Radiance file that hung
stb_image, truncated PNG/TGA/BMP/JPEG, and the formats Kiln refuses (PIC, PNM).
"""
import os
import struct
import subprocess
import tempfile
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "corpus", "image")


def pixel(x, y):
    return (x * 60 % 256, y * 60 % 256, 128, 255)


def png(w, h):
    rows = b"".join(b"\0" + b"".join(bytes(pixel(x, y)) for x in range(w)) for y in range(h))

    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def bmp(w, h):
    stride = (w * 3 + 3) & ~3
    rows = b""
    for y in reversed(range(h)):
        row = b"".join(bytes(pixel(x, y)[2::-1]) for x in range(w))
        rows += row + b"\0" * (stride - len(row))
    header = struct.pack("<IiiHHIIiiII", 40, w, h, 1, 24, 0, len(rows), 2835, 2835, 0, 0)
    return b"BM" + struct.pack("<IHHI", 14 + len(header) + len(rows), 0, 0, 54) + header + rows


def tga(w, h, rle):
    header = struct.pack("<BBBHHBHHHHBB", 0, 0, 10 if rle else 2, 0, 0, 0, 0, 0, w, h, 32, 8)
    data = b""
    for y in reversed(range(h)):
        for x in range(w):
            r, g, b, a = pixel(x, y)
            data += (b"\x00" if rle else b"") + bytes((b, g, r, a))
    return header + data


def gif():
    # 1x1, one colour: the smallest GIF89a.
    return (b"GIF89a\x01\x00\x01\x00\x80\x00\x00\xff\x80\x00\x00\x00\x00"
            b",\x00\x00\x00\x00\x01\x00\x01\x00\x00\x02\x02D\x01\x00;")


def rgbe(r, g, b):
    m = max(r, g, b)
    if m < 1e-32:
        return bytes((0, 0, 0, 0))
    e = 0
    while m >= 1.0:
        m /= 2.0
        e += 1
    while m < 0.5:
        m *= 2.0
        e -= 1
    f = 256.0 / (2.0 ** e)
    return bytes((int(r * f) & 255, int(g * f) & 255, int(b * f) & 255, e + 128))


def hdr(w, h, rle):
    out = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (h, w)
    for y in range(h):
        px = [rgbe(0.25 + x * 0.5, 1.0 + y, 4.0) for x in range(w)]
        if not rle:
            out += b"".join(px)
            continue
        out += bytes((2, 2, w >> 8, w & 255))
        for k in range(4):
            comp = bytes(p[k] for p in px)
            # one run of the first byte, then the rest as literals
            out += bytes((128 + 1, comp[0]))
            rest = comp[1:]
            while rest:
                n = min(len(rest), 128)
                out += bytes((n,)) + rest[:n]
                rest = rest[n:]
    return out


STB_JPEG = r"""
#include <stb/stb_image_write.h>
#include <stdio.h>
static void put(void* f, void* d, int n) { fwrite(d, 1, n, (FILE*)f); }
int main(void) {
    unsigned char px[%(w)d * %(h)d * 3];
    for (int y = 0; y < %(h)d; ++y)
        for (int x = 0; x < %(w)d; ++x) {
            unsigned char* p = px + (y * %(w)d + x) * 3;
            p[0] = x * 30; p[1] = y * 30; p[2] = 128;
        }
    return !stbi_write_jpg_to_func(put, stdout, %(w)d, %(h)d, 3, px, 90);
}
"""


def jpeg_from_stb(w, h):
    # A baseline JPEG from stb_image_write (libstb-dev, which Kiln builds with).
    with tempfile.TemporaryDirectory() as tmp:
        src, exe = os.path.join(tmp, "j.c"), os.path.join(tmp, "j")
        with open(src, "w") as f:
            f.write(STB_JPEG % {"w": w, "h": h})
        subprocess.run(["cc", src, "-o", exe, "-lstb"], check=True)
        return subprocess.run([exe], check=True, capture_output=True).stdout


def main():
    os.makedirs(OUT, exist_ok=True)
    seeds = {
        "png_3x2.png": png(3, 2),
        "bmp_3x2.bmp": bmp(3, 2),
        "tga_3x2.tga": tga(3, 2, False),
        "tga_rle_3x2.tga": tga(3, 2, True),
        "gif_1x1.gif": gif(),
        "hdr_flat_4x2.hdr": hdr(4, 2, False),
        "hdr_rle_9x3.hdr": hdr(9, 3, True),
        # The hang of issue 37: one run-length scanline header, then the end of the file.
        "hdr_rle_truncated.hdr": b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 8\n\x02\x02\x00\x08",
        "hdr_rle_zero_count.hdr": b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 8\n"
                                  b"\x02\x02\x00\x08" + b"\x00" * 16,
        "png_truncated.png": png(3, 2)[:-20],
        "tga_truncated.tga": tga(3, 2, False)[:-5],
        "bmp_truncated.bmp": bmp(3, 2)[:-4],
        "pic_refused.pic": b"\x53\x80\xF6\x34" + b"\0" * 84 + b"PICT" + b"\0" * 16,
        "pnm_refused.ppm": b"P6\n2 1\n255\n" + b"\x10\x20\x30\x40\x50\x60",
    }
    jpeg = jpeg_from_stb(8, 8)
    seeds["jpeg_8x8.jpg"] = jpeg
    seeds["jpeg_truncated.jpg"] = jpeg[: len(jpeg) * 2 // 3]
    for name, data in seeds.items():
        with open(os.path.join(OUT, name), "wb") as f:
            f.write(data)


if __name__ == "__main__":
    main()
