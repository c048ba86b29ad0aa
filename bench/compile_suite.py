#!/usr/bin/env python3
"""What users of `kiln compile` wait for (issue 19): cold, warm, one include edited, one keyword
added, -j 1 against every core, peak memory, the naive process chain and the floor, as ratios
measured in one run (the machine drifts by up to 40% between runs).

Usage: compile_suite.py --kiln BIN [--ci] [--shared DIR] [--json OUT] [--markdown OUT]
--ci: the shipped materials and the 256-variant generated shader only (a few minutes on 2 cores);
without it: the shipped materials, the generated shader at 8 / 64 / 512 / 1024 variants, Unity's
Standard (when DIR/unity-builtin-2022.3 exists) and a 10,240-variant shader for memory.
Exits 1 when an enforced target is missed (ratios and counts, never absolute times); the targets
that are reported but not enforced (missed, or too close to the machine's noise) are listed with
their cause in docs/performance.md.
"""
import argparse
import itertools
import json
import math
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gen_shader  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CORES = os.cpu_count() or 1
SHORT_S = 1.0  # a cold build shorter than this is measured REPEATS times (the median counts)
REPEATS = 5
NAIVE_REPEATS = 3


class Compile:
    """One `kiln compile` run: wall seconds and its --stats=json object."""

    def __init__(self, kiln, files, out, args, cache, jobs):
        cmd = [kiln, "compile", *files, "-o", out, "--stats=json", "-j", str(jobs), *args]
        cmd += ["--cache-dir", cache] if cache else ["--no-cache"]
        start = time.perf_counter()
        p = subprocess.run(cmd, capture_output=True, text=True)
        self.seconds = time.perf_counter() - start
        if p.returncode != 0:
            raise RuntimeError(f"{' '.join(cmd)} exited {p.returncode}:\n{p.stderr[-4000:]}")
        self.stats = json.loads(p.stdout[p.stdout.index("{"):])

    def __getitem__(self, key):
        return self.stats[key]


class Input:
    """A benchmark input: shader files copied into a work folder, compile arguments, edits."""

    def __init__(self, name, setup, args=(), edits=(), keyword=None, naive=None, j1=True,
                 watch=False, scene=None):
        self.name, self.setup, self.args, self.j1 = name, setup, list(args), j1
        self.watch = watch  # also time the first edit saved under `kiln watch`
        self.scene = scene  # ... and drawn by `kiln render --watch` of this scene
        self.edits = list(edits)  # (label, function(work) -> expected glslang compiles or None)
        self.keyword = keyword  # function(work) -> expected glslang compiles, or None
        self.naive = naive  # function(work, sample) -> list of naive chain command lists


def insert_lines(path, text="// bench: three lines inserted\n//\n//\n"):
    with open(path, encoding="utf-8") as f:
        body = f.read()
    with open(path, "w", encoding="utf-8") as f:
        f.write(text + body)


def materials_input():
    def setup(work):
        shutil.copytree(os.path.join(ROOT, "materials"), os.path.join(work, "materials"),
                        ignore=shutil.ignore_patterns("CMakeLists.txt", "internal"))
        return sorted(os.path.join(work, "materials", f)
                      for f in os.listdir(os.path.join(work, "materials")) if f.endswith(".shader"))

    def shift(work):
        insert_lines(os.path.join(work, "materials", "MaterialCommon.cginc"))
        return 0  # lines moved, code unchanged: nothing to compile

    return Input("shipped materials", setup, ["--all-features"],
                 [("MaterialCommon.cginc: 3 lines inserted", shift)], watch=True,
                 scene=os.path.join(ROOT, "scenes", "demo", "demo.gltf"))


def generated_input(sets, naive=True):
    total = math.prod(sets)
    if not naive:  # the memory input: cold and warm only
        return Input(f"generated {total} ({'x'.join(map(str, sets))})",
                     lambda work: [gen_shader.write(work, sets)], ["--max-variants", "20000"],
                     j1=False)

    def setup(work):
        return [gen_shader.write(work, sets)]

    def shift(work):
        insert_lines(os.path.join(work, "GenTerms.cginc"))
        return 0

    def edit_term(work):
        path = os.path.join(work, "GenTerms.cginc")
        with open(path, encoding="utf-8") as f:
            body = f.read()
        start = body.index("GenTerm_S1_K0")
        end = body.index("}", start)
        body = body[:start] + body[start:end].replace("return c *", "return 0.5 * c *") + body[end:]
        with open(path, "w", encoding="utf-8") as f:
            f.write(body)
        return total // sets[1]  # the fragment programs of the variants with S1_K0

    def add_keyword(work):
        path = os.path.join(work, f"Gen{total}.shader")
        last = len(sets) - 1
        new = gen_shader.keyword(last, sets[last])
        with open(path, encoding="utf-8") as f:
            body = f.read()
        old = gen_shader.keyword(last, sets[last] - 1)
        body = body.replace(f" {old}\n", f" {old} {new}\n", 1)
        with open(path, "w", encoding="utf-8") as f:
            f.write(body)
        return total // sets[last]  # one new fragment program per new variant; vertex unchanged

    def naive_chain(work, sample):
        return naive_commands(work, f"Gen{total}.shader", sets, sample)

    return Input(f"generated {total} ({'x'.join(map(str, sets))})", setup, [],
                 [("GenTerms.cginc: 3 lines inserted", shift),
                  ("GenTerms.cginc: GenTerm_S1_K0 edited", edit_term)],
                 add_keyword, naive_chain if naive else None)


def standard_input(shared):
    corpus = os.path.join(shared, "unity-builtin-2022.3", "Shaders")

    def setup(work):
        shutil.copytree(os.path.join(corpus, "CGIncludes"), os.path.join(work, "CGIncludes"))
        material = os.path.join(work, "normal.material")
        with open(material, "w", encoding="utf-8") as f:
            f.write('{"kiln_material": 1, "shader": "Standard", "keywords": ["_NORMALMAP"]}\n')
        return [os.path.join(corpus, "DefaultResourcesExtra", "Standard.shader")]

    def shift(work):
        insert_lines(os.path.join(work, "CGIncludes", "UnityStandardBRDF.cginc"))
        return 0

    return Input("Unity Standard, _NORMALMAP material", setup,
                 ["--materials", "{work}/normal.material", "-I", "{work}/CGIncludes",
                  "--strict-variants"],
                 [("UnityStandardBRDF.cginc: 3 lines inserted", shift)], j1=False, watch=True)


# The naive process chain: per variant and stage, glslangValidator on the assembled program (the
# macros Kiln's prelude defines for Vulkan, the keywords, the implicit CGPROGRAM includes), then
# spirv-opt -O and spirv-val, one process each, as a build script without Kiln would run them.
NAIVE_MACROS = ["SHADER_API_VULKAN=1", "SHADER_API_DESKTOP=1", "UNITY_VERSION=202230",
                "SHADER_TARGET=25", "UNITY_PBS_USE_BRDF1=1", "KILN=1", "UNITY_PASS_FORWARDBASE=1"]


def naive_commands(work, shader, sets, sample):
    with open(os.path.join(work, shader), encoding="utf-8") as f:
        text = f.read()
    body = text[text.index("CGPROGRAM") + len("CGPROGRAM"):text.index("ENDCG")]
    program = os.path.join(work, "naive_program.hlsl")
    with open(program, "w", encoding="utf-8") as f:
        f.write('#include "HLSLSupport.cginc"\n#include "UnityShaderVariables.cginc"\n'
                '#include "UnityShaderUtilities.cginc"\n' + body)
    combos = list(itertools.product(*[range(n) for n in sets]))
    rng = random.Random(19)
    chosen = rng.sample(combos, min(sample, len(combos)))
    out = []
    for i, combo in enumerate(chosen):
        for stage, entry, macro in (("vert", "vert", "SHADER_STAGE_VERTEX=1"),
                                    ("frag", "frag", "SHADER_STAGE_FRAGMENT=1")):
            spv = os.path.join(work, f"naive_{i}_{stage}")
            defines = [f"-D{m}" for m in NAIVE_MACROS + [macro]]
            defines += [f"-D{gen_shader.keyword(s, k)}=1" for s, k in enumerate(combo)]
            out.append([["glslangValidator", "-V", "-D", "--hlsl-dx9-compatible", "-S", stage,
                         "-e", entry, *defines, f"-I{os.path.join(ROOT, 'templates')}",
                         f"-I{work}", program, "-o", spv + ".spv"],
                        ["spirv-opt", "-O", spv + ".spv", "-o", spv + ".opt.spv"],
                        ["spirv-val", spv + ".opt.spv"]])
    return out


def run_naive(chains):
    """Runs the chains on every core; returns wall seconds and how many failed."""
    start = time.perf_counter()
    failed = 0
    running = []

    def reap(block):
        nonlocal failed
        for p in list(running):
            if block or p.poll() is not None:
                failed += p.wait() != 0
                running.remove(p)

    for chain in chains:
        while len(running) >= CORES:
            time.sleep(0.002)
            reap(False)
        script = " && ".join(" ".join(f"'{a}'" for a in cmd) for cmd in chain)
        running.append(subprocess.Popen(["sh", "-c", f"({script}) >/dev/null 2>&1"]))
    reap(True)
    return time.perf_counter() - start, failed


def read_until(p, needle, what):
    """The first line of p's output that holds `needle`."""
    for line in p.stdout:
        if needle in line:
            return line
    raise RuntimeError(f"{what}: no line with {needle!r} (exit {p.wait()})")


def watch_iteration(kiln, files, out, args, cache, edit, work, scene):
    """`kiln watch` on a warm cache (and `kiln render --watch` of `scene` on its pack, when
    given), then `edit` saved: seconds from the save to the line saying the new pack is written
    (and to the line saying the new frame is drawn, else None)."""
    cmd = [kiln, "watch", *files, "-o", out, "-j", str(CORES), *args, "--cache-dir", cache,
           "--builds", "2"]
    watch = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    render = None
    try:
        read_until(watch, "build 1:", "kiln watch")
        if scene:
            render = subprocess.Popen(
                [kiln, "render", scene, "--pack", out, "--width", "480", "--height", "270",
                 "-o", os.path.join(work, "watch.png"), "--watch"],
                stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
            read_until(render, "watch.png: 480x270", "kiln render --watch")
        start = time.perf_counter()
        edit(work)
        read_until(watch, "build 2:", "kiln watch")
        pack_s = time.perf_counter() - start
        image_s = None
        if render:
            read_until(render, "frame 2 drawn", "kiln render --watch")
            image_s = time.perf_counter() - start
        if watch.wait(timeout=600) != 0:
            raise RuntimeError("kiln watch failed")
        return pack_s, image_s
    finally:
        for p in (watch, render):
            if p and p.poll() is None:
                p.kill()
                p.wait()


def measure(kiln, inp, ci, naive_sample):
    work = tempfile.mkdtemp(prefix="kiln_bench_")
    try:
        files = inp.setup(work)
        args = [a.replace("{work}", work) for a in inp.args]
        out, cache = os.path.join(work, "out.kpack"), os.path.join(work, "cache")
        r = {"input": inp.name}
        start = time.perf_counter()
        subprocess.run([kiln, "--version"], capture_output=True, check=True)
        r["startup_s"] = time.perf_counter() - start
        cold = Compile(kiln, files, out, args, cache, CORES)
        if cold.seconds < SHORT_S:
            # A cold build under a second moves by 10-20% from run to run on a busy machine:
            # the median of five, each with an empty cache, and the warm build on the last.
            colds = [cold]
            for i in range(REPEATS - 1):
                shutil.rmtree(cache)
                colds.append(Compile(kiln, files, out, args, cache, CORES))
            cold = sorted(colds, key=lambda c: c.seconds)[len(colds) // 2]
            r["cold_runs_s"] = [c.seconds for c in colds]
        warm = Compile(kiln, files, out, args, cache, CORES)
        r.update(variants=cold["variants"], stage_programs=cold["stage_programs"],
                 unique_programs=cold["unique_programs"], cold_s=cold.seconds,
                 cold_ms=cold["ms"], warm_s=warm.seconds, warm_ms=warm["ms"],
                 warm_compiles=warm["glslang_compiles"], warm_direct=warm["direct_hits"],
                 peak_kib=cold["peak_rss_kib"], peak_worker_kib=cold["peak_worker_rss_kib"])
        ms, work_ms = cold["ms"], cold["work_ms"]
        # The floor: what Kiln would cost if only the unique modules' front end, optimizer and
        # validation ran (the cold run's compile work spread over every core, and its finish
        # phase), plus start-up. Kiln / floor measures everything else: loading, expansion,
        # preprocessing. A program compiles as soon as it is preprocessed, so the compile work
        # is read from the work counters (--stats work_ms), not from a phase's wall time.
        r["cold_work_ms"] = work_ms
        r["floor_s"] = (work_ms["compile"] / CORES + ms["finish"]) / 1000 + r["startup_s"]
        # The wall-clock share of preprocessing: its work spread over every core, of the total.
        r["preprocess_share"] = work_ms["preprocess"] / CORES / ms["total"]
        if inp.j1 and not ci:
            one = Compile(kiln, files, out + "1", args, None, 1)
            r["j1_s"] = one.seconds
        r["edits"] = []
        for label, edit in inp.edits:
            expected = edit(work)
            e = Compile(kiln, files, out, args, cache, CORES)
            r["edits"].append({"edit": label, "seconds": e.seconds,
                               "compiles": e["glslang_compiles"], "expected": expected})
        if inp.watch and inp.edits:
            label, edit = inp.edits[0]
            seconds, image_s = watch_iteration(kiln, files, out, args, cache, edit, work,
                                               inp.scene)
            r["watch"] = {"edit": label, "seconds": seconds, "ratio": seconds / cold.seconds,
                          "image_seconds": image_s}
        if inp.keyword:
            expected = inp.keyword(work)
            k = Compile(kiln, files, out, args, cache, CORES)
            r["keyword"] = {"seconds": k.seconds, "compiles": k["glslang_compiles"],
                            "expected": expected, "variants": k["variants"]}
        if inp.naive and naive_sample:
            chains = inp.naive(work, naive_sample)
            # The median of three runs of the sample, as noisy as a short cold build.
            runs = [run_naive(chains) for _ in range(NAIVE_REPEATS)]
            seconds = sorted(s for s, _ in runs)[len(runs) // 2]
            failed = max(f for _, f in runs)
            per_program = seconds / len(chains)
            r["naive"] = {"sampled_programs": len(chains), "failed": failed,
                          "seconds_per_program": per_program,
                          "estimated_s": per_program * cold["stage_programs"],
                          "runs_s": [s for s, _ in runs]}
        return r
    finally:
        shutil.rmtree(work, ignore_errors=True)


def check(results, ci):
    """Returns (lines, failures): each target with its value; failures count enforced misses."""
    lines, failures = [], 0

    def target(ok, enforced, text):
        nonlocal failures
        failures += enforced and not ok
        lines.append(f"{'ok  ' if ok else ('FAIL' if enforced else 'miss')} {text}"
                     f"{'' if enforced else ' (reported, not enforced)'}")

    for r in results:
        name = r["input"]
        ratio = r["warm_s"] / r["cold_s"]
        # Below 200 variants a process start, the parse and the pack's load are most of a warm
        # build: the target is for the inputs that take seconds.
        target(ratio < 0.05, r["variants"] >= 200,
               f"{name}: no-change rebuild {ratio:.3f} of cold (< 0.05)")
        target(r["warm_compiles"] == 0, True,
               f"{name}: no-change rebuild ran glslang {r['warm_compiles']} times (0)")
        for e in r["edits"]:
            target(e["compiles"] == e["expected"], True,
                   f"{name}: {e['edit']}: {e['compiles']} glslang compiles ({e['expected']})")
        if "keyword" in r:
            k = r["keyword"]
            target(k["compiles"] == k["expected"], True,
                   f"{name}: one keyword added: {k['compiles']} glslang compiles "
                   f"({k['expected']}, the new variants' fragment programs)")
        if "naive" in r:
            n = r["naive"]
            speedup = n["estimated_s"] / r["cold_s"]
            target(n["failed"] == 0, True, f"{name}: naive chain compiled its sample "
                   f"({n['failed']} of {n['sampled_programs']} failed)")
            target(speedup >= 15 or r["variants"] < 64, False,
                   f"{name}: {speedup:.1f}x the naive process chain (>= 15 from 64 variants)")
            # A guard against regressions. The ratio moves with the machine's cost of starting a
            # process (the naive chain starts three per program): 110 ms of CPU per naive program
            # where issue 19 measured 15x, 47 ms where the build of issue 42 measured 4.9x and
            # issue 43's 6-7x (docs/performance.md); the guard is below both machines' values.
            if r["variants"] >= 512:
                target(speedup >= 4, True, f"{name}: {speedup:.1f}x the naive process chain "
                       "(regression guard: >= 4 from 512 variants)")
        floor = r["cold_s"] / r["floor_s"]
        target(floor <= 1.3, False, f"{name}: Kiln / floor {floor:.2f} (<= 1.3, goal 1.15)")
        pre = r["preprocess_share"]
        target(pre < 0.25, False, f"{name}: preprocessing {pre:.0%} of cold (< 25%)")
        if r["variants"] >= 10000:
            per = (r["peak_kib"] + r["peak_worker_kib"]) / 1024 / r["variants"]
            target(per <= 0.05, True, f"{name}: peak memory {per:.4f} MB per variant (<= 0.05)")
        if "watch" in r:
            w = r["watch"]
            # Save -> new pack under kiln watch (issue 45): an include edit through the warm
            # cache, against a cold build (the same edit as a kiln compile run is in the table;
            # on Standard it preprocesses every program again: about 0.6 of cold).
            target(w["ratio"] < 1, True,
                   f"{name}: kiln watch, {w['edit']}: save -> new pack {w['seconds']:.2f} s, "
                   f"{w['ratio']:.3f} of cold (< 1)")
        if r["variants"] == 1024 and "generated" in name:
            target(r["cold_s"] < 4, False, f"{name}: cold {r['cold_s']:.1f} s (< 4 s on 2 cores)")
    return lines, failures


def markdown(results):
    out = ["| input | variants | stage / unique programs | cold s | preprocess % | warm s "
           "(ratio) | -j 1 s | floor s (Kiln/floor) | naive chain s (x) | peak MB kiln + worker |",
           "|---|---|---|---|---|---|---|---|---|---|"]
    for r in results:
        pre = r["preprocess_share"]
        j1 = f"{r['j1_s']:.2f}" if "j1_s" in r else "-"
        naive = (f"{r['naive']['estimated_s']:.1f} ({r['naive']['estimated_s'] / r['cold_s']:.1f}x)"
                 if "naive" in r else "-")
        out.append(f"| {r['input']} | {r['variants']} | {r['stage_programs']} / "
                   f"{r['unique_programs']} | {r['cold_s']:.2f} | {pre:.0%} | {r['warm_s']:.3f} "
                   f"({r['warm_s'] / r['cold_s']:.3f}) | "
                   f"{j1} | {r['floor_s']:.2f} "
                   f"({r['cold_s'] / r['floor_s']:.2f}) | {naive} | "
                   f"{r['peak_kib'] / 1024:.0f} + {r['peak_worker_kib'] / 1024:.0f} |")
    out += ["", "| input | change | seconds | glslang compiles (expected) |", "|---|---|---|---|"]
    for r in results:
        for e in r["edits"]:
            out.append(f"| {r['input']} | {e['edit']} | {e['seconds']:.2f} | {e['compiles']} "
                       f"({e['expected']}) |")
        if "watch" in r:
            w = r["watch"]
            out.append(f"| {r['input']} | kiln watch: {w['edit']}, save -> new pack | "
                       f"{w['seconds']:.2f} ({w['ratio']:.3f} of cold) | - |")
            if w.get("image_seconds") is not None:
                out.append(f"| {r['input']} | ... and kiln render --watch (demo scene, 480x270), "
                           f"save -> new image | {w['image_seconds']:.2f} | - |")
        if "keyword" in r:
            k = r["keyword"]
            out.append(f"| {r['input']} | one keyword added ({k['variants']} variants) | "
                       f"{k['seconds']:.2f} | {k['compiles']} ({k['expected']}) |")
    return "\n".join(out) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--kiln", required=True)
    ap.add_argument("--ci", action="store_true")
    ap.add_argument("--shared", default=os.path.join(ROOT, "..", "shared"))
    ap.add_argument("--json")
    ap.add_argument("--markdown")
    a = ap.parse_args()
    kiln = os.path.abspath(a.kiln)
    if a.ci:
        inputs = [(materials_input(), 0), (generated_input([4, 4, 4, 4]), 16)]
    else:
        inputs = [(materials_input(), 0)]
        inputs += [(generated_input(s), 32 if math.prod(s) < 1000 else 64) for s in ([2, 2, 2], [4, 4, 4], [8, 8, 8],
                                                     [4, 4, 4, 4, 4])]
        if os.path.isdir(os.path.join(a.shared, "unity-builtin-2022.3")):
            inputs.append((standard_input(a.shared), 0))
        else:
            print(f"{a.shared}/unity-builtin-2022.3 absent: Unity's Standard skipped")
        inputs.append((generated_input([4, 4, 4, 4, 4, 10], naive=False), 0))
    results = []
    for inp, sample in inputs:
        print(f"measuring {inp.name} ...", flush=True)
        results.append(measure(kiln, inp, a.ci, sample))
        if a.json:  # after each input, so that a long run that fails keeps what it measured
            with open(a.json, "w", encoding="utf-8") as f:
                json.dump({"cores": CORES, "results": results}, f, indent=1)
    table = markdown(results)
    print(f"\n{CORES} cores\n\n{table}")
    lines, failures = check(results, a.ci)
    print("\n".join(lines))
    print(f"compile suite: {failures} enforced target(s) missed")
    if a.json:
        with open(a.json, "w", encoding="utf-8") as f:
            json.dump({"cores": CORES, "results": results}, f, indent=1)
    if a.markdown:
        with open(a.markdown, "w", encoding="utf-8") as f:
            f.write(table)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
