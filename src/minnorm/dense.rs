//! Small dense algebra for the exact path, in place on column-major slices.
//!
//! A planar contact problem's KKT systems have a few dozen unknowns at most (8 in the palm
//! scene) and a map solves millions of them: heap matrices spent more on allocation and on
//! generic indexing than on arithmetic. These routines work on a caller's buffers and perform
//! nalgebra's arithmetic in nalgebra's order (`LU::new` with its partial pivoting and
//! reciprocal scaling, `LU::solve`, `Matrix * Vector`, `amax`), so every answer is bit for bit
//! the one a `DMatrix` gives; the tests hold them to it on random and singular matrices.

/// Factorises the k x k column-major `a` in place by Gaussian elimination with partial
/// pivoting (the unit lower factor below the diagonal, the upper factor on and above it), as
/// nalgebra's `LU::new`: a column without a non-zero pivot is left as it is. The row swaps are
/// written to `swaps` in order; returns their number.
///
/// Inlined, so that a caller that knows `k` has the loops unrolled.
#[inline(always)]
pub(super) fn lu_in_place(a: &mut [f64], k: usize, swaps: &mut [(usize, usize)]) -> usize {
    lu_steps(a, k, 0, swaps, 0)
}

/// The elimination steps `from..k` of [`lu_in_place`], after `n_swaps` swaps.
#[inline(always)]
fn lu_steps(
    a: &mut [f64],
    k: usize,
    from: usize,
    swaps: &mut [(usize, usize)],
    mut n_swaps: usize,
) -> usize {
    for i in from..k {
        // Columns up to i, and those after it.
        let (done, rest) = a[..k * k].split_at_mut((i + 1) * k);
        // The first entry of largest magnitude on or below the diagonal.
        let column = &done[i * k..];
        let mut piv = i;
        let mut largest = column[i].abs();
        for (r, v) in column.iter().enumerate().skip(i + 1) {
            if v.abs() > largest {
                largest = v.abs();
                piv = r;
            }
        }
        let diag = column[piv];
        if diag == 0.0 {
            continue;
        }
        if piv != i {
            swaps[n_swaps] = (i, piv);
            n_swaps += 1;
            for c in done.chunks_exact_mut(k) {
                c.swap(i, piv);
            }
        }
        let inv_diag = 1.0 / diag;
        let coeffs = &mut done[i * k + i + 1..];
        for v in coeffs.iter_mut() {
            *v *= inv_diag;
        }
        let coeffs = &*coeffs;
        for c in rest.chunks_exact_mut(k) {
            c.swap(i, piv);
            let p = c[i];
            for (v, l) in c[i + 1..].iter_mut().zip(coeffs) {
                *v += -p * l;
            }
        }
    }
    n_swaps
}

/// [`lu_in_place`] of a k x k matrix `a` whose leading b x b block has been factorised before
/// (`base`, b x b column-major, and its swaps `base_swaps`): the KKT matrix of an active set
/// borders the one of no active row with the set's rows and columns.
///
/// Elimination treats each entry alone, in the order of the steps: the leading block's steps
/// are the base's as long as no bordering row would be chosen as a pivot in them, the
/// bordering rows' multipliers need only the base's upper factor and the bordering columns its
/// swaps and lower factor, in the same operations in the same order. So the factors are
/// [`lu_in_place`]'s bit for bit, for a fraction of the work when the border is thin (one
/// row and column for a set of one active row). None, with `a` spoilt, when a bordering row
/// would have been a pivot: factorise the matrix whole.
#[inline(always)]
pub(super) fn lu_bordered(
    a: &mut [f64],
    k: usize,
    base: &[f64],
    b: usize,
    base_swaps: &[(usize, usize)],
    swaps: &mut [(usize, usize)],
) -> Option<usize> {
    let a = &mut a[..k * k];
    let base = &base[..b * b];
    // A bordering row is chosen at step i if it is larger than the base's pivot there (the
    // first largest wins, and the bordering rows come last), checked on the row's values as
    // they are at step i.
    for r in b..k {
        for i in 0..b {
            let diag = base[i * b + i];
            let x = a[i * k + r];
            if x.abs() > diag.abs() {
                return None;
            }
            if diag == 0.0 {
                continue;
            }
            let l = x * (1.0 / diag);
            a[i * k + r] = l;
            for c in i + 1..b {
                a[c * k + r] += -base[c * b + i] * l;
            }
        }
    }
    // The bordering columns: the base's swaps, then its steps, on every row below the pivot.
    let (leading, bordering) = a.split_at_mut(b * k);
    for column in bordering.chunks_exact_mut(k) {
        for &(i, piv) in base_swaps {
            column.swap(i, piv);
        }
        for i in 0..b {
            if base[i * b + i] == 0.0 {
                continue;
            }
            let p = column[i];
            let (upper, lower) = column.split_at_mut(b);
            for (v, l) in upper[i + 1..]
                .iter_mut()
                .zip(&base[i * b + i + 1..(i + 1) * b])
            {
                *v += -p * l;
            }
            for (v, l) in lower.iter_mut().zip(&leading[i * k + b..(i + 1) * k]) {
                *v += -p * l;
            }
        }
    }
    for (column, factored) in leading.chunks_exact_mut(k).zip(base.chunks_exact(b)) {
        column[..b].copy_from_slice(factored);
    }
    swaps[..base_swaps.len()].copy_from_slice(base_swaps);
    Some(lu_steps(a, k, b, swaps, base_swaps.len()))
}

/// Solves `A x = b` in place of `b` from [`lu_in_place`]'s factors `lu` and `swaps`, as
/// nalgebra's `LU::solve`: false (and `b` spoilt) when the upper factor has a zero on its
/// diagonal.
#[inline(always)]
pub(super) fn lu_solve(lu: &[f64], k: usize, swaps: &[(usize, usize)], b: &mut [f64]) -> bool {
    let b = &mut b[..k];
    for &(i, j) in swaps {
        b.swap(i, j);
    }
    for (i, column) in lu.chunks_exact(k).take(k).enumerate() {
        let (done, below) = b.split_at_mut(i + 1);
        let coeff = done[i];
        for (v, l) in below.iter_mut().zip(&column[i + 1..]) {
            *v += -coeff * l;
        }
    }
    for (i, column) in lu.chunks_exact(k).take(k).enumerate().rev() {
        let diag = column[i];
        if diag == 0.0 {
            return false;
        }
        let (above, rest) = b.split_at_mut(i);
        let coeff = rest[0] / diag;
        rest[0] = coeff;
        for (v, u) in above.iter_mut().zip(column) {
            *v += -coeff * u;
        }
    }
    true
}

/// `out = A x` for the column-major `a` of `out.len()` rows and `x.len()` columns, summed
/// column by column as nalgebra's product; `ABS` multiplies |A| by |x| instead.
#[inline(always)]
pub(super) fn mul_vec<const ABS: bool>(a: &[f64], x: &[f64], out: &mut [f64]) {
    let term = |v: f64, x: f64| if ABS { v.abs() * x.abs() } else { v * x };
    let m = out.len();
    let Some((&x0, x_rest)) = x.split_first().filter(|_| m > 0) else {
        out.fill(0.0);
        return;
    };
    let mut columns = a.chunks_exact(m);
    // The first column is written, as nalgebra does (0 + t would turn -0 into +0).
    for (o, &v) in out.iter_mut().zip(columns.next().unwrap_or_default()) {
        *o = term(v, x0);
    }
    for (column, &xj) in columns.zip(x_rest) {
        for (o, &v) in out.iter_mut().zip(column) {
            *o += term(v, xj);
        }
    }
}

/// The largest magnitude of `v` (0 for an empty slice), as nalgebra's `amax`: a NaN is passed
/// over unless it comes last.
pub(super) fn amax(v: &[f64]) -> f64 {
    let Some((first, rest)) = v.split_first() else {
        return 0.0;
    };
    rest.iter().fold(first.abs(), |m, x| {
        let b = x.abs();
        if m >= b { m } else { b }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{DMatrix, DVector};
    use proptest::prelude::*;

    fn bits(v: &[f64]) -> Vec<u64> {
        v.iter().map(|x| x.to_bits()).collect()
    }

    /// A k x k matrix with whole rows and columns of zeros, repeated columns and exact zeros
    /// mixed in (singular and rank-deficient KKT matrices), from a seed vector.
    fn matrix(k: usize, seed: &[f64], pattern: u8) -> Vec<f64> {
        let mut a: Vec<f64> = (0..k * k).map(|i| seed[i % seed.len()]).collect();
        match pattern % 4 {
            0 => {}
            1 => (0..k).for_each(|c| a[c * k + (c * 7) % k] = 0.0),
            2 if k > 1 => {
                let (first, second) = a.split_at_mut(k);
                second[..k].copy_from_slice(first);
            }
            _ => a.iter_mut().step_by(3).for_each(|v| *v = 0.0),
        }
        a
    }

    proptest! {
        /// The in-place LU and its solve give nalgebra's bits, solvable or not.
        #[test]
        fn lu_matches_nalgebra_bit_for_bit(
            k in 1usize..12,
            seed in prop::collection::vec(-10.0..10.0_f64, 1..40),
            rhs in prop::collection::vec(-10.0..10.0_f64, 12),
            pattern in 0u8..4,
        ) {
            let a = matrix(k, &seed, pattern);
            let b = &rhs[..k];
            let theirs = DMatrix::from_column_slice(k, k, &a).lu();
            let mut lu = a.clone();
            let mut swaps = vec![(0, 0); k];
            let n = lu_in_place(&mut lu, k, &mut swaps);
            prop_assert_eq!(bits(&lu), bits(theirs.lu_internal().as_slice()));
            let mut x = b.to_vec();
            let solved = lu_solve(&lu, k, &swaps[..n], &mut x);
            match theirs.solve(&DVector::from_column_slice(b)) {
                Some(y) => {
                    prop_assert!(solved);
                    prop_assert_eq!(bits(&x), bits(y.as_slice()));
                }
                None => prop_assert!(!solved),
            }
        }

        /// Bordering a factorised block gives the whole matrix's factors bit for bit, or
        /// declines (when a bordering row would have been a pivot).
        #[test]
        fn bordered_lu_matches_the_whole_bit_for_bit(
            (b, q) in (1usize..9, 1usize..4),
            seed in prop::collection::vec(-10.0..10.0_f64, 1..40),
            border in prop::collection::vec(prop_oneof![Just(0.0), -1.0..1.0_f64], 1..20),
            pattern in 0u8..4,
        ) {
            let k = b + q;
            // The leading block from the seed, the bordering rows and columns from `border`,
            // zero where they cross (as in a KKT matrix).
            let leading = matrix(b, &seed, pattern);
            let mut whole = vec![0.0; k * k];
            let mut next = border.iter().cycle();
            for c in 0..k {
                for r in 0..k {
                    whole[c * k + r] = match (r < b, c < b) {
                        (true, true) => leading[c * b + r],
                        (false, false) => 0.0,
                        _ => *next.next().expect("cycled"),
                    };
                }
            }
            let mut expected = whole.clone();
            let mut expected_swaps = vec![(0, 0); k];
            let n = lu_in_place(&mut expected, k, &mut expected_swaps);
            let mut base = leading.clone();
            let mut base_swaps = vec![(0, 0); b];
            let n_base = lu_in_place(&mut base, b, &mut base_swaps);
            let mut got = whole.clone();
            let mut swaps = vec![(0, 0); k];
            if let Some(m) = lu_bordered(&mut got, k, &base, b, &base_swaps[..n_base], &mut swaps) {
                prop_assert_eq!(&swaps[..m], &expected_swaps[..n]);
                prop_assert_eq!(bits(&got), bits(&expected));
            }
        }

        /// The product and the largest magnitude give nalgebra's bits, signed zeros included.
        #[test]
        fn product_and_amax_match_nalgebra_bit_for_bit(
            (m, n) in (1usize..9, 0usize..9),
            seed in prop::collection::vec(prop_oneof![Just(0.0), Just(-0.0), -10.0..10.0_f64], 1..30),
            x in prop::collection::vec(prop_oneof![Just(-0.0), -10.0..10.0_f64], 9),
        ) {
            let a: Vec<f64> = (0..m * n).map(|i| seed[i % seed.len()]).collect();
            let x = &x[..n];
            let theirs = DMatrix::from_column_slice(m, n, &a);
            let mut out = vec![f64::NAN; m];
            mul_vec::<false>(&a, x, &mut out);
            let y = &theirs * DVector::from_column_slice(x);
            prop_assert_eq!(bits(&out), bits(y.as_slice()));
            mul_vec::<true>(&a, x, &mut out);
            let y = theirs.abs() * DVector::from_column_slice(x).abs();
            prop_assert_eq!(bits(&out), bits(y.as_slice()));
            prop_assert_eq!(amax(&out).to_bits(), y.amax().to_bits());
        }
    }

    /// The palm scene's KKT matrix of its way-back stop's row is bordered, not factorised
    /// whole: the bordering row's entries are below the pivots (the case the map relies on).
    #[test]
    fn bordering_applies_to_a_contact_row_below_the_pivots() {
        // Unknowns f_n, f_t of the ground, the stop's f_n, the joint's moment; three
        // equilibrium rows; the stop's row f_n >= 0 active.
        let e = [
            [0.0, -1.0, 1.0, 0.0],
            [1.0, 0.0, 0.0, 0.0],
            [0.0, -1.0, 0.7, 1.0],
        ];
        let (n, m_e, k) = (4, 3, 8);
        let mut whole = vec![0.0; k * k];
        for i in 0..3 {
            whole[i * k + i] = 1.0;
        }
        for (r, row) in e.iter().enumerate() {
            for (c, &v) in row.iter().enumerate() {
                whole[c * k + n + r] = v;
                whole[(n + r) * k + c] = v;
            }
        }
        whole[2 * k + 7] = 1.0;
        whole[7 * k + 2] = 1.0;
        let b = n + m_e;
        let mut base: Vec<f64> = (0..b)
            .flat_map(|c| whole[c * k..c * k + b].to_vec())
            .collect();
        let mut base_swaps = vec![(0, 0); b];
        let n_base = lu_in_place(&mut base, b, &mut base_swaps);
        let mut got = whole.clone();
        let mut swaps = vec![(0, 0); k];
        let m = lu_bordered(&mut got, k, &base, b, &base_swaps[..n_base], &mut swaps)
            .expect("the stop's row is never a pivot");
        let theirs = DMatrix::from_column_slice(k, k, &whole).lu();
        assert_eq!(bits(&got), bits(theirs.lu_internal().as_slice()));
        assert!(m >= n_base);
    }

    /// A NaN is passed over by the largest magnitude unless it comes last, as in nalgebra.
    #[test]
    fn amax_passes_over_nan_as_nalgebra_does() {
        for v in [
            [f64::NAN, 1.0, 2.0],
            [1.0, f64::NAN, 2.0],
            [1.0, 2.0, f64::NAN],
        ] {
            let theirs = DVector::from_column_slice(&v).amax();
            assert_eq!(amax(&v).to_bits(), theirs.to_bits(), "{v:?}");
        }
        assert_eq!(amax(&[]), 0.0);
    }
}
