"""Docs as the code is (issue 34, item 7): every command `cdea --help` lists
is named in doc/usage.md, every parameter `cdea print-parameters --json`
lists is named in doc/ or README.md (as `Entry` or Subsection/Entry), and
every public name of the Python module is named in doc/python.md."""
import glob
import json
import os
import re
import subprocess

import pytest

import cdea

EXE = os.environ.get("CDEA_EXECUTABLE")
SRC = os.environ.get("CDEA_SOURCE_DIR", os.path.join(os.path.dirname(__file__), ".."))


def read(*names):
    return "".join(open(os.path.join(SRC, n), encoding="utf-8").read() for n in names)


def program(*args):
    if not EXE:
        pytest.skip("CDEA_EXECUTABLE not set (run through ctest)")
    done = subprocess.run([EXE, *args], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_every_command_in_usage():
    commands = re.findall(r"^  cdea ([a-z][a-z-]+)", program("--help"), re.M)
    assert len(commands) >= 12, commands
    usage = read("doc/usage.md")
    missing = [c for c in commands if f"cdea {c}" not in usage]
    assert not missing, f"commands of `cdea --help` that doc/usage.md does not name: {missing}"


def entries(tree, path=()):
    for key, value in tree.items():
        if isinstance(value, dict) and "value" not in value:
            yield from entries(value, path + (key,))
        else:
            yield path + (key,)


def test_every_parameter_in_the_docs():
    docs = read(*[os.path.relpath(p, SRC) for p in glob.glob(os.path.join(SRC, "doc", "*.md"))],
                "README.md")
    found = list(entries(json.loads(program("print-parameters", "--json"))))
    assert len(found) > 100, len(found)
    missing = ["/".join(e) for e in found if f"`{e[-1]}`" not in docs and "/".join(e) not in docs]
    assert not missing, f"parameters no document names: {missing}"


def test_every_python_name_in_python_md():
    names = [n for n in dir(cdea) if not n.startswith("_")]
    assert {"run", "fit", "load", "response"} <= set(names), names
    python_md = read("doc/python.md")
    missing = [n for n in names if n not in python_md]
    assert not missing, f"names of the module that doc/python.md does not name: {missing}"
