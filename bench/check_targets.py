#!/usr/bin/env python3
"""Checks Kiln's speed targets against a Google Benchmark JSON report.

Usage: check_targets.py report.json
Each target is a benchmark name and the most real time (ms) one iteration may take. Exits 1 when
a target is missed or its benchmark is absent, printing every measured value either way.
"""
import json
import sys

# name -> (limit in ms, what the limit stands for)
TARGETS = {
    "BM_ParseAndCheckStress1MB": (1000.0, "1 MB deeply nested .shader parses and checks in < 1 s"),
}

UNIT_TO_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}


def main() -> int:
    with open(sys.argv[1], encoding="utf-8") as f:
        report = json.load(f)
    results = {b["name"]: b for b in report["benchmarks"] if b.get("run_type") != "aggregate"}
    failed = 0
    for name, (limit_ms, meaning) in TARGETS.items():
        bench = results.get(name)
        if bench is None or bench.get("error_occurred"):
            print(f"FAIL {name}: missing or errored ({meaning})")
            failed += 1
            continue
        ms = bench["real_time"] * UNIT_TO_MS[bench["time_unit"]]
        ok = ms <= limit_ms
        failed += 0 if ok else 1
        print(f"{'ok  ' if ok else 'FAIL'} {name}: {ms:.1f} ms (target <= {limit_ms:.0f} ms: {meaning})")
    print(f"bench: {len(TARGETS) - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
