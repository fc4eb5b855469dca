//! The package's keywords and docstrings, made from the settings' one declaration: the
//! signatures `help(jamchart.solve)` shows, the parameters' units, defaults and valid values.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use crate::scene::Param;
use crate::settings::{self, Decl, Kind};

/// The functions whose keywords are declared settings.
const FUNCTIONS: [&str; 4] = ["solve", "render", "design", "vlocator"];

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
    let details = match d.details() {
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
            d.summary()
        ),
    }
}

/// What a scene parameter of `solve` takes.
const SCENE_VALUES: &str = "float or array_like";
/// ... and one that takes a range or a distribution too.
const UNCERTAIN_VALUES: &str = "float, array_like, (low, high) or Distribution";

/// The scene's parameters as keywords (`mu` ... `palm_offset_mm`, `push_ratio`).
fn scene_keywords(arrays: bool) -> Vec<Keyword> {
    Param::all()
        .filter(|p| *p != Param::ThetaDeg)
        .map(|p| {
            let d = p.decl();
            let values = match (arrays, d.uncertain) {
                (true, true) => UNCERTAIN_VALUES,
                (true, false) => SCENE_VALUES,
                (false, true) => "float, (low, high) or Distribution",
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

/// The keywords of `function`, in the order of its signature.
fn keywords_of(function: &str) -> Option<Vec<Keyword>> {
    let models: Vec<&str> = crate::models::ModelKind::ALL
        .iter()
        .map(|k| k.as_str())
        .collect();
    let model_type = format!(
        "Literal[{}]",
        models
            .iter()
            .map(|m| format!("{m:?}"))
            .collect::<Vec<_>>()
            .join(", ")
    );
    let model = own(
        "model",
        &format!(
            "{{{}}}",
            models
                .iter()
                .map(|m| format!("{m:?}"))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        Some("\"statics\""),
        "The model that answers: the closed-form statics (corrected Eq. 1-2), the minimum-norm \
         contact forces (a convex program), or the dynamic simulation (its `method` and drive \
         `mode` below; `method=\"nonsmooth\"` is the fast one).",
    );
    let model = typed(model, &model_type);
    Some(match function {
        "solve" => {
            let mut all = vec![model];
            all.extend(scene_keywords(true));
            all.extend(model_keywords());
            all.extend([
                typed(
                    own(
                        "before_mm",
                        "float or sequence of float",
                        Some("()"),
                        "With a distributed input: positions x in mm for P(x_jam < x), the \
                     probability that the disc jams before x.",
                    ),
                    "Union[float, Sequence[float]]",
                ),
                typed(
                    own(
                        "quantiles",
                        "sequence of float",
                        Some("(0.05, 0.5, 0.95)"),
                        "With a distributed input: the probabilities q in (0, 1) of the quantiles \
                     of x_jam.",
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
                        "Seed of the Monte Carlo samples: the same seed gives the same answer on \
                     any number of threads.",
                    ),
                    "int",
                ),
            ]);
            all
        }
        "render" => {
            let mut all = vec![
                typed(
                    own(
                        "read_off",
                        "dict of str to float or None",
                        Some("None"),
                        "Read every map and sweep off at your own value, e.g. {\"mu\": 0.27}: the \
                     chart draws its read-off there (render --read-off mu=0.27).",
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
            ];
            all.extend(
                scene_keywords(false)
                    .into_iter()
                    .filter(|k| k.name != "push_ratio"),
            );
            all.extend(model_keywords());
            all
        }
        "design" => {
            let mut all = vec![typed(
                own(
                    "x_target_mm",
                    "float",
                    None,
                    "Target disc position x in mm (from the hinge): carry the part at least this \
                 far; above x(90 deg) = r + h.",
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
        "vlocator" => {
            let mut all = vec![
                typed(
                    own(
                        "included_angle_deg",
                        "float or None",
                        Some("None"),
                        "Included angle of a symmetric V in deg, in (0, 180) (None: 90 deg, or \
                     with a range no V of your own is judged).",
                    ),
                    "Optional[float]",
                ),
                typed(
                    own(
                        "flank_angles",
                        "(float, float) or None",
                        Some("None"),
                        "Flank angles a1, a2 above the horizontal in deg (left, right), each in \
                     [0, 180) with a1 + a2 < 180.",
                    ),
                    "Optional[Tuple[float, float]]",
                ),
            ];
            all.extend(
                settings::locator_family()
                    .filter(|d| d.flag.is_some())
                    .map(|d| declared(d, "float, (low, high) or Distribution")),
            );
            all
        }
        _ => return None,
    })
}

/// The opening of each function's docstring.
fn intro(function: &str) -> &'static str {
    match function {
        "solve" => {
            "Where a push jams: theta_jam (deg) and x_jam (mm) of one scene, of numpy arrays of \
             scenes, or over a range or distribution of inputs.\n\n\
             Every keyword is a setting of `jamchart settings`, under its TOML key; one left \
             out keeps its default (the paper's scene). A scene parameter takes a number, an \
             array (all arrays broadcast together by numpy's rules; the answers have their \
             shape and are computed in parallel with the GIL released), a range (low, high) \
             (the answer's interval over it, as `solve --mu 0.12:0.3`) or a distribution \
             (jamchart.normal, uniform, lognormal: probabilities and quantiles as well). The \
             models' settings take one value each.\n\n\
             Returns\n-------\n\
             Solution\n    For single values: status (str, one of jamchart.STATUSES), \
             theta_jam_deg and x_jam_mm (float, NaN where the model gives none), and record \
             (the model's dict, as `solve --format json` prints it).\n\
             Solutions\n    For arrays: status, theta_jam_deg and x_jam_mm as numpy arrays \
             shaped like the broadcast inputs, status_code (uint8 indices into STATUSES), \
             to_pandas().\n\
             BoxAnswer\n    For a range or distribution: theta_jam_deg and x_jam_mm as \
             (min, max), statuses, probability and quantiles, record.\n\n\
             Raises\n------\n\
             ValueError\n    A value outside its valid range (the message names the keyword, \
             the value and the valid values), arrays that do not broadcast.\n\
             TypeError\n    An unknown keyword.\n\n\
             Examples\n--------\n\
             >>> import numpy as np, jamchart as jc\n\
             >>> r = jc.solve(mu=np.linspace(0.1, 0.5, 5), radius_mm=12.5, mass_kg=0.4,\n\
             ...              force_n=40, palm_length_mm=80)\n\
             >>> r.x_jam_mm.shape\n(5,)\n\
             >>> jc.solve(mu=0.3).status\n'jams'\n"
        }
        "render" => {
            "Draws a design chart: a built-in scene by name (jamchart.scenes() lists them) or a \
             scene file by path, with the keywords over the scene's settings.\n\n\
             Returns a Chart: svg and png (bytes), data (the data behind the chart, lists of \
             numbers as numpy arrays), save(path) (.svg, .png, .pdf, or the data's .json or \
             .csv). In Jupyter the chart shows itself.\n\n\
             Raises ValueError for an unknown scene or a bad value, TypeError for an unknown \
             keyword.\n\n\
             Examples\n--------\n\
             >>> import jamchart as jc\n\
             >>> chart = jc.render(\"universal\", read_off={\"mu\": 0.27}, radius_mm=12, \
             force_n=150)\n\
             >>> chart.save(\"shaft.pdf\")\n"
        }
        "design" => {
            "The inverse questions of `jamchart design`: the least push that carries the part \
             to x_target_mm (over the box of any ranges given), the palm length it needs, and \
             each answer checked by the nonsmooth simulation (force drive).\n\n\
             Returns the answer as a dict, the JSON `jamchart design --format json` prints.\n"
        }
        "vlocator" => {
            "A disc in a V-block (`jamchart vlocator`): its verdict (held, slips, lifts off, \
             wedged), the flank forces, the holding capacity and the optimum included angle; \
             with a range or distribution, the robust answer over the box.\n\n\
             Returns the answer as a dict, the JSON `jamchart vlocator --format json` prints.\n"
        }
        _ => "",
    }
}

/// The names of `function`'s keywords (none for a function without declared keywords).
pub(super) fn keyword_names(function: &str) -> Vec<&'static str> {
    keywords_of(function)
        .unwrap_or_default()
        .into_iter()
        .map(|k| k.name)
        .collect()
}

/// The keywords of `function` for its Python signature and stubs: (name, default as Python
/// text or None where it has none, type).
#[pyfunction]
pub(super) fn keywords(function: &str) -> PyResult<Vec<(&'static str, Option<String>, String)>> {
    let all = keywords_of(function).ok_or_else(|| unknown_function(function))?;
    Ok(all
        .into_iter()
        .map(|k| (k.name, k.default, k.annotation))
        .collect())
}

/// The docstring of `function`: what it does and returns, then each keyword with its unit,
/// default and valid values.
#[pyfunction]
pub(super) fn doc(function: &str) -> PyResult<String> {
    let all = keywords_of(function).ok_or_else(|| unknown_function(function))?;
    let entries: Vec<String> = all.into_iter().map(|k| k.entry).collect();
    Ok(format!(
        "{}\nParameters\n----------\n{}\n",
        intro(function),
        entries.join("\n")
    ))
}

fn unknown_function(function: &str) -> PyErr {
    PyValueError::new_err(format!(
        "no function {function}: the functions with declared keywords are {}",
        FUNCTIONS.join(", ")
    ))
}
