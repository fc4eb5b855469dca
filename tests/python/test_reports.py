"""jamchart.design and jamchart.vlocator: the CLI's inverse and V-block answers as dicts."""

import pytest

import jamchart as jc

from conftest import SHAFT, SHAFT_FLAGS


def without_times(doc):
    return doc


def test_design_is_the_clis_json(cli_json):
    want = cli_json("design", "--x-target", "60", "--mu", "0.12:0.3", *SHAFT_FLAGS)
    got = jc.design(x_target_mm=60, mu=(0.12, 0.3), **SHAFT)
    assert got == want
    assert got["design"]["least_push"]


def test_design_needs_its_target():
    with pytest.raises(TypeError, match="x_target_mm"):
        jc.design(mu=0.3)
    with pytest.raises(ValueError, match="x_target_mm"):
        jc.design(x_target_mm=-5)


def test_vlocator_is_the_clis_json(cli_json):
    want = cli_json("vlocator", "--included-angle", "70", "--mu", "0.25", "--load", "5")
    got = jc.vlocator(included_angle_deg=70, mu=0.25, load_n=5)
    assert got == want
    assert got["verdict"] in {"held", "slips", "lifts_off", "wedged"}


def test_vlocator_over_a_range_is_the_clis(cli_json):
    want = cli_json("vlocator", "--mu", "0.1:0.3")
    assert jc.vlocator(mu=(0.1, 0.3)) == want


def test_vlocator_refuses_a_keyword_it_does_not_take():
    with pytest.raises(TypeError, match="radius_mm"):
        jc.vlocator(radius_mm=10)
