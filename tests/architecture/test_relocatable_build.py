"""A clean clone at another place compiles from the cache (CMakeLists.txt, docs/hardening.md):
no compile but the test paths' own names the source tree in its text or in a definition,
and a compile with debug information maps the tree to `.`."""
import json
import os
import re
import shlex

SOURCE = os.path.realpath(os.environ["STOCKBRIDGE_SOURCE_DIR"])
BUILD = os.environ["STOCKBRIDGE_BUILD_DIR"]
# The one file compiled with the tree's and the program's places (tests/support/test_paths.hpp).
PLACES = os.path.join(SOURCE, "tests", "support", "test_paths.cpp")


def compiles():
    with open(os.path.join(BUILD, "compile_commands.json"), encoding="utf-8") as f:
        entries = json.load(f)
    assert entries, "compile_commands.json lists no compile"
    return [(os.path.realpath(e["file"]), shlex.split(e["command"])) for e in entries]


def test_every_unity_batch_includes_its_sources_by_their_path_in_the_tree():
    batches = [file for file, _ in compiles() if os.sep + "unity" + os.sep in file]
    assert batches, "no unity batch compiled"
    for batch in batches:
        includes = re.findall(r'^#include "([^"]+)"', open(batch, encoding="utf-8").read(), re.M)
        assert includes, batch
        for path in includes:
            assert not os.path.isabs(path), f"{batch}: includes {path} by its absolute path"
            assert os.path.exists(os.path.join(SOURCE, path)), f"{batch}: {path} is not in the tree"


def test_no_definition_names_the_tree_but_the_test_paths_file():
    for file, arguments in compiles():
        if file == PLACES:
            continue
        for argument in arguments:
            if argument.startswith("-D"):
                assert SOURCE not in argument, f"{file}: {argument}"


def test_a_compile_with_debug_information_maps_the_tree():
    for file, arguments in compiles():
        if any(a == "-g" or re.fullmatch(r"-g(line-tables-only|[0-3])", a) for a in arguments):
            assert f"-fdebug-prefix-map={SOURCE}=." in arguments, f"{file}: -g without the tree mapped to ."
