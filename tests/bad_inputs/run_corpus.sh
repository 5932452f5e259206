#!/usr/bin/env bash
# The hostile-input corpus (make_corpus.py writes it): every case under cases/ must
# fail with exit status 2 and exactly one line on stderr that contains the case's
# `expect` text and names its input file (`named` where the case has several files;
# cases whose fault is an option, option_*, name the option instead), within 20 s;
# its output file must not be created, nor overwritten when it exists. Every case
# under accepted/ (CRLF, BOM) must succeed.
# Usage: run_corpus.sh STOCKBRIDGE_PROGRAM
set -u
program="$1"
here="$(cd "$(dirname "$0")" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
passed=0
failed=0
fail() { echo "FAIL $1: $2"; failed=$((failed + 1)); }

for case_dir in "$here"/cases/*/; do
  name="$(basename "$case_dir")"
  args="$(cat "$case_dir/args")"
  expect="$(cat "$case_dir/expect")"
  if [ -f "$case_dir/named" ]; then  # an input with files beside it: the one the error is in
    input="$(cat "$case_dir/named")"
  else
    input="$(find "$case_dir" -maxdepth 1 -type f ! -name args ! -name expect -printf '%f\n' | head -1)"
  fi
  output="$(grep -oE -- '-o [^ ]+' <<< "$args" | cut -d' ' -f2)"
  ok=1
  for precious in no yes; do
    rm -rf "$work/run" && mkdir "$work/run" && cp "$case_dir"/* "$work/run/"
    # (an output into a missing folder cannot exist beforehand)
    [ -n "$output" ] && [ "$output" != "." ] && [ "$precious" = yes ] && [ -d "$(dirname "$work/run/$output")" ] &&
      echo precious > "$work/run/$output"
    (cd "$work/run" && eval "timeout 20 \"$program\" $args" > stdout.txt 2> stderr.txt < /dev/null)
    status=$?
    lines=$(wc -l < "$work/run/stderr.txt")
    [ "$status" -ne 124 ] || { fail "$name" "still running after 20 s"; ok=0; break; }
    [ "$status" -eq 2 ] || { fail "$name" "exit status $status, expected 2: $(cat "$work/run/stderr.txt")"; ok=0; break; }
    [ "$lines" -eq 1 ] || { fail "$name" "$lines lines on stderr, expected 1"; ok=0; break; }
    grep -qF -- "$expect" "$work/run/stderr.txt" || { fail "$name" "stderr lacks '$expect': $(cat "$work/run/stderr.txt")"; ok=0; break; }
    if [ -n "$input" ] && [[ "$name" != option_* ]]; then  # a bad option need not name the file
      grep -qF -- "$input" "$work/run/stderr.txt" || { fail "$name" "stderr does not name $input: $(cat "$work/run/stderr.txt")"; ok=0; break; }
    fi
    if [ -n "$output" ] && [ "$output" != "." ]; then
      if [ "$precious" = yes ] && [ -d "$(dirname "$work/run/$output")" ]; then
        [ "$(cat "$work/run/$output")" = precious ] || { fail "$name" "overwrote $output"; ok=0; break; }
      else
        [ ! -e "$work/run/$output" ] || { fail "$name" "created $output"; ok=0; break; }
      fi
    fi
  done
  [ "$ok" -eq 1 ] && passed=$((passed + 1))
done

for case_dir in "$here"/accepted/*/; do
  name="$(basename "$case_dir")"
  args="$(cat "$case_dir/args")"
  output="$(grep -oE -- '-o [^ ]+' <<< "$args" | cut -d' ' -f2)"
  rm -rf "$work/run" && mkdir "$work/run" && cp "$case_dir"/* "$work/run/"
  if (cd "$work/run" && eval "\"$program\" $args" > /dev/null 2> stderr.txt < /dev/null) && [ -s "$work/run/$output" ]; then
    passed=$((passed + 1))
  else
    fail "$name" "should be accepted: $(cat "$work/run/stderr.txt")"
  fi
done

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
