//! Numbers in lanes: `N` pushes' numbers side by side, each operation one IEEE operation per
//! lane, so that the compiler turns it into one vector instruction and a lane's bits are the
//! push's alone (`N = 1`) on every machine; and the arctangent in that arithmetic.

use std::f64::consts::{FRAC_PI_2, FRAC_PI_4};

/// `N` numbers, one per push of a batch. Each operation is a loop over the lanes doing one
/// IEEE operation (no fused multiply-add), which the compiler turns into one vector
/// instruction where the processor has them: a lane gets the same bits as a push alone
/// (`N = 1`, the scalar code), on every machine and lane width.
#[derive(Debug, Clone, Copy)]
pub(super) struct Many<const N: usize>(pub(super) [f64; N]);

/// `N` truths, one per lane of [`Many`], each as wide as its lane: all ones for true, all
/// zeros for false, as an AVX2 comparison leaves them, so that a comparison feeds a
/// selection in the vector registers, which reads the lane's sign bit ([`Mask::select`]).
/// Truths held as bytes were packed and unpacked between the two: 10^6 closed-form pushes
/// on one thread took 18.7 ms with AVX2 then, 15.5 now (the statuses also read off in
/// vector lanes, in `Push::answer`); with AVX-512, 9.9.
#[derive(Debug, Clone, Copy)]
pub(super) struct Mask<const N: usize>([u64; N]);

impl<const N: usize> From<f64> for Many<N> {
    #[inline(always)]
    fn from(v: f64) -> Self {
        Many([v; N])
    }
}

impl Many<1> {
    /// The one lane's number.
    pub(super) fn one(self) -> f64 {
        self.0[0]
    }
}

impl<const N: usize> Many<N> {
    #[inline(always)]
    pub(super) fn map(self, f: impl Fn(f64) -> f64) -> Self {
        let mut out = self.0;
        for v in &mut out {
            *v = f(*v);
        }
        Many(out)
    }

    #[inline(always)]
    fn zip(self, o: Self, f: impl Fn(f64, f64) -> f64) -> Self {
        let mut out = self.0;
        for (v, w) in out.iter_mut().zip(o.0) {
            *v = f(*v, w);
        }
        Many(out)
    }

    #[inline(always)]
    fn test(self, o: impl Into<Self>, f: impl Fn(f64, f64) -> bool) -> Mask<N> {
        let o = o.into();
        Mask::of(|j| f(self.0[j], o.0[j]))
    }

    #[inline(always)]
    pub(super) fn sqrt(self) -> Self {
        self.map(f64::sqrt)
    }

    #[inline(always)]
    pub(super) fn lt(self, o: impl Into<Self>) -> Mask<N> {
        self.test(o, |a, b| a < b)
    }

    #[inline(always)]
    pub(super) fn le(self, o: impl Into<Self>) -> Mask<N> {
        self.test(o, |a, b| a <= b)
    }

    #[inline(always)]
    pub(super) fn gt(self, o: impl Into<Self>) -> Mask<N> {
        self.test(o, |a, b| a > b)
    }

    #[inline(always)]
    pub(super) fn ge(self, o: impl Into<Self>) -> Mask<N> {
        self.test(o, |a, b| a >= b)
    }

    #[inline(always)]
    pub(super) fn eq(self, o: impl Into<Self>) -> Mask<N> {
        self.test(o, |a, b| a == b)
    }

    #[inline(always)]
    pub(super) fn is_nan(self) -> Mask<N> {
        Mask::of(|j| self.0[j].is_nan())
    }

    #[inline(always)]
    pub(super) fn is_finite(self) -> Mask<N> {
        Mask::of(|j| self.0[j].is_finite())
    }
}

impl<const N: usize> Mask<N> {
    /// Lane `j` true where `truth(j)` is.
    ///
    /// Here and in every lane operation a loop, not an array's `map`: `map` goes through
    /// `try_map`, which the compiler left as a call in one build of the crate (with the
    /// server) and not in another, a tenth of a closed-form push's instructions.
    #[inline(always)]
    fn of(truth: impl Fn(usize) -> bool) -> Self {
        let mut out = [0; N];
        for (j, m) in out.iter_mut().enumerate() {
            *m = Self::lane(truth(j));
        }
        Mask(out)
    }

    /// A lane's bits for `truth`: all ones or all zeros.
    #[inline(always)]
    fn lane(truth: bool) -> u64 {
        u64::from(truth).wrapping_neg()
    }

    /// `truth` in every lane.
    pub(super) fn splat(truth: bool) -> Self {
        Mask([Self::lane(truth); N])
    }

    /// Lane `j`'s truth.
    #[inline(always)]
    pub(super) fn get(self, j: usize) -> bool {
        self.0[j] != 0
    }

    /// Sets lane `j` to `truth`.
    pub(super) fn set(&mut self, j: usize, truth: bool) {
        self.0[j] = Self::lane(truth);
    }

    /// `yes` where true, `no` where false, lane by lane: each lane's bits taken whole from
    /// one side, as the mask's sign bit says. That is the bit AVX2's blend reads and AVX-512
    /// moves into a bit mask in one instruction; selecting by the whole mask's bits
    /// (`and`, `andnot`, `or`) took a third longer with AVX-512 and a tenth with AVX2.
    #[inline(always)]
    pub(super) fn select(self, yes: impl Into<Many<N>>, no: impl Into<Many<N>>) -> Many<N> {
        let (yes, no) = (yes.into(), no.into());
        let mut out = no.0;
        for ((o, m), y) in out.iter_mut().zip(self.0).zip(yes.0) {
            if (m as i64) < 0 {
                *o = y;
            }
        }
        Many(out)
    }
}

/// The lane-by-lane operators of [`Many`], with a plain number on either side.
macro_rules! lane_ops {
    ($($trait:ident $method:ident $op:tt),*) => {$(
        impl<const N: usize> std::ops::$trait for Many<N> {
            type Output = Self;
            #[inline(always)]
            fn $method(self, o: Self) -> Self {
                self.zip(o, |a, b| a $op b)
            }
        }
        impl<const N: usize> std::ops::$trait<f64> for Many<N> {
            type Output = Self;
            #[inline(always)]
            fn $method(self, o: f64) -> Self {
                self.zip(o.into(), |a, b| a $op b)
            }
        }
        impl<const N: usize> std::ops::$trait<Many<N>> for f64 {
            type Output = Many<N>;
            #[inline(always)]
            fn $method(self, o: Many<N>) -> Many<N> {
                Many::from(self).zip(o, |a, b| a $op b)
            }
        }
    )*};
}
lane_ops!(Add add +, Sub sub -, Mul mul *, Div div /);

/// The lane-by-lane logic of [`Mask`].
macro_rules! mask_ops {
    ($($trait:ident $method:ident $op:tt),*) => {$(
        impl<const N: usize> std::ops::$trait for Mask<N> {
            type Output = Self;
            #[inline(always)]
            fn $method(self, o: Self) -> Self {
                let mut out = self.0;
                for (m, n) in out.iter_mut().zip(o.0) {
                    *m $op n;
                }
                Mask(out)
            }
        }
    )*};
}
mask_ops!(BitAnd bitand &=, BitOr bitor |=);

impl<const N: usize> std::ops::Not for Mask<N> {
    type Output = Self;
    #[inline(always)]
    fn not(self) -> Self {
        let mut out = self.0;
        for m in &mut out {
            *m = !*m;
        }
        Mask(out)
    }
}

/// The arctangent in plain arithmetic: Cephes' `atan` (S. L. Moshier), |x| reduced to at most
/// 0.66 through tan(pi/4) or the reciprocal, then a rational function of degree 4 over 5 in
/// x^2; within 1 ulp of libm's on the tests' sample.
///
/// libm's arctangent is a call that a batch cannot share; this one has no branch and no
/// fused multiply-add, so a batch of pushes evaluates it in the processor's vector lanes
/// and every lane width, scalar included, gives the same bits on every machine (a crate's
/// vector arctangent, such as `wide`'s, fuses or not as the build's target features say).
#[inline(always)]
pub(super) fn atan<const N: usize>(x: Many<N>) -> Many<N> {
    // tan(3 pi / 8), and pi / 2 less its nearest double (pi / 4's is half of it).
    const TAN_3PI_8: f64 = 2.414_213_562_373_095;
    const MORE_BITS: f64 = 6.123_233_995_736_766e-17;
    const P: [f64; 5] = [
        -8.750_608_600_031_904e-1,
        -1.615_753_718_733_365e1,
        -7.500_855_792_314_705e1,
        -1.228_866_684_490_136_2e2,
        -6.485_021_904_942_025e1,
    ];
    const Q: [f64; 5] = [
        2.485_846_490_142_306e1,
        1.650_270_098_316_988_6e2,
        4.328_810_604_912_903e2,
        4.853_903_996_359_137e2,
        1.945_506_571_482_614e2,
    ];
    let a = x.map(f64::abs);
    // atan(a) = base + atan(num / den): pi/2 - atan(1/a) above tan(3 pi / 8), pi/4 +
    // atan((a - 1) / (a + 1)) above 0.66, atan(a) below.
    let (big, mid) = (a.gt(TAN_3PI_8), a.gt(0.66));
    let num = big.select(-1.0, mid.select(a - 1.0, a));
    let den = big.select(a, mid.select(a + 1.0, 1.0));
    let base = big.select(FRAC_PI_2, mid.select(FRAC_PI_4, 0.0));
    let more = big.select(MORE_BITS, mid.select(0.5 * MORE_BITS, 0.0));
    let t = num / den;
    let z = t * t;
    let p = (((z * P[0] + P[1]) * z + P[2]) * z + P[3]) * z + P[4];
    let q = ((((z + Q[0]) * z + Q[1]) * z + Q[2]) * z + Q[3]) * z + Q[4];
    (base + ((t * (z * p / q) + t) + more)).zip(x, f64::copysign)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The plain arctangent is libm's within 1 ulp, over the whole line (magnitudes from
    /// 1e-300 to 1e300, both signs, the reduction's bounds 0.66 and tan(3 pi / 8) and their
    /// neighbours), and keeps atan's values at 0, the infinities and NaN.
    #[test]
    fn the_plain_arctangent_is_libms_within_an_ulp() {
        let ulp = |y: f64| f64::from_bits(y.abs().to_bits() + 1) - y.abs();
        let mut xs: Vec<f64> = (0..=60_000)
            .map(|i| 10f64.powf(-300.0 + 600.0 * f64::from(i) / 60_000.0))
            .collect();
        xs.extend((0..=200_000).map(|i| 4.0 * f64::from(i) / 200_000.0));
        for edge in [0.66, 2.414_213_562_373_095, 1.0] {
            let bits = f64::to_bits(edge);
            xs.extend((bits - 50..=bits + 50).map(f64::from_bits));
        }
        let mut worst: f64 = 0.0;
        for x in xs.iter().flat_map(|&x| [x, -x]) {
            let (ours, libm) = (atan(Many::<1>::from(x)).one(), x.atan());
            let err = (ours - libm).abs() / ulp(libm);
            worst = worst.max(err);
            assert!(
                err <= 1.0,
                "atan({x:e}) = {ours:e}, libm {libm:e}: {err} ulp"
            );
        }
        assert!(
            worst > 0.0,
            "a sample where the two differ: the comparison compares"
        );
        assert_eq!(atan(Many::<1>::from(0.0)).one().to_bits(), 0.0f64.to_bits());
        assert_eq!(
            atan(Many::<1>::from(-0.0)).one().to_bits(),
            (-0.0f64).to_bits()
        );
        assert_eq!(atan(Many::<1>::from(f64::INFINITY)).one(), FRAC_PI_2);
        assert_eq!(atan(Many::<1>::from(f64::NEG_INFINITY)).one(), -FRAC_PI_2);
        assert!(atan(Many::<1>::from(f64::NAN)).one().is_nan());
    }
}
