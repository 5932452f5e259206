#!/usr/bin/env python3
"""Runs every command the README and the docs show, verbatim, as a new user would.

Usage: run_doc_commands.py SOURCE_DIR BUILD_DIR

The commands are the lines of the ```sh blocks of README.md, docs/*.md and
examples/README.md (```text blocks are synopses, with placeholders, and are not
run). They run in that order in one scratch folder laid out like a fresh clone
after the README's first command (the sources copied, `build` the build tree), so
a file one command writes is there for the next. Each must exit 0, or the status
its trailing comment names (`# exit 3`, maybe followed by why). The README's first command runs from its
first `build/stockbridge` on (the build before it is the suite's own); the blocks
in SKIPPED_BLOCKS are not run, for the reasons given there.
Prints one line per failing command and exits 1 if any failed.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

# The commands the suite itself is made of; the rest of the README's first command runs.
SETUP = "scripts/install-deps && cmake -S . -B build && cmake --build build -j2 && "
# Blocks not run, by their first command.
SKIPPED_BLOCKS = {
    "scripts/install-deps && scripts/test-all": "the test suite, which runs this",
    "cmake --preset sanitize && cmake --build --preset sanitize": "the hour of fuzzing in hardening.md needs the "
    "sanitizer build; the suite runs every fuzzer for 10 s (fuzz/run_fuzzer.sh)",
    "cd build && cpack -G DEB && apt-get install -y ./stockbridge_*.deb": "installs into the system; the "
    "suite packs the .deb and installs into temporary prefixes instead (tests/install)",
}


def documents(source):
    names = ["README.md"] + sorted(os.path.join("docs", n) for n in os.listdir(os.path.join(source, "docs"))
                                   if n.endswith(".md")) + [os.path.join("examples", "README.md")]
    return [n for n in names if os.path.exists(os.path.join(source, n))]


def sh_blocks(path):
    """(line, text) of each ```sh block."""
    text = open(path, encoding="utf-8").read()
    for match in re.finditer(r"^```sh\n(.*?)^```", text, re.S | re.M):
        yield text[:match.start()].count("\n") + 2, match.group(1)


def commands(block):
    """The block's commands: continuation lines joined, blank lines dropped."""
    joined = re.sub(r"\\\n\s*", " ", block)
    return [line for line in joined.splitlines() if line.strip()]


def expected_status(command):
    match = re.search(r"#\s*exit (\d+)\b", command)
    return int(match.group(1)) if match else 0


def script_for(block_commands, where):
    """One bash script per block (an export holds for the block's later lines)."""
    lines = ["cd \"$STOCKBRIDGE_DOC_ROOT\""]
    for command in block_commands:
        expect = expected_status(command)
        quoted = command.replace("'", "'\\''")
        lines.append(f"{command} 2> \"$STOCKBRIDGE_DOC_ROOT/.stderr\"\nstatus=$?\nif [ $status -ne {expect} ]; then "
                     f"echo \"{where}: exit $status, expected {expect}: '{quoted}': $(tail -n 1 \"$STOCKBRIDGE_DOC_ROOT/.stderr\")\"; "
                     "failed=1; fi")
    lines.append("exit ${failed:-0}")
    return "\n".join(lines)


def main():
    source, build = map(os.path.abspath, sys.argv[1:3])
    root = tempfile.mkdtemp(prefix="stockbridge-docs-")
    try:
        for name in ("README.md", "docs", "examples", "data", "scripts", "python"):
            copy = shutil.copytree if os.path.isdir(os.path.join(source, name)) else shutil.copy
            copy(os.path.join(source, name), os.path.join(root, name))
        os.symlink(build, os.path.join(root, "build"))
        env = dict(os.environ, STOCKBRIDGE_DOC_ROOT=root, MPLBACKEND="Agg")
        env.pop("PYTHONPATH", None)  # as in a new shell: the docs say where it comes from
        failures, ran = 0, 0
        for document in documents(source):
            for line, block in sh_blocks(os.path.join(source, document)):
                where = f"{document}:{line}"
                runnable = [c[len(SETUP):] if c.startswith(SETUP) else c for c in commands(block)]
                if runnable[0] in SKIPPED_BLOCKS:
                    continue
                ran += len(runnable)
                result = subprocess.run(["bash", "-c", script_for(runnable, where)], env=env, cwd=root,
                                        stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
                for failure in result.stdout.splitlines():
                    if failure.startswith(where):
                        print(failure)
                        failures += 1
        print(f"{ran} documented commands run, {failures} failed")
        return 1 if failures else 0
    finally:
        shutil.rmtree(root, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
