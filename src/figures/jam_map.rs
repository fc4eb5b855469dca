//! The jam map (Fig. 3): where the disc jams over a parameter and the palm angle.
//!
//! The statics margin mu_g R_n - R_t is evaluated on the grid (x: the scene parameter, y: the
//! palm angle theta); its sign is the region of each cell. The boundary is the model's
//! theta_jam at every column, and the read-off its jam at the scene's own value.

use serde::{Deserialize, Serialize};

use super::cells::{self, CellsTable, HasCells};
use super::models::{self, Models};
use super::{At, DataFormat, Figure, FigureData, Input};
use crate::csv_out::Column;
use crate::error::{Error, Result};
use crate::grid::{GridAxis, GridRequest, GridResult, Quantity};
use crate::models::ModelKind;
use crate::scene::Param;
use crate::scene::SceneParams;

/// What a jam map draws (`layers`, default all).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum JamMapLayer {
    /// The jam and slide regions from the sign of the margin grid.
    Regions,
    /// The closed-form boundary theta_jam(parameter).
    Boundary,
    /// The disc position x = r cot(theta/2) as a right-hand scale.
    PositionScale,
    /// The read-off construction, lines 1-3, at the scene's value of the x parameter.
    ReadOff,
}

/// `[chart]` keys of `kind = "jam_map"`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct JamMapSettings {
    /// The horizontal axis: any scene parameter but the radius (the position scale needs one r).
    pub x_axis: GridAxis,
    /// The vertical axis: `param = "theta_deg"`, the palm angle in deg.
    pub y_axis: GridAxis,
    /// The layers to draw (default: all).
    #[serde(default = "all_layers")]
    pub layers: Vec<JamMapLayer>,
    /// The model whose jam points are drawn (default: statics; the margin of a jam map's
    /// regions is always the statics').
    #[serde(default)]
    pub model: ModelKind,
    /// The band of an uncertain input not on the axes (`--set force_n=30:50`, or a range in
    /// the scene's `[scene]`): the regions at the box's earliest-jam and latest-jam corners,
    /// cells whose verdict differs between them their own class `uncertain`, and the jam
    /// region's boundary at both corners (default: none; the built-in scenes have none).
    ///
    /// Exact by monotonicity: at a cell (parameter, theta) the disc is held iff theta lies on
    /// the jam side of theta_jam, and theta_jam is monotone in every uncertain input (the
    /// proof is in [`crate::statics`]), so a cell's verdict at every value of the box lies
    /// between its verdicts at the two corners.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub band: Option<super::band::Band>,
}

fn all_layers() -> Vec<JamMapLayer> {
    use JamMapLayer::*;
    vec![Regions, Boundary, PositionScale, ReadOff]
}

/// A cell's region as the cells CSV writes it; a cell holds its index here.
pub const REGIONS: &[&str] = &["jam", "slide", "uncertain", "beyond_reach"];
/// The indices in [`REGIONS`].
pub(crate) const JAM: u8 = 0;
pub(crate) const SLIDE: u8 = 1;
pub(crate) const UNCERTAIN: u8 = 2;
pub(crate) const BEYOND_REACH: u8 = 3;

const CELLS: &str = "chart.x_axis.count * chart.y_axis.count";

impl Figure for JamMapSettings {
    type Data = JamMapData;

    fn param_axes(&self) -> Vec<(&'static str, GridAxis)> {
        vec![("x_axis", self.x_axis), ("y_axis", self.y_axis)]
    }

    /// The read-off lines mark the scene's value of the x parameter.
    fn marks_scene_value(&self) -> bool {
        self.has(JamMapLayer::ReadOff)
    }

    /// Adds the read-off layer when the scene's layers leave it out.
    fn enable_read_off(&mut self) -> bool {
        if !self.has(JamMapLayer::ReadOff) {
            self.layers.push(JamMapLayer::ReadOff);
        }
        true
    }

    /// Checks the axes against the scene.
    fn validate(&self, input: &Input) -> Result<()> {
        if self.y_axis.param != Param::ThetaDeg {
            return Err(Error::invalid(
                "chart.y_axis.param",
                self.y_axis.param.as_str(),
                "a jam map's y axis is theta_deg",
            ));
        }
        if matches!(self.x_axis.param, Param::ThetaDeg | Param::RadiusMm) {
            return Err(Error::invalid(
                "chart.x_axis.param",
                self.x_axis.param.as_str(),
                "a jam map's x axis is a scene parameter other than radius_mm",
            ));
        }
        self.request(&input.params).validate()
    }

    fn check_size(&self, _input: &Input) -> Result<()> {
        let cells = self.x_axis.count as f64 * self.y_axis.count as f64;
        crate::limits::check_items(CELLS, cells, crate::limits::JAM_MAP_CELL)
    }

    /// Computes what the layers need, and nothing else.
    fn compute(&self, input: &Input, models: &dyn Models) -> Result<JamMapData> {
        let p = input.params;
        let model = self.model.with(&input.min_norm, &input.dynamics);
        let margins = |q: &SceneParams| {
            let g = models::evaluate(models, &model, &self.request(q))?;
            Ok::<_, Error>(g.margin_n.unwrap_or_default())
        };
        let cells = match self.has(JamMapLayer::Regions) {
            true => {
                let g = models::evaluate(models, &model, &self.request(&p))?;
                // With a band, the margins at its two corners: the disc is held at every
                // value of the box where the smaller is >= 0, at some where the larger is.
                let corners = match &self.band {
                    Some(b) => Some([margins(&b.earliest)?, margins(&b.latest)?]),
                    None => None,
                };
                Some(JamMapCells::new(g, corners, &p, self.x_axis.param))
            }
            false => None,
        };
        let param = self.x_axis.param;
        let boundary = match self.has(JamMapLayer::Boundary) {
            true => {
                let xs = self.x_axis.values();
                let points = models::along(models, &model, &p, param, &xs)?;
                xs.into_iter()
                    .zip(points)
                    .map(|(value, point)| At {
                        params: [param],
                        at: [value],
                        point,
                    })
                    .collect()
            }
            false => Vec::new(),
        };
        let read_off = match (self.has(JamMapLayer::ReadOff), param.get(&p)) {
            (true, Some(value)) => Some(At {
                params: [param],
                at: [value],
                point: models.jam_point(&model, &p)?,
            }),
            _ => None,
        };
        Ok(JamMapData {
            params: p,
            settings: self.clone(),
            read_off,
            boundary,
            cells,
        })
    }
}

impl JamMapSettings {
    fn request(&self, base: &SceneParams) -> GridRequest {
        GridRequest {
            base: *base,
            x: self.x_axis,
            y: self.y_axis,
            quantities: vec![Quantity::MarginN],
        }
    }

    /// Whether layer `l` is drawn.
    pub fn has(&self, l: JamMapLayer) -> bool {
        self.layers.contains(&l)
    }
}

/// The computed jam map: its serde form is its data file (the cells go to the CSV beside it,
/// summarised under `cells`).
#[derive(Debug, Clone, Serialize)]
pub struct JamMapData {
    /// The scene's parameters.
    pub params: SceneParams,
    /// The settings it was computed with (axes, layers, model, band).
    #[serde(flatten)]
    pub settings: JamMapSettings,
    /// The model's jam at the scene's own x value (with the read-off layer).
    pub read_off: Option<At<1>>,
    /// The model's jam at each x sample (with the boundary layer).
    pub boundary: Vec<At<1>>,
    /// The margin grid and each cell's region (with the regions layer).
    #[serde(serialize_with = "cells::summary")]
    pub cells: Option<JamMapCells>,
}

impl FigureData for JamMapData {
    const FORMAT: DataFormat = DataFormat::Json;
    const CELLS: bool = true;

    fn cells(&self) -> Option<CellsTable<'_>> {
        self.cells.as_ref().map(HasCells::table)
    }
}

/// A jam map's cells (x fastest): the statics margin and each cell's region.
#[derive(Debug, Clone)]
pub struct JamMapCells {
    /// The x parameter's name and samples.
    pub x: (Param, Vec<f64>),
    /// The palm angles in deg.
    pub theta_deg: Vec<f64>,
    /// The statics margin mu_g R_n - R_t in N (>= 0: the ground holds the disc).
    pub margin_n: Vec<f64>,
    /// With a band, the margins at its earliest-jam and latest-jam corners, in N.
    pub corner_margins_n: Option<[Vec<f64>; 2]>,
    /// Each cell's region, as its index in [`REGIONS`]: jam, slide, uncertain (a band's
    /// corners disagree) or beyond_reach (the palm's contact would lie past its end).
    pub region: Vec<u8>,
}

impl JamMapCells {
    fn new(g: GridResult, corners: Option<[Vec<f64>; 2]>, p: &SceneParams, param: Param) -> Self {
        let margin_n = g.margin_n.unwrap_or_default();
        // The palm cannot reach the disc below the reach angle of the column's scene,
        // whatever the margin.
        let reach_deg: Vec<f64> = g
            .x_values
            .iter()
            .map(|v| param.apply(*p, *v).reach_angle().to_degrees())
            .collect();
        let class = |beyond: bool, lo: f64, hi: f64| match (beyond, lo >= 0.0, hi >= 0.0) {
            (true, _, _) => BEYOND_REACH,
            (false, true, _) => JAM,
            (false, false, true) => UNCERTAIN,
            (false, false, false) => SLIDE,
        };
        // Row by row, each a loop of its own: one iterator over every cell, with the band's
        // corners matched in each, was three quarters of the jam map's computing.
        let nx = reach_deg.len();
        let mut region = Vec::with_capacity(margin_n.len());
        for (iy, t) in g.y_values.iter().enumerate() {
            let cells = iy * nx..(iy + 1) * nx;
            match &corners {
                Some([e, l]) => region.extend(
                    (reach_deg.iter().zip(&e[cells.clone()]).zip(&l[cells]))
                        .map(|((r, e), l)| class(t < r, e.min(*l), e.max(*l))),
                ),
                None => region.extend(
                    (reach_deg.iter().zip(&margin_n[cells])).map(|(r, m)| class(t < r, *m, *m)),
                ),
            }
        }
        JamMapCells {
            x: (param, g.x_values),
            theta_deg: g.y_values,
            margin_n,
            corner_margins_n: corners,
            region,
        }
    }

    /// The number of x samples.
    pub fn nx(&self) -> usize {
        self.x.1.len()
    }

    /// The number of palm angles.
    pub fn ny(&self) -> usize {
        self.theta_deg.len()
    }

    /// The flat index of cell (ix, iy).
    pub fn index(&self, ix: usize, iy: usize) -> usize {
        iy * self.nx() + ix
    }
}

impl HasCells for JamMapCells {
    fn table(&self) -> CellsTable<'_> {
        let mut columns = vec![
            (
                "region",
                Column::Words {
                    words: REGIONS,
                    of: &self.region,
                },
            ),
            ("margin_n", Column::Dense(&self.margin_n)),
        ];
        if let Some([e, l]) = &self.corner_margins_n {
            columns.push(("earliest_margin_n", Column::Dense(e)));
            columns.push(("latest_margin_n", Column::Dense(l)));
        }
        let axes = [
            (self.x.0.as_str(), &self.x.1[..]),
            (Param::ThetaDeg.as_str(), &self.theta_deg[..]),
        ];
        CellsTable::new(axes, &columns)
    }
}
