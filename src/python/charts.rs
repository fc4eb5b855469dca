//! `jamchart.render`: a scene (built-in or a file) with the keywords over its settings, drawn by
//! [`crate::charts::render`]; the [`Chart`] shows itself in a notebook and saves any format.

use std::path::{Path, PathBuf};

use numpy::PyArray1;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyBytes, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};

use super::convert::{Lists, to_python};
use super::keywords::{Distribution, Range, error, scene_param, tuple_refused};
use crate::ask::{Keywords, RenderAnswer, RenderQuestion, Words};
use crate::charts::{self, Formats, Rendered, SceneSource};
use crate::settings;

/// A drawn design chart: its SVG and PNG, the data behind it, and the scene's name and kind.
#[pyclass(frozen, module = "jamchart")]
pub(super) struct Chart {
    rendered: Rendered,
    kind: String,
}

#[pymethods]
impl Chart {
    /// Does not pickle: see [`super::unpicklable`].
    fn __reduce__(&self) -> PyResult<()> {
        Err(super::unpicklable("Chart"))
    }

    /// The scene's name (`universal`, or a scene file's stem).
    #[getter]
    fn name(&self) -> &str {
        &self.rendered.name
    }

    /// The chart kind (`universal`, `jam_map`, `sweep`, ...).
    #[getter]
    fn kind(&self) -> &str {
        &self.kind
    }

    /// The SVG picture, bytes (identical to `jamchart render`'s file).
    #[getter]
    fn svg<'py>(&self, py: Python<'py>) -> Bound<'py, PyBytes> {
        PyBytes::new(py, self.rendered.svg.as_deref().unwrap_or_default())
    }

    /// The PNG picture, bytes (identical to `jamchart render`'s file).
    #[getter]
    fn png<'py>(&self, py: Python<'py>) -> Bound<'py, PyBytes> {
        PyBytes::new(py, self.rendered.png.as_deref().unwrap_or_default())
    }

    /// The data behind the chart: a JSON chart's figure as dicts with its lists of numbers
    /// as float64 numpy arrays (null as NaN), every number as computed (the `.json` file
    /// rounds them to 7 significant digits); a CSV chart's columns as {name: array}.
    #[getter]
    fn data<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        match self.rendered.data.extension {
            "json" => to_python(py, &self.rendered.computed.data(), Lists::Arrays),
            _ => csv_columns(py, &self.rendered.data.bytes),
        }
    }

    /// The data file's format: `json` or `csv`.
    #[getter]
    fn data_format(&self) -> &'static str {
        self.rendered.data.extension
    }

    /// Writes the chart to `path`, by its extension: `.svg`, `.png`, `.pdf` (made from the
    /// SVG, text as outlines), or the data's `.json` / `.csv`. The file is replaced atomically.
    /// A PDF's page is the chart's size (1 px = 1 pt), or with `paper="a4"` or `"letter"` the
    /// sheet, the chart fitted within a 12.7 mm margin (the CLI's `render --paper`).
    #[pyo3(signature = (path, *, paper=None))]
    fn save(&self, py: Python<'_>, path: PathBuf, paper: Option<&str>) -> PyResult<()> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .unwrap_or_default()
            .to_ascii_lowercase();
        let paper = match paper {
            None => None,
            Some(name) => Some(
                name.parse::<charts::output::Paper>()
                    .map_err(|e| PyValueError::new_err(format!("invalid paper = {name}: {e}")))?,
            ),
        };
        if paper.is_some() && ext != "pdf" {
            return Err(PyValueError::new_err(format!(
                "paper is for a PDF, and {} is not one: give a path ending in .pdf",
                path.display()
            )));
        }
        let svg = || self.rendered.svg.clone().unwrap_or_default();
        let bytes = match ext.as_str() {
            "svg" => svg(),
            "png" => self.rendered.png.clone().unwrap_or_default(),
            "pdf" => py
                .detach(|| charts::output::pdf(&svg(), self.rendered.size_px, paper))
                .map_err(PyValueError::new_err)?,
            e if e == self.rendered.data.extension => self.rendered.data.bytes.clone(),
            _ => {
                return Err(PyValueError::new_err(format!(
                    "cannot save {}: give a path ending in .svg, .png, .pdf or .{} (the data)",
                    path.display(),
                    self.rendered.data.extension
                )));
            }
        };
        write(&path, &bytes).map_err(error)
    }

    fn _repr_svg_(&self) -> String {
        String::from_utf8_lossy(self.rendered.svg.as_deref().unwrap_or_default()).into_owned()
    }

    fn _repr_png_<'py>(&self, py: Python<'py>) -> Bound<'py, PyBytes> {
        self.png(py)
    }

    fn __repr__(&self) -> String {
        format!(
            "jamchart.Chart({}, kind {}, data .{})",
            self.rendered.name, self.kind, self.rendered.data.extension
        )
    }
}

/// Writes `bytes` to `path` as `jamchart render` writes its files (a new name or a regular
/// file, replaced atomically).
fn write(path: &Path, bytes: &[u8]) -> crate::error::Result<()> {
    let set = crate::atomic::Set::begin([path])?;
    set.stage_all(&[crate::atomic::Output::bytes(path, bytes)])?;
    set.commit()
}

/// The built-in scenes' names (`jamchart scenes`).
#[pyfunction]
pub(super) fn scenes() -> Vec<String> {
    charts::builtin_scene_names()
}

/// `jamchart.render(scene, *, read_off=None, set=None, **settings)`: see the package's docs.
pub(super) fn render(
    py: Python<'_>,
    scene: PathBuf,
    keywords: Option<&Bound<'_, PyDict>>,
) -> PyResult<Chart> {
    let name = scene.to_string_lossy().into_owned();
    let source = match charts::builtin_scene_names().contains(&name) {
        true => SceneSource::BuiltIn(name),
        false if scene.extension().is_some_and(|e| e == "toml") => SceneSource::File(scene),
        false => {
            return Err(PyValueError::new_err(format!(
                "invalid scene = {name}: not a built-in scene (they are {}) nor a scene file \
                 (NAME.toml)",
                charts::builtin_scene_names().join(", ")
            )));
        }
    };
    let mut given = Keywords::default();
    for (k, v) in keywords.into_iter().flat_map(|d| d.iter()) {
        let key: String = k.extract()?;
        match key.as_str() {
            "read_off" | "set" | "style" if v.is_none() => continue,
            // The ink, a key of the scene file's top level: "colour" or "print" (greys).
            "style" => {
                given.0.insert(key, toml_of(&v)?);
            }
            "read_off" => {
                let mut table = toml::Table::new();
                for (rk, rv) in v.cast::<PyDict>()?.iter() {
                    table.insert(
                        rk.str()?.to_string(),
                        toml::Value::Float(rv.extract::<f64>()?),
                    );
                }
                given.0.insert(key, toml::Value::Table(table));
            }
            "set" => {
                let mut table = toml::Table::new();
                for (sk, sv) in v.cast::<PyDict>()?.iter() {
                    table.insert(sk.extract()?, toml_of(&sv)?);
                }
                given.0.insert(key, toml::Value::Table(table));
            }
            k if scene_param(k).is_some() || settings::find(k).is_some() => {
                if v.is_instance_of::<PyTuple>() {
                    return Err(tuple_refused(k));
                }
                given.0.insert(key, toml_of(&v)?);
            }
            _ => {
                return Err(PyTypeError::new_err(format!(
                    "render() got an unexpected keyword argument '{key}' (jamchart.keywords() \
                     lists the settings; other keys of the scene file go in set={{...}})"
                )));
            }
        }
    }
    let question = RenderQuestion::of(source, given).map_err(error)?;
    let RenderAnswer {
        rendered,
        kind,
        warnings,
    } = py
        .detach(|| question.answer(Formats::Both, Words::Keys))
        .map_err(error)?;
    super::solve::warn(py, warnings)?;
    Ok(Chart { rendered, kind })
}

/// A Python value as the TOML value of a scene file's key.
fn toml_of(v: &Bound<'_, PyAny>) -> PyResult<toml::Value> {
    Ok(if v.is_instance_of::<PyBool>() {
        toml::Value::Boolean(v.extract()?)
    } else if v.is_instance_of::<PyInt>() {
        toml::Value::Integer(v.extract()?)
    } else if v.is_instance_of::<PyFloat>() {
        toml::Value::Float(v.extract()?)
    } else if let Ok(s) = v.cast::<PyString>() {
        toml::Value::String(s.to_cow()?.into_owned())
    } else if let Ok(d) = v.cast::<Distribution>() {
        toml::Value::String(d.get().0.to_string())
    } else if let Ok(r) = v.cast::<Range>() {
        toml::Value::String(r.get().0.to_string())
    } else if v.is_instance_of::<PyList>() || v.is_instance_of::<PyTuple>() {
        let items: Vec<Bound<'_, PyAny>> = v.extract()?;
        toml::Value::Array(items.iter().map(toml_of).collect::<PyResult<_>>()?)
    } else if let Ok(x) = v.extract::<f64>() {
        toml::Value::Float(x)
    } else {
        return Err(PyTypeError::new_err(format!(
            "a scene's setting is a bool, number, str, list, Range or distribution, not {}",
            v.get_type().name()?
        )));
    })
}

/// A CSV's columns as {name: values}: float64 arrays where every cell is a number (empty as
/// NaN), lists of str where not.
fn csv_columns<'py>(py: Python<'py>, bytes: &[u8]) -> PyResult<Bound<'py, PyAny>> {
    let mut reader = csv::Reader::from_reader(bytes);
    let bad = |e: csv::Error| PyValueError::new_err(format!("the chart's data: {e}"));
    let names: Vec<String> = reader
        .headers()
        .map_err(bad)?
        .iter()
        .map(str::to_string)
        .collect();
    let mut cells: Vec<Vec<String>> = vec![Vec::new(); names.len()];
    for row in reader.records() {
        for (column, cell) in cells.iter_mut().zip(row.map_err(bad)?.iter()) {
            column.push(cell.to_string());
        }
    }
    let dict = PyDict::new(py);
    for (name, column) in names.iter().zip(cells) {
        let numbers: Option<Vec<f64>> = column
            .iter()
            .map(|c| match c.as_str() {
                "" => Some(f64::NAN),
                t => t.parse().ok(),
            })
            .collect();
        match numbers {
            Some(v) => dict.set_item(name, PyArray1::from_vec(py, v))?,
            None => dict.set_item(name, column)?,
        }
    }
    Ok(dict.into_any())
}
