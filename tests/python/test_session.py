"""The guide's notebook session runs end to end, cell by cell, as a notebook user runs it: no
error and no warning in any cell, and what each cell makes is what it says."""

import os
import pathlib
import warnings

import matplotlib

matplotlib.use("Agg")

import jamchart as jc  # noqa: E402

GUIDE = pathlib.Path(__file__).resolve().parents[2] / "src" / "guide.md"


def _session() -> str:
    text = GUIDE.read_text()
    block = text.split("<!-- session -->")[1].split("<!-- /session -->")[0]
    return block.strip().removeprefix("```python").removesuffix("```").strip()


def test_help_shows_the_guides_session():
    session = _session()
    assert session == jc._jamchart._session()
    assert "\n".join("    " + line for line in session.splitlines()) in jc.__doc__


def test_the_session_runs_cell_by_cell(tmp_path):
    cells = ["# %%" + c for c in _session().split("# %%")[1:]]
    assert len(cells) == 8
    space: dict = {}
    here = os.getcwd()
    os.chdir(tmp_path)
    try:
        for cell in cells:
            with warnings.catch_warnings():
                warnings.simplefilter("error")
                exec(compile(cell, cell.splitlines()[0], "exec"), space)
    finally:
        os.chdir(here)
    assert space["m"].x_jam_mm.shape == (150, 200)
    assert (space["sweep"]["radius_mm"] == 12.5).all()
    assert space["both"].guidance.startswith("which to design to:")
    assert space["spread"].probability and space["spread"].quantiles
    assert "push" in space["plan"].headline
    assert (tmp_path / "shaft.pdf").read_bytes().startswith(b"%PDF")
