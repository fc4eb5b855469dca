//! The package's functions, registered from one list ([`FUNCTIONS`]): each one's native
//! function, its keywords (made from the settings' one declaration), its docstring and its
//! type stub. A keyword function is the module's own C function with its signature in its
//! docstring ([`super::entry`]); `jamchart/__init__.py` re-exports them, and the stub
//! `jamchart/__init__.pyi` is [`_stub`]'s output (a test compares them).

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use super::entry::keyword_native;
use crate::ask::Words;
use crate::scene::Param;
use crate::settings::{self, Decl, Kind};

/// One keyword of a function: its name, its default as Python text (None: no default shown)
/// and its doc entry (numpydoc: `name : type, default X` and the indented text).
struct Keyword {
    name: &'static str,
    default: Option<String>,
    entry: String,
    /// The type in the package's stubs (`__init__.pyi`).
    annotation: String,
}

/// The keyword `name` with type `ty`, default `default` and doc `text`.
fn own(name: &'static str, ty: &str, default: Option<&str>, text: &str) -> Keyword {
    let shown = default.map_or(String::new(), |d| format!(", default {d}"));
    Keyword {
        name,
        default: default.map(str::to_string),
        entry: format!("{name} : {ty}{shown}\n    {text}"),
        annotation: String::new(),
    }
}

/// `k` with its stub type `annotation`.
fn typed(mut k: Keyword, annotation: &str) -> Keyword {
    k.annotation = annotation.to_string();
    k
}

/// A declared setting as a keyword; `values` says what a scene parameter takes.
fn declared(d: &'static Decl, values: &str) -> Keyword {
    let default = d.default_text();
    let python_default = match d.kind {
        Kind::Choice(_) => format!("{default:?}"),
        Kind::Switch => match default.as_str() {
            "true" => "True".into(),
            _ => "False".into(),
        },
        _ if default.is_empty() => "None".into(),
        _ => default.clone(),
    };
    let quoted: Vec<String> = match d.kind {
        Kind::Choice(names) => names.iter().map(|n| format!("{n:?}")).collect(),
        _ => Vec::new(),
    };
    let annotation = match d.kind {
        Kind::Choice(_) => format!("Literal[{}]", quoted.join(", ")),
        Kind::Switch => "bool".into(),
        Kind::Count => "int".into(),
        Kind::OptionalReal => "Optional[float]".into(),
        _ if values == UNCERTAIN_VALUES => "_UncertainValues".into(),
        _ if values == SCENE_VALUES => "_Values".into(),
        _ if values.contains("Distribution") => "_Uncertain".into(),
        _ => "float".into(),
    };
    let ty = match d.kind {
        Kind::Choice(_) => format!("{{{}}}", quoted.join(", ")),
        Kind::Switch => "bool".into(),
        Kind::Count => "int".into(),
        Kind::OptionalReal => "float or None".into(),
        _ => values.to_string(),
    };
    let unit = match d.unit {
        "" => String::new(),
        "-" => " Unitless;".into(),
        u => format!(" In {u};"),
    };
    let valid = match d.kind {
        Kind::Choice(_) | Kind::Switch => String::new(),
        _ => format!(" {}.", d.check.describe()),
    };
    let sets = match d.sets {
        [] => String::new(),
        keys => format!(" Sets {}.", keys.join(" and ")),
    };
    // A setting's docs name the command line's flags; a Python user gives keywords.
    let details = match Words::Keys.speak(&d.details()) {
        t if t.is_empty() => String::new(),
        t => format!("\n    {}", t.replace('\n', "\n    ")),
    };
    let shown_default = match d.kind {
        Kind::OptionalReal if default.is_empty() => "None (see below)".to_string(),
        _ => python_default.clone(),
    };
    Keyword {
        name: d.key,
        default: Some(python_default),
        annotation,
        entry: format!(
            "{} : {ty}, default {shown_default}\n    {}{unit}{valid}{sets}{details}",
            d.key,
            Words::Keys.speak(&d.summary())
        ),
    }
}

/// What a scene parameter of `solve` takes.
const SCENE_VALUES: &str = "float or array_like";
/// ... and one that takes a range or a distribution too.
const UNCERTAIN_VALUES: &str = "float, array_like, Range or Distribution";

/// The scene's parameters as keywords (`mu` ... `palm_offset_mm`, `push_ratio`).
fn scene_keywords(arrays: bool) -> Vec<Keyword> {
    Param::all()
        .filter(|p| *p != Param::ThetaDeg)
        .map(|p| {
            let d = p.decl();
            let values = match (arrays, d.uncertain) {
                (true, true) => UNCERTAIN_VALUES,
                (true, false) => SCENE_VALUES,
                (false, true) => "float, Range or Distribution",
                (false, false) => "float",
            };
            let mut k = declared(d, values);
            if d.default_text().is_empty() {
                // A derived parameter (push_ratio) has no default of its own.
                k.default = Some("None".into());
                k.entry = k.entry.replacen(", default None", ", optional", 1);
            }
            k
        })
        .collect()
}

/// The min-norm and simulation settings as keywords (single values).
fn model_keywords() -> Vec<Keyword> {
    settings::palm_family()
        .filter(|d| d.section != "scene")
        .map(|d| declared(d, "float"))
        .collect()
}

/// `model`: the model that answers.
fn model_keyword() -> Keyword {
    let quoted: Vec<String> = crate::models::ModelKind::ALL
        .iter()
        .map(|k| format!("{:?}", k.as_str()))
        .collect();
    typed(
        own(
            "model",
            &format!("{{{}}}", quoted.join(", ")),
            Some("\"statics\""),
            "The model that answers: the closed-form statics (corrected Eq. 1-2), the \
             minimum-norm contact forces (a convex program), or the dynamic simulation (its \
             `method` and drive `mode` below; `method=\"nonsmooth\"` is the fast one).",
        ),
        &format!("Literal[{}]", quoted.join(", ")),
    )
}

/// `solve`'s keywords: the model, the scene (arrays, ranges, distributions), the models'
/// settings, a distribution's question.
fn solve_keywords() -> Vec<Keyword> {
    let mut all = vec![model_keyword()];
    all.extend(scene_keywords(true));
    all.extend(model_keywords());
    all.extend([
        typed(
            own(
                "before_mm",
                "float or sequence of float",
                Some("()"),
                "With a distributed input: positions x in mm for P(x_jam < x), the probability \
                 that the disc jams before x.",
            ),
            "Union[float, Sequence[float]]",
        ),
        typed(
            own(
                "quantiles",
                "sequence of float",
                Some("(0.05, 0.5, 0.95)"),
                "With a distributed input: the probabilities q in (0, 1) of the quantiles of \
                 x_jam.",
            ),
            "Sequence[float]",
        ),
        typed(
            own(
                "samples",
                "int or None",
                Some("None"),
                "Monte Carlo samples where the answer is not exact (None: 100000 for the \
                 statics, 2000 for min-norm and dynamics).",
            ),
            "Optional[int]",
        ),
        typed(
            own(
                "seed",
                "int",
                Some("1"),
                "Seed of the Monte Carlo samples: the same seed gives the same answer on any \
                 number of threads.",
            ),
            "int",
        ),
    ]);
    all
}

/// `render`'s keywords: a read-off, any key of the scene file, the scene's and models'
/// settings (single values).
fn render_keywords() -> Vec<Keyword> {
    let mut all = vec![
        typed(
            own(
                "read_off",
                "dict of str to float or None",
                Some("None"),
                "Read every map and sweep off at your own value, e.g. {\"mu\": 0.27}: the chart \
                 draws its read-off there (render --read-off mu=0.27).",
            ),
            "Optional[Mapping[str, float]]",
        ),
        typed(
            own(
                "set",
                "dict of str to value or None",
                Some("None"),
                "Any other key of the scene file by its dotted path, e.g. \
                 {\"chart.x_axis.count\": 51, \"size.width_px\": 2000} (render --set).",
            ),
            "Optional[Mapping[str, Any]]",
        ),
        typed(
            own(
                "style",
                "{\"colour\", \"print\"} or None",
                Some("None"),
                "The ink: \"colour\", or \"print\" in greys and line styles for a black-and-white \
                 printer; None keeps the scene's (render --set style=print).",
            ),
            "Optional[Literal[\"colour\", \"print\"]]",
        ),
    ];
    all.extend(
        scene_keywords(false)
            .into_iter()
            .filter(|k| k.name != "push_ratio"),
    );
    all.extend(model_keywords());
    all
}

/// `design`'s keywords: the target, the scene (ranges and distributions).
fn design_keywords() -> Vec<Keyword> {
    let mut all = vec![typed(
        own(
            "x_target_mm",
            "float",
            None,
            "Target disc position x in mm (from the hinge): carry the part at least this far; \
             above x(90 deg) = r + h.",
        ),
        "float",
    )];
    all.extend(
        scene_keywords(false)
            .into_iter()
            .filter(|k| k.name != "push_ratio"),
    );
    all
}

/// `vlocator`'s keywords: the V's geometry, the locator's settings (ranges).
fn vlocator_keywords() -> Vec<Keyword> {
    let mut all = vec![
        typed(
            own(
                "included_angle_deg",
                "float or None",
                Some("None"),
                "Included angle of a symmetric V in deg, in (0, 180) (None: 90 deg, or with a \
                 range no V of your own is judged).",
            ),
            "Optional[float]",
        ),
        typed(
            own(
                "flank_angles",
                "(float, float) or None",
                Some("None"),
                "Flank angles a1, a2 above the horizontal in deg (left, right), each in [0, 180) \
                 with a1 + a2 < 180.",
            ),
            "Optional[Tuple[float, float]]",
        ),
    ];
    all.extend(
        settings::locator_family()
            .filter(|d| d.flag.is_some())
            .map(|d| declared(d, "float, Range or Distribution")),
    );
    all
}

/// The guide's notebook session (between its `<!-- session -->` marks), the code alone: what
/// `help(jamchart)` ends with.
#[pyfunction]
pub(super) fn _session() -> String {
    let guide = include_str!("../guide.md");
    let block = guide
        .split_once("<!-- session -->")
        .and_then(|(_, rest)| rest.split_once("<!-- /session -->"))
        .map_or("", |(block, _)| block);
    let code = block
        .trim()
        .trim_start_matches("```python")
        .trim_end_matches("```");
    code.trim().to_string()
}

/// How a function of the package is typed in its stub.
enum Stub {
    /// A function without declared keywords: its whole `def` line.
    Plain(&'static str),
    /// A function of declared keywords after `positional` (name: type), one `def` per
    /// overload: the keywords' stub types replaced as it says, its return type, and the
    /// comment after `def name(` (a mypy ignore).
    Keywords {
        positional: &'static [(&'static str, &'static str)],
        overloads: &'static [Overload],
    },
}

/// One overload of a keyword function's stub: type replacements, return type, comment.
type Overload = (
    &'static [(&'static str, &'static str)],
    &'static str,
    &'static str,
);

/// One function of the package: the one place that registers, documents and types it.
pub(super) struct Function {
    /// Its name in `jamchart`.
    pub(super) name: &'static str,
    /// Adds the native function (of the same name) to the extension module.
    add: fn(&Bound<'_, PyModule>) -> PyResult<()>,
    /// Its declared keywords, in the order of its signature (None for a plain function).
    keywords: Option<fn() -> Vec<Keyword>>,
    /// The docstring's opening (a keyword function's; a plain one documents itself).
    intro: &'static str,
    /// Its stub.
    stub: Stub,
}

/// Registers a `#[pyfunction]` by its path.
macro_rules! native {
    ($f:path) => {
        |m: &Bound<'_, PyModule>| m.add_function(pyo3::wrap_pyfunction!($f, m)?)
    };
}

/// The package's functions, in the order of their stubs. A new function is its body (a
/// keyword function's, behind [`keyword_native!`]; a plain one's `#[pyfunction]`), one entry
/// here, and the stub this writes (`__init__.pyi`).
pub(super) const FUNCTIONS: &[Function] = &[
    Function {
        name: "solve",
        add: keyword_native!("solve", |py, _, kw| super::solve::solve(py, kw)),
        keywords: Some(solve_keywords),
        intro: SOLVE,
        stub: Stub::Keywords {
            positional: &[],
            overloads: &[
                (
                    &[("_Values", "float"), ("_UncertainValues", "float")],
                    "Solution",
                    "  # type: ignore[overload-overlap]",
                ),
                (
                    &[("_UncertainValues", "_Values")],
                    "Solutions",
                    "  # type: ignore[overload-overlap]",
                ),
                (&[], "BoxAnswer", "  # type: ignore[overload-overlap]"),
                (
                    &[
                        ("_Values", "float"),
                        ("_UncertainValues", "float"),
                        (
                            "Literal[\"statics\", \"min-norm\", \"dynamics\"]",
                            "Literal[\"all\"]",
                        ),
                    ],
                    "Comparison",
                    "",
                ),
            ],
        },
    },
    Function {
        name: "render",
        add: keyword_native!("render", |py, given, kw| {
            let chart = super::charts::render(py, given[0].extract()?, kw.dict(py)?.as_ref())?;
            Ok(Bound::new(py, chart)?.into_any())
        }),
        keywords: Some(render_keywords),
        intro: RENDER,
        stub: Stub::Keywords {
            positional: &[("scene", "Union[str, \"os.PathLike[str]\"]")],
            overloads: &[(&[], "Chart", "")],
        },
    },
    Function {
        name: "design",
        add: keyword_native!("design", |py, _, kw| {
            Ok(Bound::new(py, super::reports::design(py, kw.dict(py)?.as_ref())?)?.into_any())
        }),
        keywords: Some(design_keywords),
        intro: DESIGN,
        stub: Stub::Keywords {
            positional: &[],
            overloads: &[(&[], "DesignAnswer", "")],
        },
    },
    Function {
        name: "vlocator",
        add: keyword_native!("vlocator", |py, _, kw| {
            Ok(Bound::new(py, super::reports::vlocator(py, kw.dict(py)?.as_ref())?)?.into_any())
        }),
        keywords: Some(vlocator_keywords),
        intro: VLOCATOR,
        stub: Stub::Keywords {
            positional: &[],
            overloads: &[(&[], "VlocatorAnswer", "")],
        },
    },
    Function {
        name: "normal",
        add: native!(super::keywords::normal),
        keywords: None,
        intro: "",
        stub: Stub::Plain("def normal(mean: float, sd: float) -> Distribution: ..."),
    },
    Function {
        name: "uniform",
        add: native!(super::keywords::uniform),
        keywords: None,
        intro: "",
        stub: Stub::Plain("def uniform(low: float, high: float) -> Distribution: ..."),
    },
    Function {
        name: "lognormal",
        add: native!(super::keywords::lognormal),
        keywords: None,
        intro: "",
        stub: Stub::Plain("def lognormal(median: float, sigma: float) -> Distribution: ..."),
    },
    Function {
        name: "scenes",
        add: native!(super::charts::scenes),
        keywords: None,
        intro: "",
        stub: Stub::Plain("def scenes() -> List[str]: ..."),
    },
    Function {
        name: "keywords",
        add: native!(keywords),
        keywords: None,
        intro: "",
        stub: Stub::Plain("def keywords(function: str = \"solve\") -> List[str]: ..."),
    },
];

const SOLVE: &str = "Where a push jams: theta_jam (deg) and x_jam (mm) of one scene, of numpy \
    arrays of scenes, or over a range or distribution of inputs.\n\n\
    Every keyword is a setting of `jamchart settings`, under its TOML key; one left out keeps \
    its default (the paper's scene). A scene parameter takes a number, an array (all arrays \
    broadcast together by numpy's rules; the answers have their shape and are computed in \
    parallel with the GIL released), a Range(low, high) or its text \"low:high\" (the answer's interval over \
    it, as `solve --mu 0.12:0.3`) or a distribution (jamchart.normal, uniform, lognormal: \
    probabilities and quantiles as well). The models' settings take one value each.\n\n\
    Returns\n-------\n\
    Solution\n    For single values: status (str, one of jamchart.STATUSES), theta_jam_deg and \
    x_jam_mm (float, NaN where the model gives none), record (the model's dict, as `solve \
    --format json` prints it), to_dict() (the whole document); str() is the command line's \
    report.\n\
    Solutions\n    For arrays: status, theta_jam_deg and x_jam_mm as numpy arrays shaped like \
    the broadcast inputs (NaN where there is no jam on the palm), past_palm_x_jam_mm (where a \
    beyond_reach push would jam on a long enough palm, NaN elsewhere), status_code (uint8 \
    indices into STATUSES), to_pandas().\n\
    BoxAnswer\n    For a range or distribution: theta_jam_deg and x_jam_mm as (min, max), \
    statuses, probability and quantiles, record, to_dict(); repr() is the one-line verdict, \
    str() the report.\n\
    Comparison\n    For model=\"all\" on one scene: solutions (each model's Solution by name), \
    guidance (which answer to design to, and why), to_pandas() (one row per model), str() the \
    report.\n\n\
    Raises\n------\n\
    ValueError\n    A value outside its valid range (the message names the keyword, the value \
    and the valid values), arrays that do not broadcast.\n\
    TypeError\n    An unknown keyword.\n\n\
    Examples\n--------\n\
    >>> import numpy as np, jamchart as jc\n\
    >>> r = jc.solve(mu=np.linspace(0.1, 0.5, 5), radius_mm=12.5, mass_kg=0.4,\n\
    ...              force_n=40, palm_length_mm=80)\n\
    >>> r.x_jam_mm.shape\n(5,)\n\
    >>> jc.solve(mu=0.3).status\n'jams'\n";

const RENDER: &str = "Draws a design chart: a built-in scene by name (jamchart.scenes() lists \
    them) or a scene file by path, with the keywords over the scene's settings.\n\n\
    Returns a Chart: svg and png (bytes), data (the data behind the chart, lists of numbers as \
    numpy arrays), save(path) (.svg, .png, .pdf, or the data's .json or .csv). In Jupyter the \
    chart shows itself.\n\n\
    Raises ValueError for an unknown scene or a bad value, TypeError for an unknown keyword.\n\n\
    Examples\n--------\n\
    >>> import jamchart as jc\n\
    >>> chart = jc.render(\"universal\", read_off={\"mu\": 0.27}, radius_mm=12, force_n=150)\n\
    >>> chart.save(\"shaft.pdf\")\n";

const DESIGN: &str = "The inverse questions of `jamchart design`: the least push that carries \
    the part to x_target_mm (over the box of any ranges given), the palm length it needs, and \
    each answer checked by the nonsmooth simulation (force drive).\n\n\
    Returns a DesignAnswer: each key of `jamchart design --format json` is an attribute \
    (design, earliest_corner, latest_corner, check_least_push, check_latest_jam, uncertain), \
    to_dict() the whole document; repr() is the one-line verdict, str() the command line's \
    report.\n";

const VLOCATOR: &str = "A disc in a V-block (`jamchart vlocator`): its verdict (held, slips, \
    lifts off, wedged), the flank forces, the holding capacity and the optimum included angle; \
    with a range, the V that works over the whole box.\n\n\
    Returns a VlocatorAnswer: each key of `jamchart vlocator --format json` is an attribute \
    (verdict, forces, capacity, optimum, inputs; over a box: box, design, given_v, \
    standard_v_blocks, inputs), to_dict() the whole document; repr() is the one-line verdict \
    with the mass and load it depends on, str() the command line's report.\n";

/// Adds every function of [`FUNCTIONS`] to the extension module.
pub(super) fn add_all(m: &Bound<'_, PyModule>) -> PyResult<()> {
    FUNCTIONS.iter().try_for_each(|f| (f.add)(m))
}

/// A keyword function of [`FUNCTIONS`] as its callers read it: its positional parameters,
/// its keywords in order with each one's default as Python text (None: required), and its
/// docstring. Made once for every function, at import: the keywords' docs are made from the
/// settings' declarations, 570,000 instructions a function, and a keyword given as None
/// looks its function's names up on every call.
pub(super) struct Declared {
    pub(super) positional: Vec<&'static str>,
    pub(super) keywords: Vec<(&'static str, Option<String>)>,
    /// Neither positional nor required parameters: a call's keywords go to the function as
    /// they are.
    pub(super) bare: bool,
    /// What it does and returns, then each keyword with its unit, default and valid values.
    pub(super) doc: String,
}

/// Keyword function `name` of [`FUNCTIONS`]; None for any other name.
pub(super) fn keyword_function(name: &str) -> Option<&'static Declared> {
    static ALL: std::sync::OnceLock<Vec<(&'static str, Declared)>> = std::sync::OnceLock::new();
    let all = ALL.get_or_init(|| {
        FUNCTIONS
            .iter()
            .filter_map(|f| {
                let Stub::Keywords { positional, .. } = f.stub else {
                    return None;
                };
                let all = (f.keywords?)();
                let entries: Vec<&str> = all.iter().map(|k| k.entry.as_str()).collect();
                let doc = format!(
                    "{}\nParameters\n----------\n{}\n",
                    f.intro,
                    entries.join("\n")
                );
                let keywords: Vec<_> = all.into_iter().map(|k| (k.name, k.default)).collect();
                let bare = positional.is_empty() && keywords.iter().all(|(_, d)| d.is_some());
                let positional = positional.iter().map(|(n, _)| *n).collect();
                let declared = Declared {
                    positional,
                    keywords,
                    bare,
                    doc,
                };
                Some((f.name, declared))
            })
            .collect()
    });
    all.iter().find(|(n, _)| *n == name).map(|(_, d)| d)
}

/// The names of `function`'s keywords (none for a function without declared keywords).
pub(super) fn keyword_names(function: &str) -> Vec<&'static str> {
    keyword_function(function)
        .map_or_else(Vec::new, |d| d.keywords.iter().map(|(k, _)| *k).collect())
}

/// The keywords `function` takes ("solve", "render", "design" or "vlocator"), in order: each
/// is a setting of `jamchart settings` under its TOML key; `help(jamchart.solve)` gives each
/// one's unit, default and valid values.
#[pyfunction]
#[pyo3(signature = (function = "solve"))]
pub(super) fn keywords(function: &str) -> PyResult<Vec<&'static str>> {
    keyword_function(function)
        .map(|d| d.keywords.iter().map(|(k, _)| *k).collect())
        .ok_or_else(|| unknown_function(function))
}

/// The keyword functions' names and positional parameters (what their signatures open with).
#[pyfunction]
pub(super) fn _functions() -> Vec<(&'static str, Vec<&'static str>)> {
    FUNCTIONS
        .iter()
        .filter_map(|f| Some((f.name, keyword_function(f.name)?.positional.clone())))
        .collect()
}

/// The docstring of `function` ([`Declared::doc`]).
#[pyfunction]
pub(super) fn _doc(function: &str) -> PyResult<String> {
    keyword_function(function)
        .map(|d| d.doc.clone())
        .ok_or_else(|| unknown_function(function))
}

fn unknown_function(function: &str) -> PyErr {
    let names: Vec<&str> = FUNCTIONS
        .iter()
        .filter(|f| f.keywords.is_some())
        .map(|f| f.name)
        .collect();
    PyValueError::new_err(format!(
        "no function {function}: the functions with declared keywords are {}",
        names.join(", ")
    ))
}

/// The package's `__all__`: its constants, classes and functions.
pub(super) fn all(classes: &[String]) -> Vec<String> {
    let constants = ["CHART_FORMAT", "STATUSES", "__version__"];
    let mut names: Vec<String> = constants.map(String::from).to_vec();
    names.extend(classes.iter().cloned());
    names.extend(FUNCTIONS.iter().map(|f| f.name.to_string()));
    names
}

/// The package's type stub, `jamchart/__init__.pyi`: the classes ([`super::CLASSES_STUB`]),
/// then every function of [`FUNCTIONS`] with its keywords' types.
#[pyfunction]
pub(super) fn _stub() -> String {
    let mut defs: Vec<String> = Vec::new();
    for f in FUNCTIONS {
        match &f.stub {
            Stub::Plain(line) => defs.push(line.to_string()),
            Stub::Keywords {
                positional,
                overloads,
            } => {
                let all = (f.keywords.expect("a keyword function"))();
                for (replace, returns, comment) in *overloads {
                    let mut lines: Vec<String> = positional
                        .iter()
                        .map(|(name, ty)| format!("    {name}: {ty},"))
                        .collect();
                    lines.push("    *,".into());
                    for k in &all {
                        let ty = replace
                            .iter()
                            .find(|(from, _)| *from == k.annotation)
                            .map_or(k.annotation.as_str(), |(_, to)| to);
                        let default = if k.default.is_some() { " = ..." } else { "" };
                        lines.push(format!("    {}: {ty}{default},", k.name));
                    }
                    let overload = if overloads.len() > 1 {
                        "@overload\n"
                    } else {
                        ""
                    };
                    defs.push(format!(
                        "{overload}def {}({comment}\n{}\n) -> {returns}: ...",
                        f.name,
                        lines.join("\n")
                    ));
                }
            }
        }
    }
    format!("{}\n{}\n", super::CLASSES_STUB, defs.join("\n\n"))
}
