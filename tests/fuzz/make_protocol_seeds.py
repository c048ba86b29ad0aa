#!/usr/bin/env python3
"""Writes the seeds of the worker-protocol fuzz target (corpus/worker_protocol beside this script):
one payload of each frame type, as worker/protocol.h lays them out (u32 frame type, then fields of
u8 tag, u32 size, bytes; tags as numbered in protocol.cpp)."""
import os
import struct

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "worker_protocol")


def field(tag, data):
    return bytes([tag]) + struct.pack("<I", len(data)) + data


def frame(kind, *fields):
    return struct.pack("<I", kind) + b"".join(fields)


SEEDS = {
    "request": frame(0x4b525131, field(1, b"\x01"), field(2, b"\x01"), field(3, b"dir/a.shader"),
                     field(4, b"#include \"x.cginc\"\nfloat4 frag() : SV_Target { return 1; }"),
                     field(5, b"frag"), field(6, b"inc"), field(7, b"/t"), field(28, b"202230"),
                     field(11, struct.pack("<5I", 0x07230203, 0x10300, 7, 42, 0))),
    "response": frame(0x4b525331, field(12, b"\x01"), field(14, b"\x02"), field(15, b"float4 f();"),
                      field(18, b"dir/x.cginc"), field(22, b"frag")),
    "failure": frame(0x4b524631, field(19, b"memory"), field(20, b"an allocation failed"),
                     field(35, b"\x02")),
    "hello": frame(0x4b524831, field(29, struct.pack("<I", 2)), field(30, b"kiln 0.2.0")),
    "need_file": frame(0x4b524e31, field(31, b"/client/Assets/x.cginc")),
    # XXH3-128 of "float4 x;" is not computed here: the decoder refuses the mismatch, a path the
    # fuzzer must reach too; the answer without content names a hash only.
    "file_bad_hash": frame(0x4b524331, field(31, b"/client/x.cginc"), field(32, b"\x01"),
                           field(33, b"0" * 32), field(34, b"float4 x;")),
    "file_known": frame(0x4b524331, field(31, b"/client/x.cginc"), field(32, b"\x01"),
                        field(33, b"0123456789abcdef0123456789abcdef")),
    "file_absent": frame(0x4b524331, field(31, b"/client/none.cginc"), field(32, b"\x00")),
}

os.makedirs(OUT, exist_ok=True)
for name, data in SEEDS.items():
    with open(os.path.join(OUT, name + ".bin"), "wb") as f:
        f.write(data)
