#!/usr/bin/env python3
"""The hostile-input corpus (make_corpus.py writes it).

Every case under cases/ must fail with exit status 2 and exactly one line on stderr
that contains the case's `expect` text and names its input file (`named` where the
case has several files; cases whose fault is an option, option_*, name the option
instead), within 20 s; its output file must not be created, nor overwritten when it
exists. Every case under accepted/ (CRLF, BOM) must succeed and write its output.

Usage: run_corpus.py STOCKBRIDGE_PROGRAM

One process runs the program for every case (the only process started per run), so
the corpus costs the program's own time, not a shell's.
"""
import os
import shlex
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
TIMEOUT_S = 20


def read(path):
    with open(path, encoding="utf-8", errors="replace") as handle:
        return handle.read()


def case_files(case_dir):
    return sorted(n for n in os.listdir(case_dir) if os.path.isfile(os.path.join(case_dir, n)))


def input_named(case_dir):
    """The input the error must name: `named`, or the case's one file beside args and expect."""
    named = os.path.join(case_dir, "named")
    if os.path.isfile(named):
        return read(named).strip()
    inputs = [n for n in case_files(case_dir) if n not in ("args", "expect")]
    return inputs[0] if inputs else ""


def output_of(args):
    """The value of -o, or "" when the case writes none."""
    return next((args[i + 1] for i in range(len(args) - 1) if args[i] == "-o"), "")


def fresh_run_dir(work, case_dir):
    run = os.path.join(work, "run")
    shutil.rmtree(run, ignore_errors=True)
    os.mkdir(run)
    for name in case_files(case_dir):
        shutil.copy(os.path.join(case_dir, name), run)
    return run


def run_program(program, args, cwd, timeout=None):
    return subprocess.run([program, *args], cwd=cwd, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                          stderr=subprocess.PIPE, text=True, errors="replace", timeout=timeout)


def bad_case_failure(program, work, case_dir):
    """Why the bad case fails the corpus's rules, or None."""
    name = os.path.basename(case_dir)
    args = shlex.split(read(os.path.join(case_dir, "args")))
    expect = read(os.path.join(case_dir, "expect")).rstrip("\n")
    named = input_named(case_dir)
    output = output_of(args)
    for precious in (False, True):
        run = fresh_run_dir(work, case_dir)
        target = os.path.join(run, output) if output and output != "." else ""
        # (an output into a missing folder cannot exist beforehand)
        kept = precious and target and os.path.isdir(os.path.dirname(target))
        if kept:
            with open(target, "w", encoding="utf-8") as handle:
                handle.write("precious\n")
        try:
            result = run_program(program, args, run, TIMEOUT_S)
        except subprocess.TimeoutExpired:
            return f"still running after {TIMEOUT_S} s"
        stderr = result.stderr
        if result.returncode != 2:
            return f"exit status {result.returncode}, expected 2: {stderr}"
        lines = stderr.count("\n")
        if lines != 1:
            return f"{lines} lines on stderr, expected 1"
        if expect not in stderr:
            return f"stderr lacks '{expect}': {stderr}"
        if named and not name.startswith("option_") and named not in stderr:  # a bad option need not name the file
            return f"stderr does not name {named}: {stderr}"
        if target:
            if kept and read(target) != "precious\n":
                return f"overwrote {output}"
            if not kept and os.path.exists(target):
                return f"created {output}"
    return None


def accepted_case_failure(program, work, case_dir):
    args = shlex.split(read(os.path.join(case_dir, "args")))
    run = fresh_run_dir(work, case_dir)
    result = run_program(program, args, run)
    written = os.path.join(run, output_of(args))
    if result.returncode == 0 and os.path.isfile(written) and os.path.getsize(written) > 0:
        return None
    return f"should be accepted: {result.stderr}"


def cases(kind):
    folder = os.path.join(HERE, kind)
    return [os.path.join(folder, n) for n in sorted(os.listdir(folder)) if os.path.isdir(os.path.join(folder, n))]


def main(program):
    passed = failed = 0
    with tempfile.TemporaryDirectory() as work:
        for check, kind in ((bad_case_failure, "cases"), (accepted_case_failure, "accepted")):
            for case_dir in cases(kind):
                failure = check(program, work, case_dir)
                if failure is None:
                    passed += 1
                else:
                    failed += 1
                    print(f"FAIL {os.path.basename(case_dir)}: {failure}")
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: run_corpus.py STOCKBRIDGE_PROGRAM")
    sys.exit(main(os.path.abspath(sys.argv[1])))
