#!/usr/bin/env bash
# One libFuzzer target as a test: first every past finding (regressions/<name>/,
# each must now pass), then a fixed-seed run of SECONDS from the checked-in seeds
# (seeds/<name>/), with toml.dict for the file readers and csv.dict for the CSV readers.
# New corpus entries and any crashing input go to the build directory
# (fuzz-work/<name>/), never to the source tree. Any crash, leak, timeout,
# out-of-memory or sanitizer report fails the test and names the saved input.
# Usage: run_fuzzer.sh PROGRAM NAME SECONDS
set -euo pipefail
program="$1"
name="$2"
seconds="$3"
here="$(cd "$(dirname "$0")" && pwd)"
work="$PWD/fuzz-work/$name"
rm -rf "$work"
mkdir -p "$work/corpus" "$work/artifacts"

options=(-seed=1 -timeout=20 -rss_limit_mb=2048 -max_len=4096 "-artifact_prefix=$work/artifacts/")
case "$name" in
  *_file) options+=("-dict=$here/toml.dict") ;;
  csv_reader|measured_impedance|spans_csv) options+=("-dict=$here/csv.dict") ;;
esac

if compgen -G "$here/regressions/$name/*" > /dev/null; then
  echo "== $name: past findings"
  "$program" "${options[@]}" "$here/regressions/$name"/*
fi

echo "== $name: $seconds s from seed 1"
seeds=()
[ -d "$here/seeds/$name" ] && seeds=("$here/seeds/$name")
set +e
"$program" "${options[@]}" -max_total_time="$seconds" -print_final_stats=1 "$work/corpus" "${seeds[@]}" > "$work/log" 2>&1
status=$?
set -e
grep -vE '^#[0-9]+[[:space:]]+(NEW|REDUCE|pulse)|NEW_FUNC' "$work/log" || true
if [ "$status" -ne 0 ] || compgen -G "$work/artifacts/*" > /dev/null; then
  echo "FAIL $name: exit status $status; inputs kept in $work/artifacts:"
  ls -l "$work/artifacts"
  exit 1
fi
