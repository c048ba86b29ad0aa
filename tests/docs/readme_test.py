#!/usr/bin/env python3
"""README.md against the kiln it documents.

  readme_test.py usage BIN_DIR README      every option of each command's --help is in README's
                                           usage block, and every option there is in --help
  readme_test.py quickstart BIN_DIR README the quick start's commands, run as written (after the
                                           build step) in a scratch folder

The usage block lies between <!-- usage --> and <!-- /usage -->, the quick start between
<!-- quickstart --> and <!-- /quickstart -->. Exit 0 when README and kiln agree.
"""
import os
import re
import shlex
import subprocess
import sys
import tempfile

OPTION = re.compile(r"(?<![\w./-])(--?[A-Za-z][\w-]*)")
# Options every command has, or the CLI itself: not repeated in each command's line.
COMMON = {"-h", "--help"}


def block(readme, name):
    match = re.search(r"<!-- %s -->(.*?)<!-- /%s -->" % (name, name), readme, re.S)
    if not match:
        sys.exit("README.md has no <!-- %s --> block" % name)
    return match.group(1)


def readme_commands(usage):
    """{command: set of options} from the usage block: a line `    kiln CMD ...` starts one."""
    commands, current = {}, None
    for line in usage.splitlines():
        m = re.match(r"\s+kiln (\w+)", line)
        if m and not line.lstrip().startswith("kiln -"):
            current = m.group(1)
            commands.setdefault(current, set())
            line = line[m.end():]
        elif re.match(r"\s+kiln -", line):  # the CLI's own options: --color, -W...
            current = None
            continue
        if current is None:
            continue
        if "[kiln compile's options]" in line:  # kiln watch: every option of kiln compile
            commands[current] |= commands.get("compile", set())
            line = line.replace("[kiln compile's options]", "")
        if re.match(r"\s*[a-z(]", line) and not m:
            continue  # a line of description only
        # The description column (after two or more spaces past the options) is prose.
        options_part = re.split(r"\s{3,}(?=[a-z(])", line.strip(), maxsplit=1)[0]
        for opt in OPTION.findall(options_part):
            commands[current].add(opt)
    return commands


def help_options(bin_dir, command):
    out = subprocess.run([os.path.join(bin_dir, "kiln"), command, "--help"],
                         capture_output=True, text=True, timeout=60)
    if out.returncode != 0:
        sys.exit("kiln %s --help failed: %s" % (command, out.stderr))
    options = []  # each a set of spellings of one option ("-o,--output")
    for line in out.stdout.splitlines():
        # Options start at column 2; deeper lines continue a description.
        if not re.match(r"^  -", line):
            continue
        stripped = line.strip()
        # "-o,--output TEXT  desc", "-O0 | -O | -Os   desc", "--stats{text}  desc"
        first = re.split(r"\s{2,}", stripped, maxsplit=1)[0]
        if "|" in first and first.startswith("-O"):  # "-O0 | -O | -Os": three options
            options.extend({opt} for opt in OPTION.findall(first))
            continue
        # "--stats{text}": CLI11's default value of a flag that takes one.
        spellings = {re.sub(r"[{:=].*", "", o) for o in first.split(" ")[0].split(",")}
        if spellings & COMMON:
            continue
        options.append(spellings)
    return options


def check_usage(bin_dir, readme):
    commands = readme_commands(block(readme, "usage"))
    listed = subprocess.run([os.path.join(bin_dir, "kiln"), "--help"], capture_output=True,
                            text=True, timeout=60).stdout
    # CLI11 lists subcommands under "Subcommands:" as "  name   description".
    sub = listed.split("Subcommands:", 1)[-1]
    names = {m.group(1) for m in re.finditer(r"^\s{2}(\w+)\s", sub, re.M)} - {"version"}
    failures = []
    for name in sorted(names - set(commands)):
        failures.append("kiln %s is not in README's usage block" % name)
    for name in sorted(set(commands) - names):
        failures.append("README's usage block has kiln %s, which kiln does not" % name)
    for name in sorted(names & set(commands)):
        have = help_options(bin_dir, name)
        documented = commands[name]
        for spellings in have:
            if not spellings & documented:
                failures.append("kiln %s %s: in --help, not in README" %
                                (name, ",".join(sorted(spellings))))
        known = set().union(*have) if have else set()
        for opt in sorted(documented - known):
            failures.append("kiln %s %s: in README, not in --help" % (name, opt))
    for f in failures:
        print("FAIL:", f)
    print("%d commands, %d mismatches" % (len(names), len(failures)))
    return 1 if failures else 0


def check_quickstart(bin_dir, readme, source_dir):
    lines = [l.strip() for l in block(readme, "quickstart").splitlines()]
    lines = [l for l in lines if l and not l.startswith("```") and not l.startswith("#")]
    # The build step is what made BIN_DIR; PATH is set here instead of by the export line.
    commands = [l for l in lines if not l.startswith(("bash scripts/setup.sh", "cmake ",
                                                     "export PATH"))]
    if len(commands) < 4:
        sys.exit("the quick start has %d commands after the build" % len(commands))
    with tempfile.TemporaryDirectory(prefix="kiln-quickstart-") as work:
        for name in ("materials", "scenes"):
            os.symlink(os.path.join(source_dir, name), os.path.join(work, name))
        env = dict(os.environ, PATH=bin_dir + os.pathsep + os.environ["PATH"],
                   KILN_CACHE_DIR=os.path.join(work, "cache"))
        for command in commands:
            print("$", command, flush=True)
            # The comment after a command is for the reader.
            command = command.split("  #", 1)[0]
            run = subprocess.run(command, shell=True, cwd=work, env=env, timeout=600,
                                 capture_output=True, text=True)
            sys.stdout.write(run.stdout[-2000:])
            if run.returncode != 0:
                print(run.stderr[-4000:])
                print("FAIL: exit %d" % run.returncode)
                return 1
            words = shlex.split(command)
            for flag, path in zip(words, words[1:]):
                if flag == "-o" and not os.path.exists(os.path.join(work, path)):
                    print("FAIL: %s was not written" % path)
                    return 1
    print("quick start: %d commands ran" % len(commands))
    return 0


def main():
    mode, bin_dir, readme_path = sys.argv[1:4]
    bin_dir = os.path.abspath(bin_dir)
    with open(readme_path, encoding="utf-8") as f:
        readme = f.read()
    if mode == "usage":
        return check_usage(bin_dir, readme)
    return check_quickstart(bin_dir, readme, os.path.dirname(os.path.abspath(readme_path)))


if __name__ == "__main__":
    sys.exit(main())
