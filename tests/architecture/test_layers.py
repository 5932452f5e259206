"""The library's layers (cmake/check_layers.py, a step of the library's build): the tree
keeps them, and an include that runs up them is caught, naming its file and line, and
stops the build."""
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.environ.get("STOCKBRIDGE_SOURCE_DIR", os.path.dirname(os.path.dirname(HERE)))
CHECK = os.path.join(SOURCE, "cmake", "check_layers.py")


def run_check(source):
    return subprocess.run([sys.executable, CHECK, source], stdout=subprocess.PIPE, text=True)


def copy_of_sources(tmp_path):
    for name in ("src", "include"):
        shutil.copytree(os.path.join(SOURCE, name), tmp_path / name)
    return tmp_path


def test_the_tree_keeps_its_layers():
    result = run_check(SOURCE)
    assert result.returncode == 0, result.stdout
    assert result.stdout.strip().endswith("layers: 0 include(s) against the rules")


def test_an_include_up_the_layers_is_caught_naming_its_file_and_line(tmp_path):
    tree = copy_of_sources(tmp_path)
    balance = tree / "src" / "span" / "balance.cpp"
    lines = balance.read_text(encoding="utf-8").splitlines(keepends=True)
    lines.insert(1, '#include "stockbridge/report/reports.hpp"\n')
    balance.write_text("".join(lines), encoding="utf-8")
    result = run_check(str(tree))
    assert result.returncode == 1
    assert "src/span/balance.cpp:2: span includes report (allowed: core, numerics, strand, damper)" in result.stdout


def test_a_private_header_reached_by_a_relative_path_counts_too(tmp_path):
    tree = copy_of_sources(tmp_path)
    header = tree / "include" / "stockbridge" / "damper" / "damper.hpp"
    text = header.read_text(encoding="utf-8")
    header.write_text(text.replace("#pragma once\n", '#pragma once\n#include "../line/nothing.hpp"\n', 1),
                      encoding="utf-8")
    result = run_check(str(tree))
    assert result.returncode == 1
    assert "include/stockbridge/damper/damper.hpp:2: damper includes line" in result.stdout


def test_an_include_down_the_layers_is_allowed(tmp_path):
    tree = copy_of_sources(tmp_path)
    report = tree / "src" / "report" / "svg_chart.cpp"
    report.write_text('#include "stockbridge/core/error.hpp"\n' + report.read_text(encoding="utf-8"), encoding="utf-8")
    assert run_check(str(tree)).returncode == 0


def configured_copy(tmp_path):
    """A copy of the project's build inputs, configured for the library and program alone."""
    tree = tmp_path / "tree"
    tree.mkdir()
    for name in ("CMakeLists.txt", "CMakePresets.json"):
        shutil.copy(os.path.join(SOURCE, name), tree / name)
    for name in ("src", "include", "cmake", "apps", "data"):
        shutil.copytree(os.path.join(SOURCE, name), tree / name)
    build = tmp_path / "build"
    configure = subprocess.run(["cmake", "-S", str(tree), "-B", str(build), "-DSTOCKBRIDGE_BUILD_PYTHON=OFF",
                                "-DSTOCKBRIDGE_WITH_MPI=OFF", "-DSTOCKBRIDGE_CCACHE=OFF"],
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    assert configure.returncode == 0, configure.stdout
    return tree, build


def build_target(build, target):
    return subprocess.run(["cmake", "--build", str(build), "--target", target],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def test_the_build_stops_at_an_include_up_the_layers_and_goes_on_once_it_is_gone(tmp_path):
    tree, build = configured_copy(tmp_path)
    assert build_target(build, "stockbridge_layers").returncode == 0
    balance = tree / "src" / "span" / "balance.cpp"
    original = balance.read_text(encoding="utf-8")
    balance.write_text('#include "stockbridge/line/line.hpp"\n' + original, encoding="utf-8")
    stopped = build_target(build, "stockbridge")  # the library: the check comes first
    assert stopped.returncode != 0
    assert "src/span/balance.cpp:1: span includes line" in stopped.stdout
    assert "Building CXX object" not in stopped.stdout, "compiled before the check stopped the build"
    balance.write_text(original, encoding="utf-8")
    assert build_target(build, "stockbridge_layers").returncode == 0
