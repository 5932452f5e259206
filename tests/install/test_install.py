"""The install and the Debian package, used as a user would: `cmake --install` of the
build tree into a temporary prefix, then the installed program, the C++ library
through its CMake package (examples/cpp_consumer), the installed headers and the
Python module from there; `cpack -G DEB` and the package's control fields and
contents. Every test works in its own temporary directory and removes it.

Run by ctest (tests/CMakeLists.txt: install_*, package_deb) with Debian's
/usr/bin/python3; the build tree and the tools come in the environment.
"""

import csv
import os
import re
import subprocess
import sys
import sysconfig
import tempfile
from pathlib import Path

import pytest

BUILD = Path(os.environ["STOCKBRIDGE_BUILD_DIR"])
SOURCE = Path(os.environ["STOCKBRIDGE_SOURCE_DIR"])
VERSION = os.environ["STOCKBRIDGE_VERSION"]
LIBDIR = os.environ["STOCKBRIDGE_INSTALL_LIBDIR"]  # relative to the prefix (GNUInstallDirs)
SHARED = os.environ["STOCKBRIDGE_SHARED"] == "1"  # BUILD_SHARED_LIBS
SOVERSION = os.environ["STOCKBRIDGE_SOVERSION"]
CMAKE = os.environ["STOCKBRIDGE_CMAKE"]
CPACK = os.environ["STOCKBRIDGE_CPACK"]
CXX = os.environ["STOCKBRIDGE_CXX"]
WITH_MPI = os.environ["STOCKBRIDGE_MPI"] == "1"
WITH_PYTHON = os.environ["STOCKBRIDGE_PYTHON"] == "1"
# Under any prefix but /usr (docs/install.md): where Debian's python3 looks under /usr/local.
PYTHON_DIR = f"lib/python3.{sys.version_info.minor}/dist-packages"
EXAMPLES = "share/stockbridge/examples"


def run(*command, cwd=None, env=None):
    """stdout of a command that must exit 0 (else its output in the failure)."""
    result = subprocess.run([str(c) for c in command], cwd=cwd, env=env, capture_output=True, text=True)
    assert result.returncode == 0, (f"{' '.join(map(str, command))}: exit {result.returncode}\n"
                                    f"{result.stdout[-3000:]}{result.stderr[-3000:]}")
    return result.stdout


def install(prefix, destdir=None):
    env = dict(os.environ, DESTDIR=str(destdir)) if destdir else None
    run(CMAKE, "--install", BUILD, "--prefix", prefix, env=env)


@pytest.fixture
def scratch():
    with tempfile.TemporaryDirectory(prefix="stockbridge-install-") as root:
        yield Path(root)


@pytest.fixture
def prefix(scratch):
    """The build tree installed into a temporary prefix."""
    install(scratch / "prefix")
    return scratch / "prefix"


def program_impedance(program, damper, work):
    """(Re Z, Im Z) from the program's CSV at 20 Hz, 0.2 m/s."""
    run(program, "impedance", damper, "--velocity", "0.2", "--frequencies", "20", "--quiet", "-o", "z.csv", cwd=work)
    with open(work / "z.csv", newline="") as handle:
        (row,) = list(csv.DictReader(handle))
    return float(row["re_z_n_s_m"]), float(row["im_z_n_s_m"])


def python_impedance(python_dir, damper, work):
    """(Re Z, Im Z, module file, __version__) from the Python module found in python_dir only."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env.update(PYTHONPATH=str(python_dir), PYTHONDONTWRITEBYTECODE="1")
    script = ("import stockbridge as sb\n"
              f"z = sb.impedance(sb.load_damper({str(damper)!r}), [20.0], velocity=0.2)\n"
              "print(repr(z['re_z_n_s_m'][0, 0]), repr(z['im_z_n_s_m'][0, 0]), sb.__file__, sb.__version__)\n")
    re_z, im_z, module, version = run("/usr/bin/python3", "-s", "-c", script, cwd=work, env=env).split()
    return float(re_z), float(im_z), module, version


def test_installed_tree_holds_the_public_interface_only(prefix, scratch):
    assert os.access(prefix / "bin" / "stockbridge", os.X_OK)
    libraries = {p.name for p in (prefix / LIBDIR).glob("libstockbridge.*")}
    if SHARED:
        assert libraries == {"libstockbridge.so", f"libstockbridge.so.{SOVERSION}", f"libstockbridge.so.{VERSION}"}
        dynamic = run("readelf", "-d", prefix / LIBDIR / f"libstockbridge.so.{VERSION}")
        assert f"Library soname: [libstockbridge.so.{SOVERSION}]" in dynamic
    else:
        assert libraries == {"libstockbridge.a"}
    config = prefix / LIBDIR / "cmake" / "stockbridge"
    for name in ("stockbridgeConfig.cmake", "stockbridgeConfigVersion.cmake", "stockbridgeTargets.cmake"):
        assert (config / name).is_file(), name
    assert (prefix / "share/doc/stockbridge/README.md").is_file()
    assert (prefix / "share/doc/stockbridge/docs/install.md").is_file()
    assert (prefix / EXAMPLES / "sauter2003.toml").is_file()
    assert (prefix / EXAMPLES / "cpp_consumer" / "CMakeLists.txt").is_file()

    # The headers: exactly include/stockbridge/** of the sources and the generated version.hpp.
    include = prefix / "include"
    installed = sorted(str(p.relative_to(include)) for p in include.rglob("*") if p.is_file())
    public = sorted(str(p.relative_to(SOURCE / "include")) for p in (SOURCE / "include").rglob("*.hpp"))
    assert installed == sorted(public + ["stockbridge/version.hpp"])
    # Each includes only installed headers, the standard library and Eigen (the
    # library's PUBLIC dependency; fmt, toml++, NLopt and Boost are private).
    for header in include.rglob("*.hpp"):
        for quoted in re.findall(r'^#include "([^"]+)"', header.read_text(), re.M):
            assert (include / quoted).is_file(), f"{header}: includes {quoted}, not installed"
        for system in re.findall(r"^#include <([^>]+)>", header.read_text(), re.M):
            assert "/" not in system or system.startswith("Eigen/"), f"{header}: includes <{system}>"
    # ... and all of them compile together with nothing but that include path and Eigen's.
    everything = scratch / "all_headers.cpp"
    everything.write_text("".join(f'#include "{h}"\n' for h in installed))
    run(CXX, "-std=c++20", "-fsyntax-only", "-I", include, "-I", "/usr/include/eigen3", everything)


def test_consumer_builds_against_the_package_and_equals_the_program(prefix, scratch):
    consumer = prefix / EXAMPLES / "cpp_consumer"  # as installed
    build = scratch / "consumer"
    run(CMAKE, "-S", consumer, "-B", build, f"-DCMAKE_PREFIX_PATH={prefix}", f"-DCMAKE_CXX_COMPILER={CXX}")
    run(CMAKE, "--build", build)
    damper = prefix / EXAMPLES / "sauter2003.toml"
    out = run(build / "impedance_point", damper)
    match = re.fullmatch(r"stockbridge (\S+): Z\(20 Hz, 0\.2 m/s\) = (\S+) (\S+)i N s/m\n", out)
    assert match, out
    assert match.group(1) == VERSION
    re_z, im_z = program_impedance(prefix / "bin" / "stockbridge", damper, scratch)
    assert float(match.group(2)) == pytest.approx(re_z, rel=1e-12)
    assert float(match.group(3)) == pytest.approx(im_z, rel=1e-12)


def test_installed_program_runs_the_readme_job_from_the_installed_examples(prefix, scratch):
    program = prefix / "bin" / "stockbridge"
    assert run(program, "--version") == f"stockbridge {VERSION}\n"
    # The README's main job (under a second).
    run(program, "impedance", prefix / EXAMPLES / "sauter2003.toml", "--velocity", "0.2,0.05", "--fmin", "1",
        "--fmax", "100", "--points", "200", "-o", "impedance.csv", cwd=scratch)
    with open(scratch / "impedance.csv", newline="") as handle:
        rows = list(csv.DictReader(handle))
    assert len(rows) == 400
    assert all(row["converged"] == "1" for row in rows)


@pytest.mark.skipif(not WITH_PYTHON, reason="built without the Python module")
def test_installed_python_module_imports_from_the_prefix_and_equals_the_program(prefix, scratch):
    damper = prefix / EXAMPLES / "sauter2003.toml"
    re_z, im_z, module, version = python_impedance(prefix / PYTHON_DIR, damper, scratch)
    assert Path(module).is_relative_to(prefix / PYTHON_DIR / "stockbridge"), module
    assert version == VERSION
    assert (re_z, im_z) == pytest.approx(program_impedance(prefix / "bin" / "stockbridge", damper, scratch), rel=1e-12)


@pytest.mark.skipif(not WITH_PYTHON, reason="built without the Python module")
def test_python_package_goes_where_debian_python3_looks_for_usr_and_usr_local(scratch):
    searched = run("/usr/bin/python3", "-c", "import site; print('\\n'.join(site.getsitepackages()))").split()
    for prefix, python_dir in (("/usr", "lib/python3/dist-packages"), ("/usr/local", PYTHON_DIR)):
        destdir = scratch / prefix.strip("/").replace("/", "_")
        install(prefix, destdir=destdir)
        package = destdir / prefix.lstrip("/") / python_dir / "stockbridge"
        assert (package / "__init__.py").is_file(), package
        assert list(package.glob(f"_core{sysconfig.get_config_var('EXT_SUFFIX')}")), package
        assert f"{prefix}/{python_dir}" in searched, (prefix, searched)


def test_debian_package_depends_on_the_linked_libraries_and_installs_to_usr(scratch):
    run(CPACK, "-G", "DEB", "-B", scratch, "--config", BUILD / "CPackConfig.cmake")
    arch = run("dpkg", "--print-architecture").strip()
    deb = scratch / f"stockbridge_{VERSION}_{arch}.deb"
    assert deb.is_file(), sorted(p.name for p in scratch.iterdir())

    assert run("dpkg-deb", "-f", deb, "Package", "Version", "Architecture") == (
        f"Package: stockbridge\nVersion: {VERSION}\nArchitecture: {arch}\n")
    depends = {re.sub(r"\s*\(.*\)", "", d).strip() for d in run("dpkg-deb", "-f", deb, "Depends").split(",")}
    expected = {"libc6", "libstdc++6", "libgcc-s1", "libfmt9", "libnlopt0", "libtomlplusplus3"}
    if WITH_MPI:
        expected.add("libopenmpi3")
    if WITH_PYTHON:
        expected |= {"python3", "python3-numpy"}
    assert expected <= depends, f"missing: {expected - depends}"

    files = [line.split()[5] for line in run("dpkg-deb", "-c", deb).splitlines()]  # symlinks: "path -> target"
    assert all(f == "./" or f.startswith("./usr/") for f in files), [f for f in files if not f.startswith("./usr/")]
    assert not [f for f in files if f.startswith("./usr/local")]
    for expected_file in ("./usr/bin/stockbridge", "./usr/include/stockbridge/version.hpp",
                          f"./usr/{EXAMPLES}/sauter2003.toml", "./usr/share/doc/stockbridge/docs/install.md"):
        assert expected_file in files, expected_file
    assert [f for f in files if re.fullmatch(r"\./usr/lib/(.+/)?cmake/stockbridge/stockbridgeConfig\.cmake", f)]

    # The unpacked package's program and (under /usr's Python directory) module run.
    root = scratch / "unpacked"
    run("dpkg-deb", "-x", deb, root)
    assert run(root / "usr/bin/stockbridge", "--version") == f"stockbridge {VERSION}\n"
    if WITH_PYTHON:
        damper = root / "usr" / EXAMPLES / "sauter2003.toml"
        re_z, im_z, module, _ = python_impedance(root / "usr/lib/python3/dist-packages", damper, scratch)
        assert (re_z, im_z) == pytest.approx(program_impedance(root / "usr/bin/stockbridge", damper, scratch), rel=1e-12)
