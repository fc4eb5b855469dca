//! The small Newton systems of RADAU5, solved by nalgebra's LU with partial pivoting.

use nalgebra::{DMatrix, DVectorViewMut, Dyn, LU};

/// LU factors of an n x n matrix, kept for the solves of one step.
#[derive(Debug, Clone, Default)]
pub struct Lu {
    lu: Option<LU<f64, Dyn, Dyn>>,
}

impl Lu {
    /// Factors `a` (row-major n x n). Returns false if it is singular or not finite.
    pub fn factor(&mut self, n: usize, a: &[f64]) -> bool {
        if !a.iter().all(|v| v.is_finite()) {
            self.lu = None;
            return false;
        }
        let lu = DMatrix::from_row_slice(n, n, a).lu();
        let ok = lu.is_invertible();
        self.lu = ok.then_some(lu);
        ok
    }

    /// Solves A x = b in place of `b` (A as last factored successfully).
    pub fn solve(&self, b: &mut [f64]) {
        if let Some(lu) = &self.lu {
            let n = b.len();
            lu.solve_mut(&mut DVectorViewMut::from_slice(b, n));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_a_pivoting_system() {
        let a = [0.0, 2.0, 1.0, 1.0, 1.0, 0.0, 3.0, 0.0, 1.0];
        let x = [1.0, -2.0, 3.0];
        let mut b: Vec<f64> = (0..3)
            .map(|i| (0..3).map(|j| a[3 * i + j] * x[j]).sum())
            .collect();
        let mut lu = Lu::default();
        assert!(lu.factor(3, &a));
        lu.solve(&mut b);
        for i in 0..3 {
            assert!((b[i] - x[i]).abs() < 1e-14, "{b:?}");
        }
        assert!(!lu.factor(2, &[1.0, 2.0, 2.0, 4.0]));
        assert!(!lu.factor(1, &[f64::NAN]));
    }
}
