"""jamchart.solve on numbers and numpy arrays: the answers the command line gives, shapes and
dtypes as numpy users expect, every model, and the messages of bad input."""

import math
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import jamchart as jc

from conftest import SHAFT, SHAFT_FLAGS

MODELS = ["statics", "min-norm", "dynamics"]


def same(a, b):
    """Equal floats, NaN equal to NaN, None read as NaN (JSON's null)."""
    a = math.nan if a is None else a
    b = math.nan if b is None else b
    return (math.isnan(a) and math.isnan(b)) or a == b


def test_one_push_gives_the_clis_record(cli_json):
    doc = cli_json("solve", "--mu", "0.3", "--radius", "12.5")
    s = jc.solve(mu=0.3, radius_mm=12.5)
    want = doc["results"][0]
    assert isinstance(s, jc.Solution)
    assert s.status == want["status"] == "jams"
    assert s.theta_jam_deg == want["theta_jam_deg"] and s.x_jam_mm == want["x_jam_mm"]
    record = s.record
    assert list(record) == list(want)
    for key in want:
        if key != "elapsed_s":
            assert record[key] == want[key], key
    assert s.inputs == doc["inputs"]
    assert isinstance(s.theta_jam_deg, float) and isinstance(s.status, str)


@settings(max_examples=300, deadline=None)
@given(mu=st.floats(0.0, 5.0), start=st.floats(1.0, 179.0), force=st.floats(0.5, 500.0))
def test_a_scalar_answers_record_agrees_with_its_outcome_and_is_read_once(mu, start, force):
    # The closed form's record (its extras and time) is computed when first read: what it says
    # is what the answer said at once, and reading it again reads the same record.
    s = jc.solve(mu=mu, start_angle_deg=start, force_n=force)
    took = s.elapsed_s
    assert took > 0 and s.elapsed_s == took
    r = s.record
    assert r["model"] == s.model == "statics" and r["status"] == s.status
    assert same(r["theta_jam_deg"], s.theta_jam_deg) and same(r["x_jam_mm"], s.x_jam_mm)
    assert r == s.record and s.to_dict()["results"][0] == r


@pytest.mark.parametrize("model", MODELS)
def test_every_model_answers_as_the_cli(cli_json, model):
    extra = ["--method", "nonsmooth"] if model == "dynamics" else []
    want = cli_json("solve", "--model", model, "--mu", "0.35", *extra)["results"][0]
    kw = {"method": "nonsmooth"} if model == "dynamics" else {}
    s = jc.solve(model=model, mu=0.35, **kw)
    assert s.model == want["model"] == model
    assert s.status == want["status"]
    assert same(s.theta_jam_deg, want["theta_jam_deg"])
    assert same(s.x_jam_mm, want["x_jam_mm"])


def test_min_norm_is_read_in_either_spelling():
    assert jc.solve(model="min_norm", mu=0.3).model == "min-norm"


STATUS_CASES = [
    # (flags, keywords): jams, beyond the palm, too weak, jammed at the start, never jams,
    # outside every model.
    (["--mu", "0.3"], dict(mu=0.3)),
    (["--mu", "0.05", "--palm-length", "80"], dict(mu=0.05, palm_length_mm=80)),
    (["--mu", "0.5", "--force", "1"], dict(mu=0.5, force_n=1)),
    (["--mu", "2", "--start-angle", "60"], dict(mu=2, start_angle_deg=60)),
    (["--mu", "0"], dict(mu=0)),
    (["--start-angle", "120"], dict(start_angle_deg=120)),
]


@pytest.mark.parametrize("flags,keywords", STATUS_CASES)
def test_status_and_nan_agree_with_the_clis_json(cli_json, flags, keywords):
    want = cli_json("solve", *flags)["results"][0]
    one = jc.solve(**keywords)
    assert one.status == want["status"]
    assert same(one.theta_jam_deg, want["theta_jam_deg"])
    assert same(one.x_jam_mm, want["x_jam_mm"])
    # The same push among an array answers the same, bit for bit.
    arrays = {k: np.array([v, v]) for k, v in keywords.items()}
    many = jc.solve(**arrays)
    assert list(many.status) == [want["status"]] * 2
    assert same(float(many.theta_jam_deg[1]), want["theta_jam_deg"])
    assert same(float(many.x_jam_mm[0]), want["x_jam_mm"])


def test_the_statuses_seen_cover_the_cases():
    seen = {jc.solve(**k).status for _, k in STATUS_CASES}
    assert seen == {"jams", "beyond_reach", "too_weak", "jammed_at_start", "never_jams",
                    "outside_model"}
    assert seen <= set(jc.STATUSES)


def test_arrays_broadcast_and_keep_their_shape():
    mu = np.linspace(0.1, 0.5, 4).reshape(4, 1)
    force = np.array([30.0, 40.0, 200.0])
    r = jc.solve(mu=mu, force_n=force, radius_mm=12.5, mass_kg=0.4, palm_length_mm=80)
    assert isinstance(r, jc.Solutions)
    assert r.shape == (4, 3) and len(r) == 4
    for a in (r.theta_jam_deg, r.x_jam_mm):
        assert a.shape == (4, 3) and a.dtype == np.float64
    assert r.status.shape == (4, 3) and r.status_code.dtype == np.uint8
    for i in range(4):
        for j in range(3):
            one = jc.solve(mu=float(mu[i, 0]), force_n=float(force[j]), radius_mm=12.5,
                           mass_kg=0.4, palm_length_mm=80)
            assert r.status[i, j] == one.status
            assert jc.STATUSES[r.status_code[i, j]] == one.status
            assert same(float(r.x_jam_mm[i, j]), one.x_jam_mm)


def test_a_push_past_the_palm_says_where_it_would_jam(cli_json):
    """x_jam_mm is NaN where the palm loses the part past its end; past_palm_x_jam_mm says
    where it would jam on a long enough palm (99.261 mm for the shaft at mu 0.12, as the
    CLI's past_palm), NaN on every other push."""
    r = jc.solve(mu=np.array([0.12, 0.2]), **SHAFT)
    assert list(r.status) == ["beyond_reach", "jams"]
    assert math.isnan(r.x_jam_mm[0])
    record = cli_json("solve", "--mu", "0.12", *SHAFT_FLAGS)["results"][0]
    assert r.past_palm_x_jam_mm[0] == pytest.approx(record["past_palm"]["x_jam_mm"], rel=1e-12)
    assert r.past_palm_x_jam_mm[0] == pytest.approx(99.261, abs=5e-4)
    assert math.isnan(r.past_palm_x_jam_mm[1])
    assert r.past_palm_x_jam_mm.shape == r.x_jam_mm.shape


def test_arrays_that_do_not_broadcast_are_refused_naming_both():
    with pytest.raises(ValueError, match=r"mu has shape \(3,\) and force_n has shape \(4,\)"):
        jc.solve(mu=np.ones(3) * 0.3, force_n=np.ones(4) * 40)


@pytest.mark.parametrize("dtype", [np.float32, np.int64, np.float64])
def test_any_numeric_dtype_is_read_as_float64(dtype):
    mu = np.array([1, 2, 3], dtype=dtype) / (10 if dtype != np.int64 else 1)
    if dtype == np.int64:
        mu = np.array([0, 1, 2], dtype=dtype)
    r = jc.solve(mu=mu)
    want = jc.solve(mu=np.asarray(mu, dtype=np.float64))
    np.testing.assert_array_equal(r.x_jam_mm, want.x_jam_mm)
    assert r.x_jam_mm.dtype == np.float64


def test_lists_non_contiguous_and_zero_dimensional_arrays():
    base = np.linspace(0.1, 0.6, 12)
    strided = base[::3]
    r = jc.solve(mu=strided)
    np.testing.assert_array_equal(r.x_jam_mm, jc.solve(mu=strided.copy()).x_jam_mm)
    np.testing.assert_array_equal(jc.solve(mu=list(strided)).x_jam_mm, r.x_jam_mm)
    zero_d = jc.solve(mu=np.float64(0.3))
    assert isinstance(zero_d, jc.Solution) and zero_d.x_jam_mm == jc.solve(mu=0.3).x_jam_mm


def test_misaligned_and_read_only_arrays_are_read():
    # A dask worker receives its shard as numbers in a byte frame, at any offset: numpy reads
    # them in place (ALIGNED false), and so must solve.
    frame = bytearray(8 * 12 + 1)
    mu = np.frombuffer(memoryview(frame)[1:], dtype=np.float64)
    mu[:] = np.linspace(0.1, 0.6, 12)
    assert not mu.flags["ALIGNED"]
    want = jc.solve(mu=mu.copy(), force_n=40.0).x_jam_mm
    assert np.isfinite(want).sum() > 0
    for given, expected in ((mu, want), (mu[:, None], want[:, None]), (mu[::2], want[::2])):
        np.testing.assert_array_equal(jc.solve(mu=given, force_n=40.0).x_jam_mm, expected)
    read_only = np.linspace(0.1, 0.6, 12)
    read_only.flags.writeable = False
    np.testing.assert_array_equal(jc.solve(mu=read_only, force_n=40.0).x_jam_mm, want)


def test_a_key_given_with_its_alias_wins_for_itself():
    r = jc.solve(mu=np.array([0.3, 0.4]), mu_palm=0.2)
    for i, mu in enumerate([0.3, 0.4]):
        one = jc.solve(mu_ground=mu, mu_palm=0.2)
        assert float(r.x_jam_mm[i]) == one.x_jam_mm


def test_push_ratio_reads_the_mass_of_each_push():
    mass = np.array([0.5, 1.0, 2.0])
    r = jc.solve(mass_kg=mass, push_ratio=20.0)
    for i, m in enumerate(mass):
        assert float(r.x_jam_mm[i]) == jc.solve(mass_kg=m, force_n=20.0 * m * 9.806).x_jam_mm


@pytest.mark.parametrize("model", ["min-norm", "dynamics"])
def test_a_models_map_answers_each_push_as_one_call(model):
    mu = np.array([0.15, 0.3, 0.45])
    kw = {"method": "nonsmooth"} if model == "dynamics" else {}
    r = jc.solve(model=model, mu=mu, **kw)
    assert r.model == model
    for i, m in enumerate(mu):
        one = jc.solve(model=model, mu=float(m), **kw)
        assert r.status[i] == one.status
        # The min-norm column search lands within its bisection's tolerance of one search.
        assert math.isclose(float(r.x_jam_mm[i]), one.x_jam_mm, rel_tol=1e-6)


def test_to_pandas_has_a_row_per_push():
    pd = pytest.importorskip("pandas")
    r = jc.solve(mu=np.array([[0.2, 0.3]]), force_n=np.array([[40.0], [200.0]]))
    df = r.to_pandas()
    assert isinstance(df, pd.DataFrame)
    columns = list(df.columns)
    # The arrays, the settings every push shares, then the answers.
    assert columns[:2] == ["mu", "force_n"]
    assert columns[-4:] == ["status", "theta_jam_deg", "x_jam_mm", "past_palm_x_jam_mm"]
    assert {"radius_mm", "mass_kg", "palm_length_mm"} <= set(columns[2:-4])
    assert not {"mu_ground", "mu_palm"} & set(columns)
    assert len(df) == 4
    np.testing.assert_array_equal(df["x_jam_mm"].to_numpy(), r.x_jam_mm.ravel())


def test_to_pandas_without_pandas_says_what_to_install(monkeypatch):
    import builtins
    import sys

    monkeypatch.setitem(sys.modules, "pandas", None)
    r = jc.solve(mu=np.array([0.2, 0.3]))
    with pytest.raises(ImportError, match="pip install pandas"):
        r.to_pandas()
    assert builtins  # the real import machinery was used


def test_reprs_say_what_was_answered():
    assert repr(jc.solve(mu=0.3)) == \
        "jamchart.Solution(statics: jams, theta_jam_deg=34.206, x_jam_mm=32.500)"
    r = jc.solve(mu=np.array([0.05, 0.3, 0.4]), palm_length_mm=80)
    assert repr(r) == "jamchart.Solutions(statics, shape (3,): beyond_reach 1, jams 2)"
    assert repr(jc.normal(0.2, 0.03)) == "jamchart.normal(0.2, 0.03)"


# Bad input: ValueError with the CLI's message (the parameter, the value, the valid values).
def test_a_bad_value_is_refused_as_the_cli_refuses_it(cli_error):
    cli = cli_error("solve", "--radius", "-1")
    with pytest.raises(ValueError) as e:
        jc.solve(radius_mm=-1)
    assert str(e.value) == "invalid radius_mm = -1: disc radius (mm) must be a finite number > 0"
    assert cli.replace(" (flag --radius)", "") == str(e.value)


def test_a_bad_alias_value_names_the_keyword_given():
    with pytest.raises(ValueError, match=r"^invalid mu = -1: friction coefficient must be a "
                                         r"finite number >= 0$"):
        jc.solve(mu=-1)


def test_a_bad_element_is_named_by_its_index():
    with pytest.raises(ValueError, match=r"invalid mu\[1, 0\] = -0.2: .* must be a finite "
                                         r"number >= 0"):
        jc.solve(mu=np.array([[0.1], [-0.2]]))
    with pytest.raises(ValueError, match=r"invalid force_n\[2\] = NaN: palm push \(N\) must be a finite number > 0"):
        jc.solve(force_n=[40.0, 50.0, float("nan")])


def test_a_models_setting_is_refused_with_its_section(cli_error):
    cli = cli_error("solve", "--model", "dynamics", "--rtol", "-1")
    with pytest.raises(ValueError) as e:
        jc.solve(model="dynamics", rtol=-1)
    assert str(e.value) == cli.replace(" (flag --rtol)", "")
    with pytest.raises(ValueError, match="method = euler: give one of radau5, dopri5, nonsmooth"):
        jc.solve(model="dynamics", method="euler")
    with pytest.raises(ValueError, match="the models are statics, min-norm, dynamics"):
        jc.solve(model="adams")


def test_an_unknown_keyword_is_a_type_error_with_the_nearest():
    with pytest.raises(TypeError, match="unexpected keyword argument 'raduis_mm'; did you mean "
                                        "radius_mm"):
        jc.solve(raduis_mm=10)


def test_arrays_of_non_numbers_and_bools_are_refused():
    with pytest.raises(ValueError, match="mu takes a number or an array of numbers"):
        jc.solve(mu=["a", "b"])
    with pytest.raises(TypeError, match="not a bool"):
        jc.solve(mu=True)
    with pytest.raises(ValueError, match="radius_mm takes a single number; a range or a distribution is taken by mu"):
        jc.solve(radius_mm=jc.Range(10, 12))


def test_a_likely_unit_mistake_warns_at_the_callers_line():
    with pytest.warns(UserWarning, match=r"^radius_mm = 0.01 mm is under 0.5 mm") as w:
        jc.solve(radius_mm=0.01)
    assert w[0].filename == __file__
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        jc.solve(radius_mm=10)


def test_help_answers_with_units_defaults_and_ranges():
    doc = jc.solve.__doc__
    assert "radius_mm : float or array_like, default 10\n" in doc
    assert "In mm; a finite number > 0." in doc
    assert "mu : float, array_like, Range or Distribution, default 0.4" in doc
    assert 'method : {"radau5", "dopri5", "nonsmooth"}, default "radau5"' in doc
    import inspect

    sig = inspect.signature(jc.solve)
    assert sig.parameters["force_n"].default == 200.0
    assert sig.parameters["model"].default == "statics"
    assert all(p.kind == p.KEYWORD_ONLY for p in sig.parameters.values())


def test_the_keywords_are_the_declared_settings(cli):
    """Every scene key and model setting `jamchart settings` lists is a keyword of solve."""
    table = cli("settings").split("Settings of vlocator")[0]
    keys = set()
    for line in table.splitlines():
        cells = [c.strip() for c in line.split("|")]
        if len(cells) > 3 and cells[2].startswith("`"):
            keys.add(cells[2].split("`")[1].split(".")[-1])
    kw = set(jc.keywords("solve"))
    assert keys and keys <= kw
    assert kw - keys == {"model", "push_ratio", "before_mm", "quantiles", "samples", "seed"}


@settings(max_examples=60, deadline=None)
@given(
    mu=st.lists(st.floats(0.0, 1.5), min_size=1, max_size=8),
    force=st.floats(0.5, 500.0),
    start=st.floats(5.0, 90.0),
)
def test_each_element_of_an_array_is_the_single_answer(mu, force, start):
    r = jc.solve(mu=np.array(mu), force_n=force, start_angle_deg=start)
    for i, m in enumerate(mu):
        one = jc.solve(mu=m, force_n=force, start_angle_deg=start)
        assert r.status[i] == one.status
        assert same(float(r.theta_jam_deg[i]), one.theta_jam_deg)
        assert same(float(r.x_jam_mm[i]), one.x_jam_mm)


@settings(max_examples=40, deadline=None)
@given(mu=st.floats(0.05, 0.6), more=st.floats(1.001, 3.0))
def test_more_friction_jams_earlier(mu, more):
    """theta_jam grows with mu (every term of the closed form does), so x_jam falls."""
    a = jc.solve(mu=mu, palm_length_mm=1e6)
    b = jc.solve(mu=mu * more, palm_length_mm=1e6)
    if a.status == b.status == "jams":
        assert b.theta_jam_deg >= a.theta_jam_deg and b.x_jam_mm <= a.x_jam_mm


def test_scalars_give_scalars_and_the_shaft_example_runs():
    mu = np.linspace(0.1, 0.5, 100_000)
    r = jc.solve(mu=mu, **SHAFT)
    assert r.theta_jam_deg.shape == mu.shape
    jams = r.status == "jams"
    assert jams.any() and np.isnan(r.x_jam_mm[~jams]).all()
    assert not np.isnan(r.x_jam_mm[jams]).any()


def test_none_is_a_keywords_default():
    assert jc.solve(push_ratio=None, atol=None, mu=None).x_jam_mm == jc.solve().x_jam_mm


def test_an_empty_array_gives_empty_answers():
    r = jc.solve(mu=np.zeros((0, 3)), force_n=np.array([40.0, 50.0, 60.0]))
    assert r.shape == (0, 3) and r.x_jam_mm.shape == (0, 3) and r.status.shape == (0, 3)


def test_an_array_of_more_dimensions_than_numpy_reads_is_a_value_error():
    # 33 dimensions of one element: numpy 2 makes it; the reader stops at 32.
    many = np.zeros((1,) * 33) + 0.3
    with pytest.raises(ValueError, match="33 dimensions"):
        jc.solve(mu=many)
    assert jc.solve(mu=np.zeros((1,) * 32) + 0.3).x_jam_mm.shape == (1,) * 32


def test_an_array_calls_inputs_are_the_values_passed():
    """`.inputs` of an array call once reported the default part (r 10, m 1, F 200) beside the
    arrays: anyone logging it recorded the wrong part."""
    got = jc.solve(mu=np.array([0.2, 0.3]), radius_mm=12.5, mass_kg=0.4, force_n=40.0)
    assert got.inputs["radius_mm"] == 12.5
    assert got.inputs["mass_kg"] == 0.4 and got.inputs["force_n"] == 40.0
    assert list(got.inputs["mu"]) == [0.2, 0.3]


def test_two_ways_to_set_the_push_are_refused():
    """A push given as force_n and as push_ratio together answered for the ratio's push while
    `.inputs` showed force_n."""
    for keywords in [dict(force_n=np.array([100.0, 200.0]), push_ratio=5),
                     dict(force_n=100.0, push_ratio=np.array([5.0, 6.0])),
                     dict(force_n=100.0, push_ratio=5)]:
        with pytest.raises(ValueError, match="both set the push: give one of them"):
            jc.solve(**keywords)


def test_arrays_of_bools_complex_numbers_or_dates_are_refused():
    for values in [np.array([True, False]), np.array([0.2 + 1j, 0.3]),
                   np.array(["2020-01-01"], dtype="datetime64[D]")]:
        with pytest.raises(ValueError, match="mu takes a number or an array of numbers, not an "
                                             "array of"):
            jc.solve(mu=values)


def test_one_push_prints_the_clis_report(cli):
    got = jc.solve(mu=0.21, radius_mm=12.5, mass_kg=0.4, force_n=40.0, palm_length_mm=80.0)
    want = cli("solve", "--mu", "0.21", "--radius", "12.5", "--mass", "0.4", "--force", "40",
               "--palm-length", "80")
    took = lambda text: [l for l in text.splitlines() if not l.strip().startswith("took")]
    assert took(str(got)) == took(want)
    assert got.to_dict()["results"][0] == got.record


def _outcome(**keywords):
    """What a call gives: its answer's every face (or its exception) and its warnings."""
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        try:
            s = jc.solve(**keywords)
            doc = s.to_dict()
            for r in doc["results"]:
                r.pop("elapsed_s")
            text = "\n".join(l for l in str(s).splitlines() if not l.strip().startswith("took "))
            got = (type(s), repr(s), text, repr(doc), repr(s.inputs), s.status,
                   repr(s.theta_jam_deg), repr(s.x_jam_mm))
        except Exception as e:  # noqa: BLE001 (the exception is the outcome compared)
            got = (type(e), str(e))
    return got, [(w.category, str(w.message), w.lineno) for w in seen]


def test_numbers_of_the_scene_are_answered_as_every_other_call():
    """A call of scene numbers alone is read without the keyword map; a None beside them (the
    keyword's default) takes the general path. Both give the same answer, warnings and
    refusals for every scene keyword, the alias mu beside mu_ground and mu_palm, push_ratio
    beside force_n, and edge values (NaN, both zeros, the least subnormal, 1e308, ints, an
    int beyond a double, numpy scalars, a bool)."""
    keys = [k for k in jc.keywords("solve") if k in (
        "mu", "mu_ground", "mu_palm", "radius_mm", "mass_kg", "force_n", "gravity_m_s2",
        "start_angle_deg", "palm_length_mm", "palm_offset_mm", "push_ratio")]
    assert len(keys) == 11, keys
    keys += ["theta_deg", "raduis_mm"]
    values = [0.3, -0.0, 0.0, math.nan, math.inf, -math.inf, 5e-324, 1e308, -1.0, 7, 0, 90,
              200, 10**400, np.float64(0.25), np.float32(0.5), np.int64(3), True, 179.9]
    calls = [{}]
    calls += [{k: v} for k in keys for v in values]
    calls += [{a: values[i % len(values)], b: values[(i * 5 + 3) % len(values)]}
              for i, (a, b) in enumerate((a, b) for a in keys for b in keys if a != b)]
    answered = 0
    for keywords in calls:
        fast = _outcome(**keywords)
        general = _outcome(**keywords, samples=None)
        assert fast == general, keywords
        answered += fast[0][0] is jc.Solution
    assert answered > 100, answered
