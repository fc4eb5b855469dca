"""What a notebook user meets beyond one answer: ranges spelt one way, checked distributions,
every model side by side, arrays bounded and warned about like single values, answers that cross
process boundaries, charts on paper."""

import pathlib
import pickle
import warnings

import numpy as np
import pytest

import jamchart as jc

SHAFT = dict(radius_mm=12.5, mass_kg=0.4, force_n=40, palm_length_mm=80)


def test_a_tuple_is_refused_with_the_two_spellings_it_could_mean():
    """numpy reads (0.12, 0.3) as two values, the package once as a range: never guessed."""
    with pytest.raises(ValueError, match=r"mu: a tuple could mean two values or a range; give "
                                         r"jamchart.Range\(LOW, HIGH\)"):
        jc.solve(mu=(0.12, 0.3))
    with pytest.raises(ValueError, match="mu: a tuple"):
        jc.design(x_target_mm=60, mu=(0.12, 0.3))
    with pytest.raises(ValueError, match="mu: a tuple"):
        jc.render("universal", mu=(0.12, 0.3))


def test_a_range_object_and_the_clis_text_are_one_range():
    r = jc.Range(0.12, 0.3)
    assert (r.low, r.high, r.nominal) == (0.12, 0.3, 0.21)
    assert repr(r) == "jamchart.Range(0.12, 0.3)"
    assert jc.solve(mu=r, **SHAFT).to_dict() == jc.solve(mu="0.12:0.3", **SHAFT).to_dict()
    # A list is values, as numpy reads it.
    assert jc.solve(mu=[0.12, 0.3], **SHAFT).shape == (2,)


def test_distribution_and_range_objects_are_checked_when_made():
    for make, why in [
        (lambda: jc.normal(0.2, -1), r"jamchart.normal\(0.2, -1\): its standard deviation must be > 0"),
        (lambda: jc.uniform(0.3, 0.1), r"jamchart.uniform\(0.3, 0.1\): the range is reversed"),
        (lambda: jc.lognormal(0, 0.1), r"its median must be > 0"),
        (lambda: jc.Range(0.3, 0.3), r"the range is empty"),
    ]:
        with pytest.raises(ValueError, match=why):
            make()
    d = jc.normal(0.2, 0.03)
    for p in [1.5, -0.1, float("nan")]:
        with pytest.raises(ValueError, match="is not a probability"):
            d.quantile(p)
    with pytest.raises(ValueError, match="x is NaN"):
        d.cdf(float("nan"))
    assert d.quantile(0.0) <= d.quantile(0.5) <= d.quantile(1.0)


def test_every_model_side_by_side_with_which_to_design_to(cli_json):
    got = jc.solve(mu=0.3, model="all", **SHAFT)
    assert isinstance(got, jc.Comparison)
    assert got.models == ["statics", "min-norm", "dynamics"]
    flags = ["--radius", "12.5", "--mass", "0.4", "--force", "40", "--palm-length", "80"]
    want = cli_json("solve", "--mu", "0.3", "--model", "all", *flags)
    got_dict = got.to_dict()
    for r in got_dict["results"] + want["results"]:
        r.pop("elapsed_s")
    assert got_dict == want
    assert got.guidance.startswith("which to design to:\n  a slow push limited to F = 40 N")
    assert str(got).endswith(got.guidance)
    assert got.solutions["statics"].x_jam_mm == jc.solve(mu=0.3, **SHAFT).x_jam_mm
    table = got.to_pandas()
    assert list(table["model"]) == got.models
    assert list(table.columns) == ["model", "status", "theta_jam_deg", "x_jam_mm", "elapsed_s"]
    with pytest.raises(ValueError, match='model="all" compares the models on one scene'):
        jc.solve(mu=np.array([0.2, 0.3]), model="all")


def test_arrays_beyond_the_cost_bound_are_refused_before_any_work():
    """A broadcast of 2^40 pushes once ran on for hours with Ctrl-C ignored."""
    huge = np.broadcast_to(np.array(0.3), (2**40,))
    with pytest.raises(ValueError, match=r"the memory of 1099511627776 pushes would take about"):
        jc.solve(mu=huge)
    with pytest.raises(ValueError, match=r"2000000 pushes of the simulation by RADAU5, about .* "
                                         r"each, would take about 21 min of one core, over the "
                                         r"limit of 10 min \(set by mu\)"):
        jc.solve(model="dynamics", mu=np.full(2_000_000, 0.3))
    with pytest.raises(ValueError, match=r"invalid quantiles = 1000000 values: give at most 1000"):
        jc.solve(mu=jc.normal(0.3, 0.03), quantiles=np.linspace(0.01, 0.99, 1_000_000))


def test_arrays_warn_of_a_likely_unit_mistake_as_single_values_do():
    with pytest.warns(UserWarning, match=r"^radius_mm = 0.4 mm is under 0.5 mm.*the first such "
                                         r"push: index 0\)") as w:
        jc.solve(radius_mm=np.array([0.4, 0.41]))
    assert w[0].filename == __file__
    with pytest.warns(UserWarning, match=r"the first such push: index \(1, 0\)"):
        jc.solve(mu=np.array([[0.2], [3.0]]), radius_mm=np.array([10.0, 12.0]))
    # The scene the arrays start from holds the default radius (10 mm), longer than this palm:
    # no push has a palm shorter than its disc, so nothing is said.
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        jc.solve(radius_mm=np.array([5.0, 6.0]), palm_length_mm=8)
        jc.solve(mu=np.linspace(0.1, 0.5, 10_000))


def test_array_answers_pickle_and_the_rest_say_what_to_send():
    got = jc.solve(mu=np.linspace(0.1, 0.5, 7), radius_mm=12.5)
    back = pickle.loads(pickle.dumps(got))
    for name in ["status_code", "theta_jam_deg", "x_jam_mm", "past_palm_x_jam_mm"]:
        np.testing.assert_array_equal(getattr(back, name), getattr(got, name))
    assert back.model == got.model
    assert back.inputs.keys() == got.inputs.keys()
    assert back.inputs["radius_mm"] == 12.5
    for obj in [jc.Range(0.1, 0.3), jc.normal(0.2, 0.03), jc.lognormal(40, 0.1)]:
        assert repr(pickle.loads(pickle.dumps(obj))) == repr(obj)
    for obj in [jc.solve(mu=0.3), jc.solve(mu=jc.Range(0.1, 0.3)), jc.vlocator()]:
        with pytest.raises(TypeError, match=r"does not pickle: return its .to_dict\(\)"):
            pickle.dumps(obj)


def test_the_functions_pickle_as_their_names():
    """Dask and multiprocessing send a function to a worker by pickling it: each of the
    package's functions pickles as its name and comes back as itself."""
    for name, _ in jc._jamchart._functions():
        f = getattr(jc, name)
        assert pickle.loads(pickle.dumps(f)) is f, name


def test_positional_arguments_are_taken_as_a_def_takes_them():
    """The functions are the module's own, not Python defs: each takes its positional
    arguments by position or by name, and refuses others in Python's words."""
    with pytest.raises(TypeError, match=r"^solve\(\) takes no positional arguments \(give each "
                                        r"value by its keyword\) but 1 was given$"):
        jc.solve(0.3)
    with pytest.raises(TypeError, match=r"^render\(\) takes 1 positional argument \(scene\) but "
                                        r"0 were given$"):
        jc.render(radius_mm=12)
    with pytest.raises(TypeError, match=r"^render\(\) takes 1 positional argument \(scene\) but "
                                        r"2 were given$"):
        jc.render("fig3", "fig4")
    with pytest.raises(TypeError, match=r"^design\(\) missing required keyword argument: "
                                        r"'x_target_mm'$"):
        jc.design(radius_mm=12)
    by_name = jc.render(scene="fig3", radius_mm=12)
    assert by_name.svg == jc.render("fig3", radius_mm=12).svg


def test_an_array_answer_leaves_out_the_settings_its_arrays_vary():
    got = jc.solve(mu=np.array([0.2, 0.3]), radius_mm=12.5)
    assert "mu_ground" not in got.inputs and "mu_palm" not in got.inputs
    assert got.inputs["radius_mm"] == 12.5
    table = got.to_pandas()
    assert list(table["radius_mm"]) == [12.5, 12.5]
    assert list(table["mass_kg"]) == [1.0, 1.0]
    assert "mu_ground" not in table.columns
    pushed = jc.solve(mass_kg=np.array([0.5, 1.0]), push_ratio=5)
    assert "force_n" not in pushed.inputs


def test_a_chart_prints_on_paper_and_in_greys(tmp_path, cli):
    chart = jc.render("universal")
    chart.save(tmp_path / "a4.pdf", paper="a4")
    cli("render", "universal", "--format", "pdf", "--paper", "a4", "--out", str(tmp_path / "cli"))
    assert (tmp_path / "a4.pdf").read_bytes() == (tmp_path / "cli" / "universal.pdf").read_bytes()
    with pytest.raises(ValueError, match="invalid paper = a3"):
        chart.save(tmp_path / "a3.pdf", paper="a3")
    with pytest.raises(ValueError, match="paper is for a PDF"):
        chart.save(tmp_path / "x.png", paper="a4")
    grey = jc.render("fig3", style="print")
    assert grey.svg == jc.render("fig3", set={"style": "print"}).svg
    assert grey.svg != jc.render("fig3").svg


def test_render_takes_the_ranges_and_distributions_the_cli_takes():
    by_object = jc.render("universal", mu=jc.Range(0.12, 0.3))
    by_text = jc.render("universal", mu="0.12:0.3")
    assert by_object.svg == by_text.svg
    chart = jc.render("jam-probability", mu=jc.normal(0.21, 0.03))
    assert b"0.21" in chart.svg


def test_help_speaks_keywords_not_flags():
    doc = jc.solve.__doc__
    assert "--mu-ground" not in doc and "--mu-palm" not in doc
    assert "mu_ground or mu_palm given as well take precedence" in doc
