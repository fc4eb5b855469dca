"""The package's stubs: the keywords they declare are the declared settings, and mypy --strict
checks a user's script against them."""

import ast
import pathlib
import subprocess
import sys

import jamchart as jc

HERE = pathlib.Path(__file__).resolve().parent
STUB = pathlib.Path(jc.__file__).with_name("__init__.pyi")


def stub_keywords(function):
    """The keyword-only parameters of each overload of `function` in the stub."""
    tree = ast.parse(STUB.read_text())
    found = []
    for node in tree.body:
        if isinstance(node, ast.FunctionDef) and node.name == function:
            found.append(([a.arg for a in node.args.kwonlyargs],
                          [ast.unparse(a.annotation) for a in node.args.kwonlyargs]))
    return found


def test_the_package_is_typed():
    assert STUB.is_file() and STUB.with_name("py.typed").is_file()


def test_the_stub_declares_every_keyword_with_its_type():
    for function in ["solve", "render", "design", "vlocator"]:
        declared = jc._jamchart.keywords(function)
        names = [n for n, _, _ in declared]
        overloads = stub_keywords(function)
        assert overloads, function
        for got_names, got_types in overloads:
            assert got_names == names, function
            for (name, _, ty), got in zip(declared, got_types):
                allowed = {ty, "float"} if ty in ("_Values", "_UncertainValues", "_Uncertain") else {ty}
                if ty == "_UncertainValues":
                    allowed.add("_Values")
                assert got in allowed, (function, name, got, ty)


def test_mypy_strict_checks_a_users_script():
    done = subprocess.run(
        [sys.executable, "-m", "mypy", "--strict", "--no-incremental", str(HERE / "typed_example.py")],
        capture_output=True, text=True,
    )
    assert done.returncode == 0, done.stdout + done.stderr


def test_mypy_catches_a_misspelt_keyword(tmp_path):
    script = tmp_path / "wrong.py"
    script.write_text("import jamchart as jc\njc.solve(raduis_mm=10.0)\n")
    done = subprocess.run([sys.executable, "-m", "mypy", "--strict", "--no-incremental", str(script)],
                          capture_output=True, text=True)
    assert done.returncode == 1 and "raduis_mm" in done.stdout
