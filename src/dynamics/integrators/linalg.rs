//! Dense LU decomposition with partial pivoting for the small Newton systems of Radau5.

/// LU factors of a row-major n x n matrix, in place, with the row permutation.
#[derive(Debug, Clone, Default)]
pub struct Lu {
    n: usize,
    a: Vec<f64>,
    piv: Vec<usize>,
}

impl Lu {
    /// Factors `a` (row-major n x n). Returns false if it is singular to working precision.
    pub fn factor(&mut self, n: usize, a: &[f64]) -> bool {
        self.n = n;
        self.a.clear();
        self.a.extend_from_slice(a);
        self.piv.clear();
        self.piv.extend(0..n);
        let m = &mut self.a;
        for k in 0..n {
            let (mut p, mut best) = (k, m[k * n + k].abs());
            for i in k + 1..n {
                let v = m[i * n + k].abs();
                if v > best {
                    p = i;
                    best = v;
                }
            }
            if best.is_nan() || best <= 0.0 || !best.is_finite() {
                return false;
            }
            if p != k {
                for j in 0..n {
                    m.swap(k * n + j, p * n + j);
                }
                self.piv.swap(k, p);
            }
            let d = m[k * n + k];
            for i in k + 1..n {
                let l = m[i * n + k] / d;
                m[i * n + k] = l;
                if l != 0.0 {
                    for j in k + 1..n {
                        m[i * n + j] -= l * m[k * n + j];
                    }
                }
            }
        }
        true
    }

    /// Solves A x = b in place of `b`.
    pub fn solve(&self, b: &mut [f64], work: &mut Vec<f64>) {
        let n = self.n;
        let m = &self.a;
        work.clear();
        work.extend(self.piv.iter().map(|&p| b[p]));
        for i in 0..n {
            let mut s = work[i];
            for j in 0..i {
                s -= m[i * n + j] * work[j];
            }
            work[i] = s;
        }
        for i in (0..n).rev() {
            let mut s = work[i];
            for j in i + 1..n {
                s -= m[i * n + j] * work[j];
            }
            work[i] = s / m[i * n + i];
        }
        b.copy_from_slice(work);
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
        lu.solve(&mut b, &mut Vec::new());
        for i in 0..3 {
            assert!((b[i] - x[i]).abs() < 1e-14, "{b:?}");
        }
        assert!(!lu.factor(2, &[1.0, 2.0, 2.0, 4.0]));
    }
}
