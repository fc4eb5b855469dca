//! A [`Solution`]'s serde form: the keys every model shares, then the model's own.
//!
//! ```text
//! { "model": "statics" | "min-norm" | "dynamics",
//!   "status", "theta_jam_deg", "x_jam_mm",     every model
//!   ...                                        the model's own keys
//!   "elapsed_s" }
//! ```
//! The statics and the simulation write their solution's fields; the min-norm model its search
//! (solves, iterations, formulation, backend, undetermined solves), the contact forces at the
//! jam and its cross-check; a model that did not run, its reason under `outside_model`. Every
//! front end prints this one form (`solve --format json`, the Python package).

use serde::{Serialize, Serializer};

use super::{Detail, OutsideModel, Solution};
use crate::dynamics::DynamicsSolution;
use crate::minnorm::qp::Backend;
use crate::minnorm::{MinNormCheck, PalmSolution};
use crate::scene::JamStatus;
use crate::statics::StaticsSolution;

impl Serialize for Solution {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let own = match &self.detail {
            Detail::Statics(d) => Own::Statics(d),
            Detail::MinNorm(d) => Own::MinNorm(MinNormRecord::of(d)),
            Detail::Dynamics(d) => Own::Dynamics(d),
            Detail::Outside(why) => Own::Outside(OutsideRecord {
                status: self.status,
                theta_jam_deg: self.theta_jam_deg,
                x_jam_mm: self.x_jam_mm,
                outside_model: why,
            }),
        };
        Doc {
            model: self.model.as_str(),
            own,
            elapsed_s: self.elapsed_s,
        }
        .serialize(s)
    }
}

#[derive(Serialize)]
struct Doc<'a> {
    model: &'static str,
    #[serde(flatten)]
    own: Own<'a>,
    elapsed_s: f64,
}

/// A model's own keys (each begins with the shared status, theta_jam_deg and x_jam_mm).
#[derive(Serialize)]
#[serde(untagged)]
enum Own<'a> {
    Statics(&'a StaticsSolution),
    MinNorm(MinNormRecord),
    Dynamics(&'a DynamicsSolution),
    Outside(OutsideRecord<'a>),
}

#[derive(Serialize)]
struct OutsideRecord<'a> {
    status: JamStatus,
    theta_jam_deg: Option<f64>,
    x_jam_mm: Option<f64>,
    outside_model: &'a OutsideModel,
}

/// The min-norm model's keys: its search and the forces at the jam.
#[derive(Serialize)]
struct MinNormRecord {
    status: JamStatus,
    theta_jam_deg: Option<f64>,
    x_jam_mm: Option<f64>,
    iterations: u32,
    solves: u32,
    formulation: &'static str,
    backend: Backend,
    undetermined_solves: u32,
    contacts_at_jam: Vec<ContactRecord>,
    cross_check: Option<MinNormCheck>,
}

/// One contact's force at the jam, in its normal-tangent frame, in N.
#[derive(Serialize)]
struct ContactRecord {
    contact: &'static str,
    normal_n: f64,
    tangential_n: f64,
    utilisation: f64,
}

impl MinNormRecord {
    fn of(s: &PalmSolution) -> Self {
        let contacts_at_jam = s
            .at_jam
            .iter()
            .flat_map(|sol| {
                sol.forces
                    .iter()
                    .zip(s.formulation.contact_names())
                    .map(|(f, name)| ContactRecord {
                        contact: name,
                        normal_n: f.normal_n,
                        tangential_n: f.tangential_n[0],
                        utilisation: f.utilisation,
                    })
            })
            .collect();
        MinNormRecord {
            status: s.status,
            theta_jam_deg: s.theta_jam_deg,
            x_jam_mm: s.x_jam_mm,
            iterations: s.iterations,
            solves: s.solves,
            formulation: s.formulation.as_str(),
            backend: s.backend,
            undetermined_solves: s.undetermined_solves,
            contacts_at_jam,
            cross_check: s.cross_check,
        }
    }
}
