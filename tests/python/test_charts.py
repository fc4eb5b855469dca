"""jamchart.render: the CLI's pictures and data, shown in a notebook, saved in any format."""

import json

import numpy as np
import pytest

import jamchart as jc


@pytest.fixture(scope="module")
def universal():
    return jc.render("universal", read_off={"mu": 0.27}, radius_mm=12, force_n=150)


def test_the_chart_is_the_clis_bytes(cli, tmp_path, universal):
    cli("render", "universal", "--set", "radius_mm=12", "--set", "force_n=150",
        "--read-off", "mu=0.27", "--out", str(tmp_path), "--quiet")
    assert universal.svg == (tmp_path / "universal.svg").read_bytes()
    assert universal.png == (tmp_path / "universal.png").read_bytes()
    data = (tmp_path / f"universal.{universal.data_format}").read_bytes()
    if universal.data_format == "json":
        doc = json.loads(data)
        # The file names its scene beside the figure; the figure is the same, its numbers
        # rounded in the file to 7 significant digits and as computed in `data`.
        assert set(universal.data) == set(doc) - {"scene", "title", "cells_file"}
        compared = []

        def same(got, want, at):
            if isinstance(got, dict):
                for k in got:
                    same(got[k], want[k], f"{at}.{k}")
            elif isinstance(got, list):
                assert len(got) == len(want), at
                for i, (g, w) in enumerate(zip(got, want)):
                    same(g, w, f"{at}[{i}]")
            elif isinstance(got, np.ndarray):
                want = np.array([np.nan if w is None else w for w in want], dtype=float)
                assert np.allclose(got, want, rtol=1e-6, equal_nan=True), at
                compared.append(at)
            elif isinstance(got, float):
                assert abs(got - want) <= 1e-6 * abs(want), at

        same(universal.data, {k: doc[k] for k in universal.data}, "data")
        assert len(compared) >= 5, compared


def test_the_notebook_reprs_are_the_pictures(universal):
    assert universal._repr_svg_().startswith("<svg")
    assert universal._repr_svg_().encode() == universal.svg
    assert universal._repr_png_()[:8] == b"\x89PNG\r\n\x1a\n"
    assert repr(universal).startswith("jamchart.Chart(universal, kind universal")


def test_the_data_has_numpy_arrays(universal):
    def arrays(v):
        if isinstance(v, np.ndarray):
            yield v
        elif isinstance(v, dict):
            for x in v.values():
                yield from arrays(x)
        elif isinstance(v, list):
            for x in v:
                yield from arrays(x)

    found = list(arrays(universal.data))
    assert found and all(a.dtype == np.float64 for a in found)


def test_a_csv_chart_gives_its_columns():
    chart = jc.render("fig7b", set={"chart.x_axis.count": 9})
    assert chart.data_format == "csv"
    columns = chart.data
    numeric = [v for v in columns.values() if isinstance(v, np.ndarray)]
    assert numeric and all(len(v) == len(numeric[0]) for v in numeric)


@pytest.mark.parametrize("ext,magic", [("svg", b"<svg"), ("png", b"\x89PNG"), ("pdf", b"%PDF")])
def test_save_writes_each_format(universal, tmp_path, ext, magic):
    path = tmp_path / f"shaft.{ext}"
    universal.save(path)
    assert path.read_bytes().startswith(magic)


def test_save_refuses_an_unknown_format(universal, tmp_path):
    with pytest.raises(ValueError, match=r"\.svg, \.png, \.pdf"):
        universal.save(tmp_path / "shaft.gif")


def test_bad_scenes_and_values_are_refused():
    with pytest.raises(ValueError, match="not a built-in scene"):
        jc.render("fig99")
    with pytest.raises(ValueError, match="radius_mm"):
        jc.render("universal", radius_mm=-1)
    with pytest.raises(TypeError, match="unexpected keyword argument 'colour'"):
        jc.render("universal", colour="red")
    assert "universal" in jc.scenes()
