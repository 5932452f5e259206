#!/usr/bin/env bash
# Writes the HTML pages of `span` (a span, and one with spheres along it), `impedance`,
# `line` and `design` (--report) and of
# `datasheet` on the examples, then checks them in headless chromium with
# check_page.py: nothing outside the page, no request, no console error, a screenshot
# that shows something, every figure on one A4 page, a PDF.
#
# Usage: make_and_check_reports.sh STOCKBRIDGE SOURCE_DIR OUT_DIR
# The commands run from SOURCE_DIR (the examples' relative paths); OUT_DIR is emptied
# and gets the pages, their CSVs, screenshots (NAME.png) and printouts (NAME.pdf).
# Exits 1 if a command or a check failed, 77 (ctest's skip) when chromium is missing.
set -uo pipefail
if [ $# -ne 3 ]; then
  echo "usage: $0 STOCKBRIDGE SOURCE_DIR OUT_DIR" >&2
  exit 2
fi
cli=$1
source_dir=$2
out=$3
here=$(cd "$(dirname "$0")" && pwd)

rm -rf "$out"
mkdir -p "$out"
cd "$source_dir" || exit 1

failed=0
run() {
  local log="$out/command.log"
  echo "+ stockbridge $*"
  if ! "$cli" "$@" >"$log" 2>&1; then
    sed 's/^/  /' "$log"
    echo "FAILED: stockbridge $*"
    failed=1
  fi
}

start=$SECONDS
run span examples/aster570_400m.toml --points 40 -o "$out/span.csv" --report "$out/span.html" --quiet
run span examples/opgw_600m_spheres.toml --points 40 -o "$out/span_spheres.csv" --report "$out/span_spheres.html" --quiet
run impedance examples/sauter2003.toml --velocity 0.2,0.05 --fmin 5 --fmax 100 --points 60 \
  -o "$out/impedance.csv" --report "$out/impedance.html"
run line examples/line_short.toml -o "$out/line.csv" --report "$out/line.html" --quiet
run design examples/design_aster570.toml --samples 2 --polish 0 --quiet \
  -o "$out/design.csv" --best "$out/design_best.toml" --report "$out/design.html"
run datasheet examples/sauter2003.toml --spans examples/aster570_400m.toml -o "$out/datasheet.html"
echo "commands: $((SECONDS - start)) s"

pages=()
for name in span span_spheres impedance line design datasheet; do
  if [ -f "$out/$name.html" ]; then
    pages+=("$out/$name.html")
  else
    echo "$out/$name.html: not written"
    failed=1
  fi
done

status=0
if [ ${#pages[@]} -gt 0 ]; then
  /usr/bin/python3 "$here/check_page.py" --verbose --screenshots "$out" --pdf "$out" "${pages[@]}"
  status=$?
fi
if [ $failed -ne 0 ]; then
  exit 1
fi
exit $status
