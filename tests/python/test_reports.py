"""jamchart.design and jamchart.vlocator: the CLI's inverse and V-block answers as objects
whose attributes are the JSON document's keys, `to_dict()` the document itself."""

import pytest

import jamchart as jc

from conftest import SHAFT, SHAFT_FLAGS


def test_design_is_the_clis_json(cli_json, cli):
    want = cli_json("design", "--x-target", "60", "--mu", "0.12:0.3", *SHAFT_FLAGS)
    got = jc.design(x_target_mm=60, mu=jc.Range(0.12, 0.3), **SHAFT)
    assert isinstance(got, jc.DesignAnswer)
    assert got.to_dict() == want
    assert got.design == want["design"] and got.design["least_push"]
    assert repr(got).startswith("jamchart.DesignAnswer(no push carries the disc to x = 60 mm over "
                                "mu = 0.12:0.3: the friction wedge locks it")
    assert str(got) == cli("design", "--x-target", "60", "--mu", "0.12:0.3", *SHAFT_FLAGS)


def test_design_needs_its_target():
    with pytest.raises(TypeError, match="x_target_mm"):
        jc.design(mu=0.3)
    with pytest.raises(ValueError, match="x_target_mm"):
        jc.design(x_target_mm=-5)


def test_vlocator_is_the_clis_json(cli_json):
    want = cli_json("vlocator", "--included-angle", "70", "--mu", "0.25", "--load", "5")
    got = jc.vlocator(included_angle_deg=70, mu=0.25, load_n=5)
    assert got.to_dict() == want
    assert got.verdict in {"held", "slips", "lifts_off", "wedged"}
    assert repr(got) == f"jamchart.VlocatorAnswer({got.headline})"
    assert got.headline.startswith(got.verdict + ": V of 70.00 deg")
    with pytest.raises(AttributeError, match="verdict"):
        got.verdikt


def test_vlocator_over_a_range_is_the_clis(cli_json):
    want = cli_json("vlocator", "--mu", "0.1:0.3")
    got = jc.vlocator(mu=jc.Range(0.1, 0.3))
    assert got.to_dict() == want
    assert got.headline.startswith("V-blocks of ") and "(m = 1 kg)" in got.headline


def test_a_v_block_that_does_not_work_says_so_in_one_line():
    got = jc.vlocator(mu=jc.Range(0.1, 0.25), load_n=20, mass_kg=0.4)
    assert repr(got).startswith("jamchart.VlocatorAnswer(no single V works over mu 0.1 to 0.25 "
                                "under 20 N (m = 0.4 kg)")


def test_vlocator_refuses_a_keyword_it_does_not_take():
    with pytest.raises(TypeError, match="radius_mm"):
        jc.vlocator(radius_mm=10)
