//! Many pushes at once, as columns: N values of one or more scene parameters in, the status,
//! theta_jam and x_jam of each out, written into buffers the caller owns.
//!
//! A binding (numpy arrays) hands its arrays over as they are and gets its answers without a
//! copy; every answer is [`super::solve`]'s, in the same order for any thread count. The
//! closed form answers each push without building a [`super::Solution`] (no clock read, no
//! detail); the other models go through [`super::solve`], min-norm pushes that differ in one
//! parameter only a column at a time ([`super::solve_column`]).

use std::sync::atomic::{AtomicBool, Ordering};

use rayon::prelude::*;

use super::{ModelSpec, outside, solve, solve_column};
use crate::error::{Error, Result};
use crate::scene::{JamStatus, SceneParams};
use crate::scene::{Param, Setter};
use crate::statics;

/// N pushes: a base scene and the parameters that vary, each a column of N values (or of one,
/// taken by every push).
#[derive(Debug, Clone)]
pub struct Pushes<'a> {
    /// The scene every push starts from.
    pub base: SceneParams,
    /// The parameters that vary and their values, in their units (`mu` sets both frictions).
    pub columns: Vec<(Param, &'a [f64])>,
}

/// Where the answers go, one element per push; each slice N long.
#[derive(Debug)]
pub struct Answers<'a> {
    /// The status, as its index in [`JamStatus::NAMES`].
    pub status: &'a mut [u8],
    /// theta_jam in deg, NaN where the model gives none.
    pub theta_jam_deg: &'a mut [f64],
    /// x_jam in mm, NaN where the model gives none.
    pub x_jam_mm: &'a mut [f64],
    /// If asked, where each push answered `beyond_reach` would jam on a long enough palm:
    /// the closed form's x_jam in mm ([`crate::statics::PastPalm`]), NaN for every other
    /// push, so that NaN in `x_jam_mm` keeps meaning "no jam on this palm" and this column
    /// says where the palm lost the part. The simulations and the min-norm search give no
    /// such answer: NaN throughout for those models.
    pub past_palm_x_jam_mm: Option<&'a mut [f64]>,
}

impl Pushes<'_> {
    /// The number of pushes: the longest column (1 without columns).
    pub fn len(&self) -> usize {
        self.columns.iter().map(|(_, v)| v.len()).max().unwrap_or(1)
    }

    /// Whether there is no push (a column of no values).
    pub fn is_empty(&self) -> bool {
        self.columns.iter().any(|(_, v)| v.is_empty())
    }

    /// The unit warnings of these pushes ([`SceneParams::unit_warnings`]), each kind once,
    /// with the first push (its index) that shows it. Each warning is a threshold on one
    /// parameter or a monotone pair of them, so the corners of the columns' box show every
    /// warning any push shows: a box whose corners are all plausible (the usual case) costs
    /// one pass over each column for its ends and no push is built.
    pub fn unit_warnings(&self) -> Vec<(usize, String)> {
        let n = self.len();
        if self.is_empty() || self.validate(n).is_err() {
            return Vec::new();
        }
        let resolved = self.resolved();
        let ends: Vec<(f64, f64)> = self.columns.iter().map(|(_, v)| ends(v)).collect();
        // More than 16 columns (no scene has as many parameters) are checked push by push.
        let corner_warns = ends.len() > 16
            || (0..1u32 << ends.len()).any(|corner| {
                let mut p = self.base;
                for (k, ((param, _), (lo, hi))) in self.columns.iter().zip(&ends).enumerate() {
                    let v = if corner >> k & 1 == 0 { *lo } else { *hi };
                    p = param.apply(p, v);
                }
                !p.unit_warnings().is_empty()
            });
        if !corner_warns {
            return Vec::new();
        }
        let warnings = |i: usize| resolved.scene(self.base, i).unit_warnings();
        // Each kind of warning by the key it opens with, at its first push.
        let mut out: Vec<(usize, String)> = Vec::new();
        let mut start = 0;
        while start < n {
            let seen: Vec<&str> = out.iter().map(|(_, w)| opening(w)).collect();
            let next = (start..n)
                .into_par_iter()
                .with_min_len(CHUNK)
                .find_first(|&i| warnings(i).iter().any(|w| !seen.contains(&opening(w))));
            let Some(i) = next else { break };
            let new: Vec<String> = warnings(i)
                .into_iter()
                .filter(|w| !seen.contains(&opening(w)))
                .collect();
            out.extend(new.into_iter().map(|w| (i, w)));
            start = i + 1;
        }
        out
    }

    /// The columns with the fields each one sets looked up once: a map of 10^6 pushes looked
    /// each column's declaration up by name 10^6 times.
    fn resolved(&self) -> Resolved<'_> {
        let columns = self
            .columns
            .iter()
            .map(|(param, values)| {
                let set = match *param {
                    Param::PushRatio => Sets::PushRatio,
                    p => {
                        let (keys, setters) = p.fields();
                        Sets::Fields(keys, setters)
                    }
                };
                (set, *values)
            })
            .collect();
        Resolved { columns }
    }

    /// Checks the columns' lengths and that each parameter is a scene parameter.
    fn validate(&self, n: usize) -> Result<()> {
        for (param, values) in &self.columns {
            if *param == Param::ThetaDeg {
                return Err(Error::invalid(
                    param.as_str(),
                    "a column",
                    "the palm angle is the state of a push, not a parameter of its scene",
                ));
            }
            if values.len() != n && values.len() != 1 {
                return Err(Error::invalid(
                    param.as_str(),
                    format!("{} values", values.len()),
                    format!("every column has {n} values, or one for every push"),
                ));
            }
        }
        Ok(())
    }
}

/// The least and the greatest of `values`, NaN passed over (as by f64::min), the infinities
/// the wrong way round for none: a longer column's blocks shared among the threads, each
/// block's comparisons in [`ENDS_LANES`] running ends, so that they run in vector lanes (a
/// fold of one pair of ends waits on each comparison: 1.3 ms for 10^6 values).
fn ends(values: &[f64]) -> (f64, f64) {
    const BLOCK: usize = 4096;
    let wider = |(lo, hi): (f64, f64), (l, h): (f64, f64)| {
        (if l < lo { l } else { lo }, if h > hi { h } else { hi })
    };
    let none = (f64::INFINITY, f64::NEG_INFINITY);
    let block_ends = |block: &[f64]| {
        let (mut lo, mut hi) = ([f64::INFINITY; ENDS_LANES], [f64::NEG_INFINITY; ENDS_LANES]);
        let (runs, rest) = block.as_chunks::<ENDS_LANES>();
        for run in runs {
            for j in 0..ENDS_LANES {
                (lo[j], hi[j]) = wider((lo[j], hi[j]), (run[j], run[j]));
            }
        }
        let lanes = lo.into_iter().zip(hi);
        lanes.chain(rest.iter().map(|&x| (x, x))).fold(none, wider)
    };
    // A column of one block is not worth handing to the thread pool.
    if values.len() <= BLOCK {
        return block_ends(values);
    }
    values
        .par_chunks(BLOCK)
        .map(block_ends)
        .reduce(|| none, wider)
}

/// The running ends of a block of [`ends`].
const ENDS_LANES: usize = 8;

/// A warning's key, the word it opens with: warnings of one kind at different pushes differ
/// in their numbers only.
fn opening(warning: &str) -> &str {
    warning.split_whitespace().next().unwrap_or_default()
}

/// What a column sets in a push's scene.
#[derive(Debug, Clone)]
enum Sets {
    /// These fields, to the column's value (an alias sets several), and their setters.
    Fields(&'static [&'static str], Vec<Setter>),
    /// The push as a multiple of the weight: force_n = value m g.
    PushRatio,
}

/// [`Pushes`]'s columns, each with what it sets.
struct Resolved<'a> {
    columns: Vec<(Sets, &'a [f64])>,
}

impl Resolved<'_> {
    /// Whether a column sets the field `key`.
    fn sets(&self, key: &str) -> bool {
        self.columns.iter().any(|(set, _)| match set {
            Sets::Fields(keys, _) => keys.contains(&key),
            Sets::PushRatio => false,
        })
    }

    /// The first push whose scene from `base` is invalid, if any. Each field's check stands
    /// alone ([`SceneParams::validate`]), so a column's values are checked against the fields
    /// they set, one pass over each column; a column of push ratios (a force from the mass
    /// and gravity) is checked push by push.
    fn first_invalid(&self, base: SceneParams, n: usize) -> Option<usize> {
        if base.validate().is_err() {
            return Some(0);
        }
        if self
            .columns
            .iter()
            .any(|(set, _)| matches!(set, Sets::PushRatio))
        {
            return (0..n)
                .into_par_iter()
                .with_min_len(CHUNK)
                .find_first(|&i| self.scene(base, i).validate().is_err());
        }
        let mut first: Option<usize> = None;
        for (set, values) in &self.columns {
            let Sets::Fields(keys, _) = set else { continue };
            let decls: Vec<_> = keys
                .iter()
                .filter_map(|k| crate::settings::find(k))
                .collect();
            for (k, decl) in decls.iter().enumerate() {
                // Fields with the same check (both frictions of `mu`) are one pass.
                if decls[..k].iter().any(|d| d.check == decl.check) {
                    continue;
                }
                let bad = decl.check.first_refused(values);
                // A column of one value is every push's: the first push shows it.
                let bad = bad.map(|i| if values.len() == 1 { 0 } else { i });
                first = match (first, bad) {
                    (Some(a), Some(b)) => Some(a.min(b)),
                    (a, b) => a.or(b),
                };
            }
        }
        first
    }

    /// Push `i`'s scene from `base`: each column's value set in order, as
    /// [`Param::apply`] sets it.
    #[inline]
    fn scene(&self, base: SceneParams, i: usize) -> SceneParams {
        let mut p = base;
        for (set, values) in &self.columns {
            let v = if values.len() == 1 {
                values[0]
            } else {
                values[i]
            };
            match set {
                Sets::Fields(_, setters) => {
                    for set in setters {
                        set(&mut p, v);
                    }
                }
                Sets::PushRatio => p = Param::PushRatio.apply(p, v),
            }
        }
        p
    }
}

/// Closed-form pushes answered together ([`statics::Push`]): four vectors of AVX2's four or two
/// of AVX-512's eight, whose chains of divisions and square roots overlap (with AVX2, 8 lanes
/// and 32 each took a fifth longer; with AVX-512, 8 took 9 % longer and 32 three fifths longer).
const LANES: usize = 16;

/// Pushes answered per task of the thread pool: large enough that a closed-form answer
/// (about 0.1 us) outweighs the task, small enough that 2 threads share a map of 10^4.
const CHUNK: usize = 512;

/// Closed-form pushes answered on the calling thread, not the pool's (about 40 us of answers):
/// a Python call of 1,000 pushes took 49 us through the pool and 19 here, one of 4,000 84 us
/// and 53; from about 6,000 (130 us against 175) the pool's two threads win.
const SERIAL_STATICS: usize = 8 * CHUNK;

/// Answers every push of `pushes` with the model of `spec`, writing into `out`.
///
/// Every scene is checked first: `Err` names the first invalid parameter and value (and
/// nothing is solved), as [`super::solve`] would for that push alone.
pub fn solve_into(spec: &ModelSpec, pushes: &Pushes, out: Answers) -> Result<()> {
    let never = AtomicBool::new(false);
    solve_into_until(spec, pushes, out, &never).map(|_| ())
}

/// How far [`solve_into_until`] went.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Finished {
    /// Every push is answered.
    All,
    /// `stop` was set: the chunks begun before it are answered, the rest of the answers are
    /// left as they were.
    Stopped {
        /// How many pushes were answered.
        answered: usize,
    },
}

/// [`solve_into`] that looks at `stop` before each chunk of the pool's work and leaves the
/// chunks not yet begun once it is set: a caller on another thread (a binding polling for
/// Ctrl-C) ends a long map within one chunk of work per thread (one simulation, a min-norm
/// column, or one chunk of closed-form answers).
pub fn solve_into_until(
    spec: &ModelSpec,
    pushes: &Pushes,
    out: Answers,
    stop: &AtomicBool,
) -> Result<Finished> {
    solve_in_width(spec, pushes, out, stop, Width::widest())
}

/// [`solve_into_until`] with the closed form's chunks in vector width `width` (one the
/// processor has).
fn solve_in_width(
    spec: &ModelSpec,
    pushes: &Pushes,
    out: Answers,
    stop: &AtomicBool,
    width: Width,
) -> Result<Finished> {
    let n = pushes.len();
    let lens = [
        out.status.len(),
        out.theta_jam_deg.len(),
        out.x_jam_mm.len(),
        out.past_palm_x_jam_mm.as_ref().map_or(n, |p| p.len()),
    ];
    if lens.iter().any(|&l| l != n) {
        return Err(Error::invalid(
            "answers",
            format!("{lens:?} elements"),
            format!("each answer buffer holds one element per push ({n})"),
        ));
    }
    pushes.validate(n)?;
    spec.validate()?;
    let resolved = pushes.resolved();
    let scene = |i: usize| resolved.scene(pushes.base, i);
    if let Some(i) = resolved.first_invalid(pushes.base, n) {
        scene(i).validate()?;
    }
    let closed_form = ClosedForm::of(pushes, &resolved, width);
    let chunk = match spec {
        ModelSpec::Statics => CHUNK,
        ModelSpec::MinNorm(_) => column_len(pushes, n),
        // A simulation outweighs any task: spread them one by one.
        ModelSpec::Dynamics { .. } => 1,
    };
    let Answers {
        status,
        theta_jam_deg,
        x_jam_mm,
        past_palm_x_jam_mm,
    } = out;
    let write = |start: usize, chunk: Chunk| -> Result<usize> {
        if stop.load(Ordering::Relaxed) {
            return Ok(0);
        }
        let len = chunk.0.0.0.len();
        // Every model named: a new one is placed here before it compiles.
        let (((s, t), x), past) = match spec {
            // Closed-form answers LANES at a time, written in place.
            ModelSpec::Statics => {
                closed_form.answer_chunk(start, chunk);
                return Ok(len);
            }
            ModelSpec::MinNorm(_) | ModelSpec::Dynamics { .. } => chunk,
        };
        if let Some(past) = past {
            past.fill(f64::NAN);
        }
        let mut put = |k: usize, (st, th, xj): (JamStatus, Option<f64>, Option<f64>)| {
            s[k] = st.index();
            t[k] = th.unwrap_or(f64::NAN);
            x[k] = xj.unwrap_or(f64::NAN);
        };
        // A column of min-norm pushes searches each from its neighbours' answers.
        if let ModelSpec::MinNorm(_) = spec {
            let scenes: Vec<SceneParams> = (start..start + len).map(scene).collect();
            let answers = solve_column(spec, &scenes)?;
            // Every element is written: a binding hands over arrays it has not set.
            if answers.len() != len {
                return Err(Error::Defect(format!(
                    "a min-norm column of {len} pushes gave {} answers",
                    answers.len()
                )));
            }
            for (k, a) in answers.into_iter().enumerate() {
                put(k, (a.status, a.theta_jam_deg, a.x_jam_mm));
            }
            return Ok(len);
        }
        // A simulation, written in place: an answer costs less than collecting it.
        for k in 0..len {
            let s = solve(spec, &scene(start + k))?;
            put(k, (s.status, s.theta_jam_deg, s.x_jam_mm));
        }
        Ok(len)
    };
    // A few closed-form chunks are answered on this thread: handing them to the pool costs
    // more than the answers ([`SERIAL_STATICS`]).
    let serial = matches!(spec, ModelSpec::Statics) && n <= SERIAL_STATICS;
    let answered = if serial {
        write(0, (((status, theta_jam_deg), x_jam_mm), past_palm_x_jam_mm))
    } else {
        let answers = status
            .par_chunks_mut(chunk)
            .zip(theta_jam_deg.par_chunks_mut(chunk))
            .zip(x_jam_mm.par_chunks_mut(chunk));
        match past_palm_x_jam_mm {
            Some(past) => answer_chunks(
                answers.zip(past.par_chunks_mut(chunk).map(Some)),
                chunk,
                write,
            ),
            None => {
                let none = (0..n.div_ceil(chunk)).into_par_iter().map(|_| None);
                answer_chunks(answers.zip(none), chunk, write)
            }
        }
    }?;
    Ok(match answered == n {
        true => Finished::All,
        false => Finished::Stopped { answered },
    })
}

/// One chunk of the answers' slices: status, theta_jam, x_jam, and the past-palm x_jam if
/// asked.
type Chunk<'a> = (
    ((&'a mut [u8], &'a mut [f64]), &'a mut [f64]),
    Option<&'a mut [f64]>,
);

/// Writes each chunk of `chunks` (the `chunk`-th pushes from its index on) and counts the
/// pushes answered: one function for the answers with and without the past-palm column.
fn answer_chunks<'a>(
    chunks: impl IndexedParallelIterator<Item = Chunk<'a>>,
    chunk: usize,
    write: impl Fn(usize, Chunk<'a>) -> Result<usize> + Sync + Send,
) -> Result<usize> {
    chunks
        .enumerate()
        .map(|(c, answers)| write(c * chunk, answers))
        .try_reduce(|| 0, |a, b| Ok(a + b))
}

/// How many min-norm pushes to search as one column: a run of neighbours (a map's column of
/// N / 2 threads' worth, at most 64, so that a search starts near its answer and both threads
/// share the work).
fn column_len(pushes: &Pushes, n: usize) -> usize {
    let varying = pushes.columns.iter().filter(|(_, v)| v.len() > 1).count();
    match varying {
        0 | 1 => n.div_ceil(2).clamp(1, 64),
        _ => 1,
    }
}

/// The vector width a chunk of closed-form answers is compiled for: every width gives the
/// same bits ([`ClosedForm::answer_chunk_in`]), the widest runs fastest.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Width {
    /// The target's baseline: SSE2's two lanes on x86-64.
    Baseline,
    /// AVX2's four lanes a vector.
    #[cfg(target_arch = "x86_64")]
    Avx2,
    /// AVX-512's eight lanes a vector and 32 vector registers.
    #[cfg(target_arch = "x86_64")]
    Avx512,
}

impl Width {
    /// The widest this processor runs.
    fn widest() -> Self {
        #[cfg(target_arch = "x86_64")]
        {
            use std::arch::is_x86_feature_detected as has;
            if has!("avx512f") && has!("avx512dq") && has!("avx512vl") && has!("avx512bw") {
                return Width::Avx512;
            }
            if has!("avx2") {
                return Width::Avx2;
            }
        }
        Width::Baseline
    }

    /// Every width this processor runs, narrowest first (a processor with AVX-512 has AVX2).
    #[cfg(test)]
    fn available() -> Vec<Self> {
        #[cfg(target_arch = "x86_64")]
        let all = [Width::Baseline, Width::Avx2, Width::Avx512];
        #[cfg(not(target_arch = "x86_64"))]
        let all = [Width::Baseline];
        let widest = Self::widest();
        let up_to = all.iter().position(|&w| w == widest).unwrap_or(0);
        all[..=up_to].to_vec()
    }
}

/// Where a closed-form batch takes its pushes' inputs: the inputs no column varies are set
/// once, the varying ones copied from their columns batch by batch, so no push builds a scene.
struct ClosedForm<'a> {
    /// The inputs every push shares.
    base: statics::Push<LANES>,
    /// The columns of more than one value that set an input the closed form reads (the last
    /// column to set an input), by that input's key; None where a column is not a field's
    /// value as it stands (push ratios): each push's scene is then built.
    varying: Option<Vec<(usize, &'a [f64])>>,
    /// A column of more than one value sets the start angle.
    start_varies: bool,
    /// A column of more than one value sets the start angle, the radius, the palm's offset
    /// or its length: each push derives its start ([`statics::Push::derive`]).
    start_derived: bool,
    /// Every push lies outside the closed form's model (its start angle, shared, does).
    all_outside: bool,
    /// The vector width the chunks run in, one the processor has.
    width: Width,
    resolved: &'a Resolved<'a>,
    pushes: &'a Pushes<'a>,
}

impl<'a> ClosedForm<'a> {
    fn of(pushes: &'a Pushes<'a>, resolved: &'a Resolved<'a>, width: Width) -> Self {
        let mut base = pushes.base;
        let mut varying: Option<Vec<(&'static str, &'a [f64])>> = Some(Vec::new());
        for (set, values) in &resolved.columns {
            let Sets::Fields(keys, _) = set else {
                varying = None;
                continue;
            };
            for &key in *keys {
                // A column of one value is every push's: it joins the shared inputs.
                if let (Some(set), [v]) = (SceneParams::real_setter(key), values) {
                    set(&mut base, *v);
                }
                if let Some(list) = varying.as_mut() {
                    list.retain(|(k, _)| *k != key);
                    if values.len() > 1 {
                        list.push((key, values));
                    }
                }
            }
        }
        let start_varies = match &varying {
            Some(list) => list.iter().any(|(k, _)| *k == "start_angle_deg"),
            None => resolved.sets("start_angle_deg"),
        };
        // Only the inputs the closed form reads.
        let varying: Option<Vec<(usize, &[f64])>> = varying.map(|list| {
            let input = |(k, v): (&str, _)| Some((statics::Push::<LANES>::input(k)?, v));
            list.into_iter().filter_map(input).collect()
        });
        let start_derived = varying.as_ref().is_some_and(|list| {
            list.iter()
                .any(|(i, _)| statics::Push::START_INPUTS.contains(i))
        });
        let all_outside = !start_varies && outside(super::ModelKind::Statics, &base).is_some();
        ClosedForm {
            base: statics::Push::splat(statics::Push::of(&base)),
            varying,
            start_varies,
            start_derived,
            all_outside,
            width,
            resolved,
            pushes,
        }
    }

    /// Sets `lanes` to the pushes `at` (in order; a run of LANES neighbours is copied as one
    /// block): the varying inputs taken from their columns, or each push's scene built.
    #[inline(always)]
    fn load(&self, lanes: &mut statics::Push<LANES>, at: [usize; LANES]) {
        let Some(list) = &self.varying else {
            for (j, &i) in at.iter().enumerate() {
                let scene = self.resolved.scene(self.pushes.base, i);
                lanes.set(j, &statics::Push::of(&scene));
            }
            return;
        };
        let run = at[LANES - 1] - at[0] == LANES - 1;
        for &(input, values) in list {
            let lane = lanes.input_mut(input);
            match run {
                true => lane.copy_from_slice(&values[at[0]..at[0] + LANES]),
                false => {
                    for (v, &i) in lane.iter_mut().zip(&at) {
                        *v = values[i];
                    }
                }
            }
        }
        if self.start_derived {
            for j in 0..LANES {
                lanes.derive(j, self.start_varies);
            }
        }
    }

    /// Answers the pushes from `first` on into `out` (one chunk), in the vector width chosen.
    fn answer_chunk(&self, first: usize, out: Chunk) {
        match self.width {
            Width::Baseline => self.answer_chunk_in(first, out),
            // SAFETY: a width is the processor's widest (`Width::widest`) or one below it.
            #[cfg(target_arch = "x86_64")]
            Width::Avx2 => unsafe { self.answer_chunk_avx2(first, out) },
            // SAFETY: as above.
            #[cfg(target_arch = "x86_64")]
            Width::Avx512 => unsafe { self.answer_chunk_avx512(first, out) },
        }
    }

    /// [`Self::answer_chunk`] compiled for AVX2: four lanes a vector instead of two.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn answer_chunk_avx2(&self, first: usize, out: Chunk) {
        self.answer_chunk_in(first, out);
    }

    /// [`Self::answer_chunk`] compiled for AVX-512: eight lanes a vector and 32 vector
    /// registers, so that a batch's sixteen lanes spill less (9.9 ms for 10^6 pushes on one
    /// thread against AVX2's 15.5 on a Xeon that has both).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx512f,avx512dq,avx512vl,avx512bw")]
    fn answer_chunk_avx512(&self, first: usize, out: Chunk) {
        self.answer_chunk_in(first, out);
    }

    /// One chunk's answers, compiled for whatever vector width the caller was: every
    /// operation is one IEEE operation a lane and none is fused (Rust never contracts a
    /// multiply and an add), so each width gives the same bits.
    #[inline(always)]
    fn answer_chunk_in(&self, first: usize, out: Chunk) {
        let (((status, theta), x), mut past) = out;
        let len = status.len();
        if self.all_outside {
            status.fill(JamStatus::OutsideModel.index());
            theta.fill(f64::NAN);
            x.fill(f64::NAN);
            if let Some(past) = past {
                past.fill(f64::NAN);
            }
            return;
        }
        let mut lanes = self.base;
        let (mut s, mut t, mut xs) = ([0u8; LANES], [0.0; LANES], [0.0; LANES]);
        let mut ps = [f64::NAN; LANES];
        for k in (0..len).step_by(LANES) {
            // A last, partial batch repeats its last push.
            let mut at = [0; LANES];
            for (j, i) in at.iter_mut().enumerate() {
                *i = first + (k + j).min(len - 1);
            }
            self.load(&mut lanes, at);
            lanes.answer(&mut s, &mut t, &mut xs, past.is_some().then_some(&mut ps));
            let n = LANES.min(len - k);
            if self.start_varies {
                for j in 0..n {
                    let scene = SceneParams {
                        start_angle_deg: lanes.start_deg(j),
                        ..self.pushes.base
                    };
                    if outside(super::ModelKind::Statics, &scene).is_some() {
                        (s[j], t[j], xs[j]) = (JamStatus::OutsideModel.index(), f64::NAN, f64::NAN);
                        ps[j] = f64::NAN;
                    }
                }
            }
            // A whole batch is copied as one block of known size (no call to memcpy).
            match n == LANES {
                true => {
                    status[k..k + LANES].copy_from_slice(&s);
                    theta[k..k + LANES].copy_from_slice(&t);
                    x[k..k + LANES].copy_from_slice(&xs);
                    if let Some(past) = past.as_deref_mut() {
                        past[k..k + LANES].copy_from_slice(&ps);
                    }
                }
                false => {
                    status[k..k + n].copy_from_slice(&s[..n]);
                    theta[k..k + n].copy_from_slice(&t[..n]);
                    x[k..k + n].copy_from_slice(&xs[..n]);
                    if let Some(past) = past.as_deref_mut() {
                        past[k..k + n].copy_from_slice(&ps[..n]);
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The columns' box screens the pushes: a box whose corners are plausible says nothing; a
    /// push that is a likely unit mistake is named at its index, each kind of warning once,
    /// and a corner no push takes (a short palm only with a small disc) warns of nothing.
    #[test]
    fn unit_warnings_name_the_first_push_of_each_kind() {
        let mu = [0.2, 3.0, 0.3, 4.0];
        let radius = [10.0, 0.4, 0.3, 10.0];
        let pushes = |columns| Pushes {
            base: SceneParams::default(),
            columns,
        };
        let (mu_p, r_p) = (
            Param::named("mu").unwrap(),
            Param::named("radius_mm").unwrap(),
        );
        let got = pushes(vec![(mu_p, &mu[..]), (r_p, &radius[..])]).unit_warnings();
        let at: Vec<(usize, &str)> = got.iter().map(|(i, w)| (*i, opening(w))).collect();
        assert_eq!(at, [(1, "mu_ground"), (1, "radius_mm")], "{got:?}");
        let plain = [0.2, 0.3];
        assert!(pushes(vec![(mu_p, &plain[..])]).unit_warnings().is_empty());
        // Small discs on short palms: the corner (large disc, short palm) is no push's.
        let (short, small) = ([5.0, 150.0], [4.0, 10.0]);
        let l_p = Param::named("palm_length_mm").unwrap();
        let paired = pushes(vec![(r_p, &small[..]), (l_p, &short[..])]).unit_warnings();
        assert!(paired.is_empty(), "{paired:?}");
        let crossed = [150.0, 5.0];
        let shorter = pushes(vec![(r_p, &small[..]), (l_p, &crossed[..])]).unit_warnings();
        assert_eq!(shorter.len(), 1);
        assert_eq!(shorter[0].0, 1);
        assert!(shorter[0].1.starts_with("palm_length_mm"), "{shorter:?}");
    }

    /// A column's ends are its least and greatest values whatever its length (blocks and
    /// runs of lanes with a remainder), NaN passed over wherever it stands, the infinities
    /// kept, and no value at all the empty ends.
    #[test]
    fn a_columns_ends_pass_over_nan() {
        let fold = |v: &[f64]| {
            v.iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| {
                    (if x < lo { x } else { lo }, if x > hi { x } else { hi })
                })
        };
        for n in [0, 1, 7, 8, 9, 4095, 4096, 4097, 3 * 4096 + 5, 40_000] {
            let mut v: Vec<f64> = (0..n)
                .map(|i| ((i as f64 + 1.0) * 0.618_033_988_75).fract() * 10.0 - 5.0)
                .collect();
            assert_eq!(ends(&v), fold(&v), "{n} values");
            for (k, bad) in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, -1e300, 1e300]
                .into_iter()
                .enumerate()
            {
                if let Some(x) = v.get_mut((k * 4099 + 3) % n.max(1)) {
                    *x = bad;
                }
                assert_eq!(ends(&v), fold(&v), "{n} values with {bad}");
            }
        }
        let nan = [f64::NAN; 9];
        assert_eq!(ends(&nan), (f64::INFINITY, f64::NEG_INFINITY));
    }

    /// A stop set before the work begins leaves every answer as it was; an unset one answers
    /// every push, the same answers as [`solve_into`].
    #[test]
    fn a_stop_leaves_the_chunks_not_begun() {
        let mu: Vec<f64> = (1..=3000).map(|i| f64::from(i) * 1e-4).collect();
        let pushes = Pushes {
            base: SceneParams::default(),
            columns: vec![(Param::named("mu").unwrap(), &mu[..])],
        };
        let n = mu.len();
        let run = |stop: bool| {
            let (mut st, mut th, mut x) = (vec![99u8; n], vec![-1.0; n], vec![-1.0; n]);
            let out = Answers {
                status: &mut st,
                theta_jam_deg: &mut th,
                x_jam_mm: &mut x,
                past_palm_x_jam_mm: None,
            };
            let flag = AtomicBool::new(stop);
            let done = solve_into_until(&ModelSpec::Statics, &pushes, out, &flag).unwrap();
            (done, st, th, x)
        };
        let (done, st, th, x) = run(true);
        assert_eq!(done, Finished::Stopped { answered: 0 });
        assert!(st.iter().all(|&s| s == 99) && th.iter().chain(&x).all(|&v| v == -1.0));
        let (done, st, th, _) = run(false);
        assert_eq!(done, Finished::All);
        let (st1, th1, _) = answered(&ModelSpec::Statics, &pushes);
        assert_eq!(st, st1);
        assert!(th.iter().zip(&th1).all(|(a, b)| a.to_bits() == b.to_bits()));
    }

    /// Closed-form pushes answered together are the same bits as each answered alone by
    /// [`super::solve`], in every vector width the processor has, on the calling thread and
    /// on the pool, with every status among them, whichever fields vary (the start angle too,
    /// above 90 deg outside the model), and a count that leaves a partial batch; the
    /// past-palm column too.
    #[test]
    fn closed_form_batches_answer_each_push_as_solve_does() {
        // Answered on the calling thread, and in chunks on the pool.
        for n in [4 * 250 + 3, SERIAL_STATICS + 4 * 250 + 3] {
            closed_form_batches_of(n);
        }
    }

    /// [`closed_form_batches_answer_each_push_as_solve_does`] for `n` pushes.
    fn closed_form_batches_of(n: usize) {
        // A fixed sequence spread over each field's range (a Weyl sequence per column).
        let spread = |k: usize, lo: f64, hi: f64| -> Vec<f64> {
            let a = [
                0.618_033_988_75,
                0.414_213_562_37,
                0.732_050_807_57,
                0.236_067_977_5,
            ][k % 4]
                + 0.1 * k as f64;
            (0..n)
                .map(|i| lo + (hi - lo) * (a * (i as f64 + 1.0)).fract())
                .collect()
        };
        let mu_g = spread(0, 0.0, 1.5);
        let mu_p = spread(1, 0.0, 1.5);
        let mass = spread(2, 0.0, 30.0);
        let force = spread(3, 1.0, 300.0);
        let start = spread(4, 20.0, 110.0);
        let offset = spread(5, 0.0, 3.0);
        let palm = spread(6, 5.0, 120.0);
        let named = |k: &str| Param::named(k).unwrap();
        let columns = vec![
            (named("mu_ground"), &mu_g[..]),
            (named("mu_palm"), &mu_p[..]),
            (named("mass_kg"), &mass[..]),
            (named("force_n"), &force[..]),
            (named("palm_offset_mm"), &offset[..]),
            (named("palm_length_mm"), &palm[..]),
        ];
        let mu = spread(7, 0.0, 1.5);
        let radius = spread(8, 2.0, 60.0);
        let ratio = spread(9, 0.1, 40.0);
        let one_mass = [0.3];
        // Above 90 deg: every push lies outside the model.
        let one_start = [120.0];
        let mut seen = std::collections::HashSet::new();
        // Six fields; the same and the start angle; one friction for both contacts (`mu`),
        // the radius and a column of one value, without a palm offset; push ratios, whose
        // scenes are built push by push, with and without a start angle shared by all.
        let configurations = [
            columns.clone(),
            [
                columns.clone(),
                vec![(named("start_angle_deg"), &start[..])],
            ]
            .concat(),
            vec![
                (named("mu"), &mu[..]),
                (named("radius_mm"), &radius[..]),
                (named("mass_kg"), &one_mass[..]),
            ],
            vec![(named("mu"), &mu[..]), (Param::PushRatio, &ratio[..])],
            vec![
                (Param::PushRatio, &ratio[..]),
                (named("start_angle_deg"), &one_start[..]),
            ],
        ];
        let widths = Width::available();
        assert_eq!(widths.last(), Some(&Width::widest()));
        for (columns, &width) in configurations
            .iter()
            .flat_map(|c| widths.iter().map(move |w| (c, w)))
        {
            let pushes = Pushes {
                base: SceneParams::default(),
                columns: columns.clone(),
            };
            let (mut st, mut th, mut x, mut past) =
                (vec![0u8; n], vec![0.0; n], vec![0.0; n], vec![-7.0; n]);
            let out = Answers {
                status: &mut st,
                theta_jam_deg: &mut th,
                x_jam_mm: &mut x,
                past_palm_x_jam_mm: Some(&mut past),
            };
            let never = AtomicBool::new(false);
            solve_in_width(&ModelSpec::Statics, &pushes, out, &never, width).unwrap();
            let resolved = pushes.resolved();
            let bits = |v: Option<f64>| v.unwrap_or(f64::NAN).to_bits();
            for i in 0..n {
                let scene = resolved.scene(pushes.base, i);
                let one = solve(&ModelSpec::Statics, &scene).unwrap();
                seen.insert(one.status);
                let at = format!("push {i} in {width:?}");
                assert_eq!(JamStatus::ALL[st[i] as usize], one.status, "{at}");
                assert_eq!(th[i].to_bits(), bits(one.theta_jam_deg), "{at}");
                assert_eq!(x[i].to_bits(), bits(one.x_jam_mm), "{at}");
                let past_palm = match one.status {
                    JamStatus::OutsideModel => None,
                    _ => crate::statics::solve(&scene).past_palm,
                };
                assert_eq!(
                    past[i].to_bits(),
                    bits(past_palm.map(|p| p.x_jam_mm)),
                    "{at}"
                );
            }
        }
        use JamStatus::*;
        for status in [TooWeak, JammedAtStart, BeyondReach, Jams, OutsideModel] {
            assert!(seen.contains(&status), "{status:?} not among {seen:?}");
        }
    }

    /// Of several invalid pushes the first in order is refused, whichever column holds it, with
    /// the message `solve` gives that push alone; a push-ratio column (a force from each push's
    /// mass) is checked push by push.
    #[test]
    fn the_first_invalid_push_is_refused_as_solve_refuses_it() {
        let mu = [0.1, 0.2, 0.3, -0.4];
        let force = [40.0, -1.0, 40.0, 40.0];
        fn run(columns: Vec<(Param, &[f64])>) -> (String, Pushes<'_>) {
            let pushes = Pushes {
                base: SceneParams::default(),
                columns,
            };
            let n = pushes.len();
            let (mut st, mut th, mut x) = (vec![0; n], vec![0.0; n], vec![0.0; n]);
            let out = Answers {
                status: &mut st,
                theta_jam_deg: &mut th,
                x_jam_mm: &mut x,
                past_palm_x_jam_mm: None,
            };
            let e = solve_into(&ModelSpec::Statics, &pushes, out).unwrap_err();
            (e.to_string(), pushes)
        }
        let (msg, pushes) = run(vec![
            (Param::named("mu").unwrap(), &mu[..]),
            (Param::named("force_n").unwrap(), &force[..]),
        ]);
        let alone = pushes
            .resolved()
            .scene(pushes.base, 1)
            .validate()
            .unwrap_err();
        assert_eq!(msg, alone.to_string());
        assert!(msg.contains("force_n") && msg.contains("-1"), "{msg}");
        let mass = [1.0, 0.0, 2.0];
        let (msg, _) = run(vec![
            (Param::named("mass_kg").unwrap(), &mass[..]),
            (Param::PushRatio, &[10.0][..]),
        ]);
        assert!(msg.contains("force_n") && msg.contains("= 0"), "{msg}");
    }

    /// The array answers had NaN in x_jam_mm for a push the palm loses past its end, and no
    /// word of where it would jam: the 25 mm shaft at mu 0.12 on an 80 mm palm would jam at
    /// 99.261 mm on a long palm (`solve --mu 0.12`'s past_palm). A column of its own gives
    /// it, NaN on every other push, so that x_jam_mm keeps its meaning.
    #[test]
    fn a_push_past_the_palm_gives_where_it_would_jam() {
        let mu = [0.12, 0.2, 0.0];
        let base = SceneParams {
            radius_mm: 12.5,
            mass_kg: 0.4,
            force_n: 40.0,
            palm_length_mm: 80.0,
            ..SceneParams::default()
        };
        let pushes = Pushes {
            base,
            columns: vec![(Param::named("mu").unwrap(), &mu[..])],
        };
        let (st, _, x, past) = answered_with_past(&ModelSpec::Statics, &pushes);
        assert_eq!(st[0], JamStatus::BeyondReach.index());
        assert!(x[0].is_nan(), "{x:?}");
        assert!((past[0] - 99.2613605241956).abs() < 1e-9, "{past:?}");
        // Jams on the palm, never jams: no jam past the palm.
        assert!(x[1].is_finite() && past[1].is_nan(), "{x:?} {past:?}");
        assert!(past[2].is_nan(), "{past:?}");
    }

    /// Over several chunks of pushes, each push's past-palm jam is its own scene's, the chunk
    /// and the batch that hold it found by its index: pushes past the palm in runs and
    /// scattered among others, with the start derived push by push (a column of radii) and
    /// with each push's scene built (a column of push ratios).
    #[test]
    fn past_palm_jams_follow_their_pushes_across_chunks() {
        // More than one thread's worth: the chunks go to the pool.
        let n = SERIAL_STATICS + 3 * CHUNK + 7;
        let mu: Vec<f64> = (0..n).map(|i| 0.4 * i as f64 / n as f64).collect();
        // A scrambled order: neighbours' statuses differ.
        let scrambled: Vec<f64> = (0..n).map(|i| mu[i * 389 % n]).collect();
        let radius: Vec<f64> = (0..n).map(|i| 4.0 + (i * 7 % 13) as f64).collect();
        let ratio: Vec<f64> = (0..n).map(|i| 2.0 + (i * 5 % 11) as f64).collect();
        let base = SceneParams {
            palm_length_mm: 40.0,
            ..SceneParams::default()
        };
        let named = |k| Param::named(k).unwrap();
        let sets: [Vec<(Param, &[f64])>; 4] = [
            vec![(named("mu"), &mu[..])],
            vec![(named("mu"), &scrambled[..])],
            vec![
                (named("mu"), &scrambled[..]),
                (named("radius_mm"), &radius[..]),
            ],
            vec![
                (named("mu"), &scrambled[..]),
                (Param::PushRatio, &ratio[..]),
            ],
        ];
        for columns in sets {
            let pushes = Pushes { base, columns };
            let (st, th, x, past) = answered_with_past(&ModelSpec::Statics, &pushes);
            // Asking for the column changes no other answer.
            let (st0, th0, x0) = answered(&ModelSpec::Statics, &pushes);
            assert_eq!(st, st0);
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert!(bits(&th) == bits(&th0) && bits(&x) == bits(&x0));
            let resolved = pushes.resolved();
            let mut found = 0;
            for (i, x) in past.iter().enumerate() {
                let own = crate::statics::solve(&resolved.scene(base, i)).past_palm;
                let want = own.map_or(f64::NAN, |p| p.x_jam_mm);
                assert_eq!(
                    x.to_bits(),
                    want.to_bits(),
                    "push {i} of {:?}",
                    pushes.columns
                );
                found += usize::from(own.is_some());
            }
            assert!(found > 20 && found < n - 20, "{found} of {n} past the palm");
        }
        let pushes = Pushes {
            base,
            columns: vec![(named("mu"), &mu[..100])],
        };
        let (st, _, _, past) = answered_with_past(&ModelSpec::MinNorm(Default::default()), &pushes);
        assert!(st.contains(&JamStatus::BeyondReach.index()), "{st:?}");
        assert!(past.iter().all(|x| x.is_nan()));
    }

    /// `pushes` answered: status, theta_jam and x_jam.
    fn answered(spec: &ModelSpec, pushes: &Pushes) -> (Vec<u8>, Vec<f64>, Vec<f64>) {
        let n = pushes.len();
        let (mut st, mut th, mut x) = (vec![0; n], vec![0.0; n], vec![0.0; n]);
        let out = Answers {
            status: &mut st,
            theta_jam_deg: &mut th,
            x_jam_mm: &mut x,
            past_palm_x_jam_mm: None,
        };
        solve_into(spec, pushes, out).unwrap();
        (st, th, x)
    }

    /// `pushes` answered with the past-palm column: status, theta_jam, x_jam and past-palm
    /// x_jam, the last set to a sentinel first so that an element left unwritten shows.
    fn answered_with_past(
        spec: &ModelSpec,
        pushes: &Pushes,
    ) -> (Vec<u8>, Vec<f64>, Vec<f64>, Vec<f64>) {
        let n = pushes.len();
        let (mut st, mut th, mut x, mut past) =
            (vec![0; n], vec![0.0; n], vec![0.0; n], vec![-7.0; n]);
        let out = Answers {
            status: &mut st,
            theta_jam_deg: &mut th,
            x_jam_mm: &mut x,
            past_palm_x_jam_mm: Some(&mut past),
        };
        solve_into(spec, pushes, out).unwrap();
        assert!(!past.contains(&-7.0), "every past-palm element written");
        (st, th, x, past)
    }

    /// A past-palm column of another length than the pushes' is refused, as the other
    /// answers' are; pushes outside the closed form's model (a start angle past the palm's
    /// lifting the disc) have none, beside one inside it that has.
    #[test]
    fn the_past_palm_column_is_one_per_push() {
        let mu = [0.05, 0.1, 0.2];
        let pushes = Pushes {
            base: SceneParams::default(),
            columns: vec![(Param::named("mu").unwrap(), &mu[..])],
        };
        let (mut st, mut th, mut x, mut past) =
            (vec![0; 3], vec![0.0; 3], vec![0.0; 3], vec![0.0; 2]);
        let out = Answers {
            status: &mut st,
            theta_jam_deg: &mut th,
            x_jam_mm: &mut x,
            past_palm_x_jam_mm: Some(&mut past),
        };
        let e = solve_into(&ModelSpec::Statics, &pushes, out).unwrap_err();
        assert!(e.to_string().contains("one element per push (3)"), "{e}");
        let start = [179.0, 90.0, 179.0];
        let pushes = Pushes {
            base: SceneParams {
                palm_length_mm: 40.0,
                ..SceneParams::default().with_mu(0.02)
            },
            columns: vec![(Param::named("start_angle_deg").unwrap(), &start[..])],
        };
        let (st, _, _, past) = answered_with_past(&ModelSpec::Statics, &pushes);
        let outside = JamStatus::OutsideModel.index();
        assert_eq!(st, [outside, JamStatus::BeyondReach.index(), outside]);
        assert!(
            past[0].is_nan() && past[1].is_finite() && past[2].is_nan(),
            "{past:?}"
        );
    }
}
