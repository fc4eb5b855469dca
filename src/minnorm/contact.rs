//! The general contact problem: point contacts, bilateral joints and the external wrench
//! (Eqs. 3, 5, 6), planar or spatial, and its lowering to the matrices both solvers read.

use nalgebra::{DMatrix, DVector, Vector3};

use crate::error::{Error, Result};

/// Which equilibrium rows the problem has.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Space {
    /// Three rows (Fx, Fy, Mz); every position and normal lies in the x-y plane (z = 0).
    /// Friction cones are exact: |f_t| <= mu f_n with f_t along z x n.
    Planar,
    /// The paper's six rows (Fx, Fy, Fz, Mx, My, Mz) of Eq. 5; friction cones are second-order
    /// cones ||(f_t1, f_t2)|| <= mu f_n.
    Spatial,
}

/// A point contact on the body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact {
    /// Contact point in mm, in the problem's frame (moments are taken about its origin).
    pub position_mm: [f64; 3],
    /// Inward normal: the direction in which the contact can push the body. Any finite,
    /// non-zero length; it is normalised.
    pub normal: [f64; 3],
    /// Coulomb friction coefficient, >= 0 (0: a frictionless contact carries f_n only).
    pub mu: f64,
    /// Prescribed normal force in N, if the contact's normal push is given (e.g. a palm pushed
    /// with a known force); its friction stays unknown within |f_t| <= mu f_n.
    pub normal_force_n: Option<f64>,
}

impl Contact {
    /// A contact in the x-y plane at (x, y) mm with inward normal (nx, ny).
    pub fn planar(position_mm: [f64; 2], normal: [f64; 2], mu: f64) -> Self {
        Contact::spatial(
            [position_mm[0], position_mm[1], 0.0],
            [normal[0], normal[1], 0.0],
            mu,
        )
    }

    /// A contact in space.
    pub fn spatial(position_mm: [f64; 3], normal: [f64; 3], mu: f64) -> Self {
        Contact {
            position_mm,
            normal,
            mu,
            normal_force_n: None,
        }
    }

    /// The same contact with its normal push prescribed to `force_n` N.
    pub fn with_normal_force(mut self, force_n: f64) -> Self {
        self.normal_force_n = Some(force_n);
        self
    }
}

/// A bilateral reaction, free in sign. Joint reactions satisfy equilibrium but do not enter
/// the objective: the minimum norm is taken over the contact forces only (Eq. 4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Joint {
    /// A force along `direction` (any non-zero length, normalised) through `position_mm`; its
    /// reaction is reported in N.
    Force {
        /// A point of the force's line of action, in mm.
        position_mm: [f64; 3],
        /// Its direction (normalised here).
        direction: [f64; 3],
    },
    /// A pure moment about `axis` (normalised), reported in N mm; in a planar problem only
    /// the z axis is meaningful (a translational joint that keeps the body from rotating).
    Moment {
        /// The moment's axis (normalised here).
        axis: [f64; 3],
    },
}

/// A wrench: a force in N and a moment in N mm about the frame's origin (Eq. 6).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Wrench {
    /// Force in N.
    pub force_n: [f64; 3],
    /// Moment about the origin in N mm.
    pub moment_nmm: [f64; 3],
}

impl Wrench {
    /// The wrench of `force_n` acting at `point_mm`: [F, r x F] (Eq. 6).
    pub fn force_at(point_mm: [f64; 3], force_n: [f64; 3]) -> Self {
        let m = Vector3::from(point_mm).cross(&Vector3::from(force_n));
        Wrench {
            force_n,
            moment_nmm: m.into(),
        }
    }

    /// The sum of two wrenches about the same origin.
    pub fn plus(self, other: Wrench) -> Self {
        let add = |a: [f64; 3], b: [f64; 3]| [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
        Wrench {
            force_n: add(self.force_n, other.force_n),
            moment_nmm: add(self.moment_nmm, other.moment_nmm),
        }
    }
}

/// Contacts, joints and the external wrench W_e that they must balance (Eq. 3).
#[derive(Debug, Clone, PartialEq)]
pub struct ContactProblem {
    /// Planar or spatial equilibrium.
    pub space: Space,
    /// The point contacts (at least one).
    pub contacts: Vec<Contact>,
    /// Bilateral joint reactions (may be empty).
    pub joints: Vec<Joint>,
    /// External wrench (weight and applied loads) about the origin.
    pub load: Wrench,
}

fn fmt3(v: [f64; 3]) -> String {
    format!("({}, {}, {})", v[0], v[1], v[2])
}

/// Normalises `v`; the error names the key `key()` when it is not finite or has no length
/// (the key is written only then: a grid lowers millions of valid problems).
fn unit(key: impl FnOnce() -> String, v: [f64; 3], space: Space) -> Result<Vector3<f64>> {
    let vec = Vector3::from(v);
    if !v.iter().all(|c| c.is_finite()) {
        return Err(Error::invalid(&key(), fmt3(v), "components must be finite"));
    }
    if space == Space::Planar && v[2] != 0.0 {
        return Err(Error::invalid(
            &key(),
            fmt3(v),
            "a planar problem lies in z = 0",
        ));
    }
    let n = vec.norm();
    let u = vec / n;
    if n > 0.0 && u.iter().all(|c| c.is_finite()) {
        Ok(u)
    } else {
        Err(Error::invalid(
            &key(),
            fmt3(v),
            "a direction needs a non-zero length",
        ))
    }
}

/// The point `p`; the error names the key `key()` when it is not finite or leaves the plane.
fn point(key: impl FnOnce() -> String, p: [f64; 3], space: Space) -> Result<Vector3<f64>> {
    if !p.iter().all(|c| c.is_finite()) {
        return Err(Error::invalid(
            &key(),
            fmt3(p),
            "coordinates must be finite",
        ));
    }
    if space == Space::Planar && p[2] != 0.0 {
        return Err(Error::invalid(
            &key(),
            fmt3(p),
            "a planar problem lies in z = 0",
        ));
    }
    Ok(Vector3::from(p))
}

/// Two unit tangents completing the normal to a right-handed frame (n, t1, t2). In the plane
/// t1 = z x n and t2 is unused.
fn tangents(n: &Vector3<f64>, space: Space) -> [Vector3<f64>; 2] {
    let t1 = match space {
        Space::Planar => Vector3::new(-n.y, n.x, 0.0),
        Space::Spatial => {
            // The axis least aligned with n gives a well-conditioned cross product.
            let a = n.iamin();
            let mut e = Vector3::zeros();
            e[a] = 1.0;
            e.cross(n).normalize()
        }
    };
    let t2 = n.cross(&t1);
    [t1, t2]
}

/// How one contact's variables sit in the lowered problem.
#[derive(Debug, Clone)]
pub(crate) struct ContactCols {
    /// Index of f_n; the tangential components follow it.
    pub start: usize,
    /// Number of tangential components: 0 (frictionless), 1 (planar) or 2 (spatial).
    pub n_tangent: usize,
    pub normal: Vector3<f64>,
    pub tangent: [Vector3<f64>; 2],
    pub mu: f64,
}

/// Kind of a block of cone rows `g . x` (scaled problem).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum ConeKind {
    /// Each row >= 0.
    Nonneg,
    /// Three rows (s0, s1, s2) with ||(s1, s2)|| <= s0.
    Soc3,
}

/// The problem as matrices, scaled so that forces and lever arms are of order one:
/// `eq x = eq_rhs`, each cone block of `cone_rows` in its cone, minimise sum of x_i^2 over the
/// contact variables (`n_contact_vars` first columns).
#[derive(Debug, Clone)]
pub(crate) struct Lowered {
    pub eq: DMatrix<f64>,
    pub eq_rhs: DVector<f64>,
    pub cone_rows: DMatrix<f64>,
    pub cones: Vec<(ConeKind, usize)>,
    pub contacts: Vec<ContactCols>,
    pub n_contact_vars: usize,
    /// Equilibrium rows (3 or 6); prescribed normal forces add rows after them.
    pub n_equilibrium: usize,
    /// Variables scale: a force variable times `force_scale_n` is in N.
    pub force_scale_n: f64,
    /// Lever-arm scale in mm: moment rows are divided by it.
    pub length_scale_mm: f64,
    pub space: Space,
    /// Per joint: whether it is a moment (reported in N mm) or a force (N).
    pub joint_is_moment: Vec<bool>,
    /// Buffers of the lowering, kept so that lowering into the same value again allocates
    /// nothing: each contact's and force joint's point, the prescribed normal forces (column,
    /// N) and each joint's force and moment columns.
    positions: Vec<Vector3<f64>>,
    prescribed: Vec<(usize, f64)>,
    joint_axes: Vec<(Vector3<f64>, Vector3<f64>)>,
}

impl Default for Lowered {
    fn default() -> Self {
        Lowered {
            eq: DMatrix::zeros(0, 0),
            eq_rhs: DVector::zeros(0),
            cone_rows: DMatrix::zeros(0, 0),
            cones: Vec::new(),
            contacts: Vec::new(),
            n_contact_vars: 0,
            n_equilibrium: 0,
            force_scale_n: 1.0,
            length_scale_mm: 1.0,
            space: Space::Planar,
            joint_is_moment: Vec::new(),
            positions: Vec::new(),
            prescribed: Vec::new(),
            joint_axes: Vec::new(),
        }
    }
}

/// `m` as a zero matrix of `rows` x `cols`, in its own buffer when the shape is the same.
fn zeroed(m: &mut DMatrix<f64>, rows: usize, cols: usize) {
    if m.shape() == (rows, cols) {
        m.as_mut_slice().fill(0.0);
    } else {
        *m = DMatrix::zeros(rows, cols);
    }
}

impl ContactProblem {
    /// Checks the input; the error names the contact or joint index and the value.
    pub fn validate(&self) -> Result<()> {
        self.lower().map(|_| ())
    }

    /// Validates and lowers the problem to scaled matrices.
    pub(crate) fn lower(&self) -> Result<Lowered> {
        let mut low = Lowered::default();
        self.lower_into(&mut low)?;
        Ok(low)
    }

    /// [`Self::lower`] into `low`, reusing its buffers (a map lowers millions of problems of
    /// the same shape). On `Err`, `low` is left partly written.
    pub(crate) fn lower_into(&self, low: &mut Lowered) -> Result<()> {
        let space = self.space;
        if self.contacts.is_empty() {
            return Err(Error::invalid(
                "contacts",
                "[]",
                "a contact problem needs at least one contact",
            ));
        }
        let load_f = point(|| "load.force_n".into(), self.load.force_n, Space::Spatial)?;
        let load_m = point(
            || "load.moment_nmm".into(),
            self.load.moment_nmm,
            Space::Spatial,
        )?;
        if space == Space::Planar && (load_f.z != 0.0 || load_m.x != 0.0 || load_m.y != 0.0) {
            return Err(Error::invalid(
                "load",
                format!(
                    "{} N, {} N mm",
                    fmt3(self.load.force_n),
                    fmt3(self.load.moment_nmm)
                ),
                "a planar load has no force along z and no moment about x or y",
            ));
        }

        let cols = &mut low.contacts;
        let positions = &mut low.positions;
        let prescribed = &mut low.prescribed;
        cols.clear();
        positions.clear();
        prescribed.clear();
        let mut next = 0;
        for (i, c) in self.contacts.iter().enumerate() {
            let p = point(
                || format!("contacts[{i}].position_mm"),
                c.position_mm,
                space,
            )?;
            let n = unit(|| format!("contacts[{i}].normal"), c.normal, space)?;
            if !(c.mu.is_finite() && c.mu >= 0.0) {
                return Err(Error::invalid(
                    &format!("contacts[{i}].mu"),
                    c.mu,
                    "friction coefficients are finite and >= 0",
                ));
            }
            if let Some(f) = c.normal_force_n {
                if !(f.is_finite() && f >= 0.0) {
                    return Err(Error::invalid(
                        &format!("contacts[{i}].normal_force_n"),
                        f,
                        "a prescribed normal push is finite and >= 0 N",
                    ));
                }
                prescribed.push((next, f));
            }
            let n_tangent = match (c.mu > 0.0, space) {
                (false, _) => 0,
                (true, Space::Planar) => 1,
                (true, Space::Spatial) => 2,
            };
            cols.push(ContactCols {
                start: next,
                n_tangent,
                normal: n,
                tangent: tangents(&n, space),
                mu: c.mu,
            });
            positions.push(p);
            next += 1 + n_tangent;
        }
        let n_contact_vars = next;

        let joint_axes = &mut low.joint_axes;
        joint_axes.clear();
        low.joint_is_moment.clear();
        for (k, j) in self.joints.iter().enumerate() {
            let (f, m, is_moment) = match *j {
                Joint::Force {
                    position_mm,
                    direction,
                } => {
                    let p = point(|| format!("joints[{k}].position_mm"), position_mm, space)?;
                    let d = unit(|| format!("joints[{k}].direction"), direction, space)?;
                    positions.push(p);
                    (d, p.cross(&d), false)
                }
                Joint::Moment { axis } => {
                    let a = unit(|| format!("joints[{k}].axis"), axis, Space::Spatial)?;
                    if space == Space::Planar && (a.x != 0.0 || a.y != 0.0) {
                        return Err(Error::invalid(
                            &format!("joints[{k}].axis"),
                            fmt3(axis),
                            "a planar moment joint acts about z",
                        ));
                    }
                    (Vector3::zeros(), a, true)
                }
            };
            joint_axes.push((f, m));
            low.joint_is_moment.push(is_moment);
        }

        // Scales: lever arms by the farthest point, forces by the largest load component.
        let length = positions.iter().map(|p| p.norm()).fold(0.0, f64::max);
        let length = if length > 0.0 { length } else { 1.0 };
        let force = prescribed
            .iter()
            .map(|&(_, f)| f)
            .fold(load_f.norm().max(load_m.norm() / length), f64::max);
        let force = if force > 0.0 && force.is_finite() {
            force
        } else {
            1.0
        };

        let n_eq_rows = if space == Space::Planar { 3 } else { 6 };
        let n_vars = n_contact_vars + joint_axes.len();
        let eq = &mut low.eq;
        zeroed(eq, n_eq_rows + prescribed.len(), n_vars);
        let eq_rhs = &mut low.eq_rhs;
        if eq_rhs.len() == eq.nrows() {
            eq_rhs.as_mut_slice().fill(0.0);
        } else {
            *eq_rhs = DVector::zeros(eq.nrows());
        }
        // Writes a column's force part f and moment part m (about the origin, in N mm per N).
        let mut put = |col: usize, f: &Vector3<f64>, m: &Vector3<f64>| match space {
            Space::Planar => {
                eq[(0, col)] = f.x;
                eq[(1, col)] = f.y;
                eq[(2, col)] = m.z / length;
            }
            Space::Spatial => {
                for r in 0..3 {
                    eq[(r, col)] = f[r];
                    eq[(3 + r, col)] = m[r] / length;
                }
            }
        };
        for (c, p) in cols.iter().zip(positions.iter()) {
            put(c.start, &c.normal, &p.cross(&c.normal));
            for k in 0..c.n_tangent {
                put(c.start + 1 + k, &c.tangent[k], &p.cross(&c.tangent[k]));
            }
        }
        for (k, ((f, m), is_moment)) in joint_axes.iter().zip(&low.joint_is_moment).enumerate() {
            // A moment joint's variable is scaled by force * length, so its column is m / length
            // times length: write the axis directly.
            let m = if *is_moment { m * length } else { *m };
            put(n_contact_vars + k, f, &m);
        }
        let rhs_f = -load_f / force;
        let rhs_m = -load_m / (force * length);
        match space {
            Space::Planar => {
                eq_rhs[0] = rhs_f.x;
                eq_rhs[1] = rhs_f.y;
                eq_rhs[2] = rhs_m.z;
            }
            Space::Spatial => {
                for r in 0..3 {
                    eq_rhs[r] = rhs_f[r];
                    eq_rhs[3 + r] = rhs_m[r];
                }
            }
        }
        for (i, &(col, f)) in prescribed.iter().enumerate() {
            eq[(n_eq_rows + i, col)] = 1.0;
            eq_rhs[n_eq_rows + i] = f / force;
        }

        cone_rows(cols, n_vars, &mut low.cone_rows, &mut low.cones);
        low.n_contact_vars = n_contact_vars;
        low.n_equilibrium = n_eq_rows;
        low.force_scale_n = force;
        low.length_scale_mm = length;
        low.space = space;
        Ok(())
    }
}

/// The friction-cone rows of every contact: planar |f_t| <= mu f_n as two linear rows
/// (mu f_n - f_t >= 0, mu f_n + f_t >= 0, which imply f_n >= 0), spatial as a second-order cone
/// (mu f_n, f_t1, f_t2), frictionless as f_n >= 0.
fn cone_rows(
    cols: &[ContactCols],
    n_vars: usize,
    g: &mut DMatrix<f64>,
    cones: &mut Vec<(ConeKind, usize)>,
) {
    let n_rows: usize = cols
        .iter()
        .map(|c| match c.n_tangent {
            0 => 1,
            1 => 2,
            _ => 3,
        })
        .sum();
    zeroed(g, n_rows, n_vars);
    cones.clear();
    let push = |cones: &mut Vec<(ConeKind, usize)>, kind, rows| match cones.last_mut() {
        // Neighbouring non-negative rows form one cone.
        Some((ConeKind::Nonneg, n)) if kind == ConeKind::Nonneg => *n += rows,
        _ => cones.push((kind, rows)),
    };
    let mut r = 0;
    for c in cols {
        let s = c.start;
        match c.n_tangent {
            0 => {
                g[(r, s)] = 1.0;
                push(cones, ConeKind::Nonneg, 1);
                r += 1;
            }
            1 => {
                g[(r, s)] = c.mu;
                g[(r, s + 1)] = -1.0;
                g[(r + 1, s)] = c.mu;
                g[(r + 1, s + 1)] = 1.0;
                push(cones, ConeKind::Nonneg, 2);
                r += 2;
            }
            _ => {
                g[(r, s)] = c.mu;
                g[(r + 1, s + 1)] = 1.0;
                g[(r + 2, s + 2)] = 1.0;
                push(cones, ConeKind::Soc3, 3);
                r += 3;
            }
        }
    }
}
