"""The package's stubs: the keywords they declare are the declared settings, and mypy --strict
checks a user's script against them."""

import ast
import inspect
import pathlib
import subprocess
import os
import sys

import jamchart as jc

HERE = pathlib.Path(__file__).resolve().parent
STUB = pathlib.Path(jc.__file__).with_name("__init__.pyi")


def test_the_package_is_typed():
    assert STUB.is_file() and STUB.with_name("py.typed").is_file()


def test_the_stub_declares_every_keyword_with_its_type():
    """The stub is the one the extension writes from its list of functions and the settings'
    declaration; after a new setting or function, rewrite it with JAMCHART_WRITE_STUB=1 (then
    copy it into the package: pip install . again)."""
    want = jc._jamchart._stub()
    source = HERE.parents[1] / "src" / "python" / "jamchart" / "__init__.pyi"
    if os.environ.get("JAMCHART_WRITE_STUB") == "1":
        source.write_text(want)
    assert source.read_text() == want
    assert STUB.read_text() == want, "the installed stub is older: pip install . again"
    tree = ast.parse(want)
    solves = [n for n in tree.body if isinstance(n, ast.FunctionDef) and n.name == "solve"]
    assert len(solves) == 4
    assert [a.arg for a in solves[0].args.kwonlyargs] == jc.keywords("solve")


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


def test_every_name_of_the_package_is_in_its_stub_and_all():
    """One list registers a function: its wrapper, `__all__` and its stub follow from it."""
    tree = ast.parse(STUB.read_text())
    declared = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    declared |= {t.id for n in tree.body if isinstance(n, ast.AnnAssign) for t in [n.target]}
    public = {n for n in jc.__all__}
    assert public <= declared, public - declared
    assert {n for n in declared if not n.startswith("_")} <= public
    for name in jc.__all__:
        assert hasattr(jc, name), name
    for name, positional in jc._jamchart._functions():
        assert list(inspect.signature(getattr(jc, name)).parameters)[:len(positional)] == positional
        assert getattr(jc, name).__doc__.startswith(jc._jamchart._doc(name)[:40])
