#!/usr/bin/env python3
"""Kiln's tools reach the runtime's internals through one header (issue 40).

kiln_tools (tools/src) and the CLI (tools/cli, tools/kiln*) link the runtime like an engine does,
through its public headers (runtime/include). What the `kiln test` and `kiln stability` harnesses
need beyond that is declared in runtime/src/render/tool_access.h, the one private header of the
runtime they may include. This test fails on any other include of a runtime/src header from
tools/, and on a `Renderer::State` or `internal_state()` there (the state is the runtime's).

Usage: layering_test.py SOURCE_DIR
"""
import os
import re
import sys

ALLOWED = {"render/tool_access.h"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
STATE = re.compile(r"\bRenderer::State\b|\binternal_state\s*\(")


def private_headers(source):
    """Every header under runtime/src, as the runtime's own sources include it."""
    out = set()
    base = os.path.join(source, "runtime", "src")
    for root, _, files in os.walk(base):
        for name in files:
            if name.endswith(".h"):
                out.add(os.path.relpath(os.path.join(root, name), base))
    return out


def main():
    source = sys.argv[1]
    private = private_headers(source)
    assert "render/renderer_state.h" in private, "runtime/src moved: update this test"
    failures, checked = [], 0
    for root, _, files in os.walk(os.path.join(source, "tools")):
        for name in sorted(files):
            if not name.endswith((".h", ".cpp")):
                continue
            path = os.path.join(root, name)
            rel = os.path.relpath(path, source)
            with open(path, encoding="utf-8") as f:
                text = f.read()
            checked += 1
            for header in INCLUDE.findall(text):
                if header in private and header not in ALLOWED:
                    failures.append(f"{rel}: includes the runtime's private {header}")
            for line_no, line in enumerate(text.splitlines(), 1):
                if STATE.search(line) and not line.lstrip().startswith("//"):
                    failures.append(f"{rel}:{line_no}: reaches Renderer::State")
    for f in failures:
        print("FAIL:", f)
    print(f"{checked} files of tools/, {len(failures)} reaching past render/tool_access.h")
    return 1 if failures or checked < 20 else 0


if __name__ == "__main__":
    sys.exit(main())
