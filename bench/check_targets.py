#!/usr/bin/env python3
"""Checks Kiln's speed targets against a Google Benchmark JSON report.

Usage: check_targets.py report.json
Two kinds of target:
- a benchmark name and the most real time (ms) one iteration may take;
- a ratio: the real time of one benchmark over another's at most some factor (the cost of worker
  isolation against in-process compilation, issue 13). Benchmarks run with repetitions use their
  fastest repetition, which is the least disturbed by whatever else the machine runs.
Exits 1 when a target is missed or its benchmark is absent, printing every measured value either way.
"""
import json
import sys

# name -> (limit in ms, what the limit stands for)
TARGETS = {
    "BM_ParseAndCheckStress1MB": (1000.0, "1 MB deeply nested .shader parses and checks in < 1 s"),
}

# (numerator, denominator) -> (largest ratio, what it stands for)
RATIOS = {
    ("BM_CompileShippedMaterials/workers:1", "BM_CompileShippedMaterials/workers:0"):
        (1.10, "the shipped materials compile in kiln-worker processes within 10% of in-process"),
    ("BM_Compile1000Variants/workers:1", "BM_Compile1000Variants/workers:0"):
        (1.10, "a 1000-variant shader compiles in kiln-worker processes within 10% of in-process"),
}

UNIT_TO_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}


def fastest(report):
    """Benchmark name (without the /iterations:..., /repeats:... suffixes) -> fastest ms."""
    out = {}
    for b in report["benchmarks"]:
        if b.get("run_type") == "aggregate" or b.get("error_occurred"):
            continue
        name = "/".join(p for p in b["name"].split("/")
                        if not p.startswith(("iterations:", "repeats:", "real_time")))
        ms = b["real_time"] * UNIT_TO_MS[b["time_unit"]]
        out[name] = min(ms, out.get(name, ms))
    return out


def main() -> int:
    with open(sys.argv[1], encoding="utf-8") as f:
        report = json.load(f)
    times = fastest(report)
    failed = 0
    for name, (limit_ms, meaning) in TARGETS.items():
        if name not in times:
            print(f"FAIL {name}: missing or errored ({meaning})")
            failed += 1
            continue
        ms = times[name]
        ok = ms <= limit_ms
        failed += 0 if ok else 1
        print(f"{'ok  ' if ok else 'FAIL'} {name}: {ms:.1f} ms (target <= {limit_ms:.0f} ms: {meaning})")
    for (num, den), (limit, meaning) in RATIOS.items():
        if num not in times or den not in times:
            print(f"FAIL {num} / {den}: missing or errored ({meaning})")
            failed += 1
            continue
        ratio = times[num] / times[den]
        ok = ratio <= limit
        failed += 0 if ok else 1
        print(f"{'ok  ' if ok else 'FAIL'} {num} / {den}: {times[num]:.0f} / {times[den]:.0f} ms "
              f"= {ratio:.3f} (target <= {limit:.2f}: {meaning})")
    total = len(TARGETS) + len(RATIOS)
    print(f"bench: {total - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
