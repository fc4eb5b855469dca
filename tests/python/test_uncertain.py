"""jamchart.solve over ranges and distributions: the CLI's interval, probabilities and
quantiles, and the laws they keep."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import jamchart as jc

from conftest import SHAFT, SHAFT_FLAGS


def test_a_range_is_the_clis_interval(cli_json):
    want = cli_json("solve", "--mu", "0.12:0.3", *SHAFT_FLAGS)["results"][0]
    got = jc.solve(mu=jc.Range(0.12, 0.3), **SHAFT)
    assert isinstance(got, jc.BoxAnswer)
    assert got.record == want
    assert got.theta_jam_deg == tuple(want["theta_jam_deg"])
    assert got.x_jam_mm == tuple(want["x_jam_mm"])
    assert got.statuses == want["statuses"]
    # The CLI's text syntax reads the same.
    assert jc.solve(mu="0.12:0.3", **SHAFT).record == want


def test_a_distribution_gives_the_clis_probabilities_and_quantiles(cli_json):
    want = cli_json("solve", "--mu", "normal(0.2,0.03)", "--before", "50,60", *SHAFT_FLAGS)
    got = jc.solve(mu=jc.normal(0.2, 0.03), before_mm=[50, 60], **SHAFT)
    record = want["results"][0]
    assert got.record == record
    assert got.probability == [(b["x_mm"], b["probability"]["value"])
                               for b in record["distribution"]["before"]]
    assert [q for q, _ in got.quantiles] == [0.05, 0.5, 0.95]


def test_a_sampled_model_is_seeded_as_the_cli(cli_json):
    flags = ["--model", "min-norm", "--mu", "uniform(0.2,0.4)", "--force", "lognormal(60,0.1)",
             "--samples", "200", "--seed", "7", "--before", "30"]
    want = cli_json("solve", *flags)["results"][0]
    got = jc.solve(model="min-norm", mu=jc.uniform(0.2, 0.4), force_n=jc.lognormal(60, 0.1),
                   samples=200, seed=7, before_mm=30)
    assert got.record == want
    assert got.record["distribution"]["method"] == "monte_carlo"


def test_bad_ranges_are_refused_as_the_cli_refuses_them(cli_error):
    for flags, keywords in [
        (["--mu", "0.3:0.12"], dict(mu="0.3:0.12")),
        (["--mu", "normal(0.2,-1)"], dict(mu="normal(0.2,-1)")),
        (["--force", "0:40"], dict(force_n=jc.Range(0, 40))),
    ]:
        cli = cli_error("solve", *flags)
        with pytest.raises(ValueError) as e:
            jc.solve(**keywords)
        flag = cli[cli.index(" (flag"):cli.index(")", cli.index(" (flag")) + 1]
        assert cli.replace(flag, "") == str(e.value)


def test_a_range_with_an_array_is_refused():
    with pytest.raises(ValueError, match="mu is an array, and a range or a distribution is "
                                         "answered for one scene"):
        jc.solve(mu=np.array([0.2, 0.3]), force_n=jc.Range(30, 50))


def test_question_keywords_without_a_distribution_warn():
    with pytest.warns(UserWarning, match="before_mm has no effect without a distributed input"):
        jc.solve(mu=0.3, before_mm=50)
    with pytest.raises(ValueError, match="quantiles"):
        jc.solve(mu=jc.normal(0.2, 0.03), quantiles=[1.5])


def test_a_distribution_object_reads_back():
    d = jc.normal(0.2, 0.03)
    assert d.nominal == 0.2
    assert abs(d.cdf(d.quantile(0.3)) - 0.3) < 1e-12


@settings(max_examples=40, deadline=None)
@given(lo=st.floats(0.02, 1.0), width=st.floats(0.01, 0.8), force=st.floats(10, 400),
       t=st.lists(st.floats(0, 1), min_size=1, max_size=6))
def test_the_range_answer_contains_the_point_answers(lo, width, force, t):
    """The closed form's box answer is exact (monotone): every point inside it jams within it."""
    hi = lo + width
    box = jc.solve(mu=jc.Range(lo, hi), force_n=force, palm_length_mm=1e6)
    points = jc.solve(mu=lo + width * np.array(t), force_n=force, palm_length_mm=1e6)
    jams = points.status == "jams"
    if box.theta_jam_deg is None:
        assert not jams.any()
        return
    t0, t1 = box.theta_jam_deg
    x0, x1 = box.x_jam_mm
    tol = 1e-9
    assert ((points.theta_jam_deg[jams] >= t0 - tol) & (points.theta_jam_deg[jams] <= t1 + tol)).all()
    assert ((points.x_jam_mm[jams] >= x0 * (1 - tol)) & (points.x_jam_mm[jams] <= x1 * (1 + tol))).all()
    assert set(points.status) <= set(box.statuses)


def test_a_range_or_distribution_with_a_non_finite_end_is_refused():
    """A range with a NaN or infinite end was dropped on its way to the scene, which then
    answered the default friction (mu 0.4) without a word."""
    nan, inf = float("nan"), float("inf")
    for keywords in [dict(mu="0.1:nan"), dict(mu="0.1:inf"), dict(force_n="10:nan"),
                     dict(mass_kg="1:inf")]:
        key = next(iter(keywords))
        with pytest.raises(ValueError, match=f"invalid {key} = "):
            jc.solve(**keywords)
    for make in [lambda: jc.Range(0.1, nan), lambda: jc.Range(0.1, inf), lambda: jc.normal(nan, 1),
                 lambda: jc.lognormal(1, inf), lambda: jc.uniform(-inf, 1)]:
        with pytest.raises(ValueError, match="is not a finite number"):
            make()


def test_the_box_answer_is_the_clis_document(cli_json, cli):
    want = cli_json("solve", "--mu", "normal(0.21,0.03)", "--before", "50", *SHAFT_FLAGS)
    got = jc.solve(mu=jc.normal(0.21, 0.03), before_mm=50, **SHAFT)
    assert got.to_dict() == want
    assert str(got) == cli("solve", "--mu", "normal(0.21,0.03)", "--before", "50", *SHAFT_FLAGS)
    assert "P(jams before 50 mm) = 0.1756" in repr(got)
