"""Fixtures of the Python package's tests: the command-line binary, run for its JSON, as the
reference every answer of the package is held against."""

import json
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def _binary() -> pathlib.Path:
    given = os.environ.get("JAMCHART_BIN")
    path = pathlib.Path(given) if given else ROOT / "target" / "release" / "jamchart"
    if not path.is_file():
        pytest.fail(f"no jamchart binary at {path}: build it (cargo build --release) or set JAMCHART_BIN")
    return path


@pytest.fixture(scope="session")
def cli():
    """Runs `jamchart ARGS...` and returns its stdout; fails on a non-zero exit."""
    binary = _binary()

    def run(*args: str) -> str:
        done = subprocess.run([str(binary), *args], capture_output=True, text=True)
        assert done.returncode == 0, f"jamchart {' '.join(args)}: {done.stderr}"
        return done.stdout

    return run


@pytest.fixture(scope="session")
def cli_json(cli):
    """Runs `jamchart ARGS... --format json` and returns the parsed document."""
    return lambda *args: json.loads(cli(*args, "--format", "json"))


@pytest.fixture(scope="session")
def cli_error():
    """Runs `jamchart ARGS...`, expects exit 2, and returns its message without `jamchart: `."""
    binary = _binary()

    def run(*args: str) -> str:
        done = subprocess.run([str(binary), *args], capture_output=True, text=True)
        assert done.returncode == 2, f"jamchart {' '.join(args)} exited {done.returncode}"
        return done.stderr.strip().removeprefix("jamchart: ")

    return run


# The worked example the uncertainty tests share: a 25 mm shaft pushed by an 80 mm palm.
SHAFT = dict(radius_mm=12.5, mass_kg=0.4, force_n=40.0, palm_length_mm=80.0)
SHAFT_FLAGS = ["--radius", "12.5", "--mass", "0.4", "--force", "40", "--palm-length", "80"]
