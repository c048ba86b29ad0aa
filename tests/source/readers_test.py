#!/usr/bin/env python3
"""Every file Kiln reads goes through one bounded reader (issue 37).

base::ReadRegularFile (base/src/files.cpp) opens without blocking, takes regular files only,
bounds the size and remembers what it read for the output-safety guard. This test lists every
other way the libraries and tools could open a file (open, fopen, streams, mmap, stb_image's and
tinygltf's file loaders, OpenColorIO's CreateFromFile) and fails on any that is not in ALLOWED
with its reason, so a new reader cannot bypass the bounded one unnoticed.

Usage: readers_test.py SOURCE_DIR
"""
import os
import re
import sys

PATTERNS = {
    "open": re.compile(r"(?<![\w.>])(?:::)?open(?:at)?\s*\("),
    "fopen": re.compile(r"\bf(?:re)?open\s*\("),
    "stream": re.compile(r"\bstd::(?:i|o)?fstream\b|\bifstream\b"),
    "mmap": re.compile(r"\bmmap\s*\("),
    "stb_image file": re.compile(r"\bstbi_(?:load|loadf|load_16|is_hdr|info)\s*\("),
    "stb_image any": re.compile(r"\bstbi_(?:load|loadf|info)_from_(?:memory|callbacks)\s*\("),
    "tinygltf file": re.compile(r"\bLoad(?:ASCII|Binary)FromFile\s*\("),
    "OpenColorIO file": re.compile(r"\bCreateFromFile\s*\("),
}

# (file, pattern): why this one is allowed.
ALLOWED = {
    ("base/src/files.cpp", "open"):
        "the bounded reader itself, the atomic writer's temporary file and its directory fsync",
    ("runtime/src/pack/reader.cpp", "open"):
        "MappedFile::Map: O_NONBLOCK, fstat S_ISREG before mmap, noted for the input guard",
    ("runtime/src/pack/reader.cpp", "mmap"): "MappedFile::Map, of the checked descriptor",
    ("compiler/src/driver/module_store.cpp", "open"):
        "a shader's modules file: lstat and fstat S_ISREG, O_NOFOLLOW | O_NONBLOCK, size bounded "
        "by Cache::kMaxPackEntryBytes, every read inside the size (module_bundle.h); and the "
        "temporary file its new modules are written to",
    ("compiler/src/worker/pool.cpp", "fopen"): "/proc/PID/statm of a worker, for its memory",
    ("runtime/src/image/stb_decoder.cpp", "stb_image any"):
        "the image reader: bytes from ReadRegularFile through bounded callbacks (image.cpp)",
}

ROOTS = ["base", "compiler", "runtime", "tools"]


def main():
    source = sys.argv[1]
    seen, failures = set(), []
    for root in ROOTS:
        for folder, _, files in os.walk(os.path.join(source, root)):
            for name in sorted(files):
                if not name.endswith((".cpp", ".h")) or name.endswith(("_test.cpp", "_fuzz.cpp")):
                    continue
                path = os.path.join(folder, name)
                rel = os.path.relpath(path, source)
                with open(path, encoding="utf-8", errors="replace") as f:
                    for number, line in enumerate(f, 1):
                        code = line.split("//", 1)[0]
                        for kind, pattern in PATTERNS.items():
                            if not pattern.search(code):
                                continue
                            if (rel, kind) in ALLOWED:
                                seen.add((rel, kind))
                            else:
                                failures.append(f"{rel}:{number}: {kind}: {line.strip()}")
    for key in sorted(set(ALLOWED) - seen):
        failures.append(f"{key[0]}: no longer uses {key[1]}: remove it from ALLOWED")
    if failures:
        print("files read outside base::ReadRegularFile (read through it, or add the place to "
              "ALLOWED in tests/source/readers_test.py with the reason it is safe):")
        print("\n".join(failures))
        return 1
    print(f"ok: {len(seen)} allowed places, no other file reader")
    return 0


if __name__ == "__main__":
    sys.exit(main())
