//! Tree-sparse `L^T D L` factorisation of the joint-space mass matrix (Featherstone,
//! "Rigid Body Dynamics Algorithms", 2008, section 6.5, Tables 6.3 and 6.4; the packed
//! row layout follows MuJoCo's `mj_factorM`).
//!
//! With the degrees of freedom numbered so that every dof's parent `λ(k)` comes before it
//! (the expanded parent array of the tree: the previous dof of the same joint, else the
//! last dof of the nearest ancestor joint that has one), `H[k, j] = 0` unless one of `k`, `j`
//! is an ancestor of the other. Factorising from the leaves inwards,
//! `H = L^T D L` with `L` unit lower triangular and `D` diagonal keeps that pattern (no
//! fill-in), so row `k` of `H`, `L` needs only the entries of its ancestor chain
//! `k, λ(k), λ(λ(k)), ...`. Those chains are stored row after row in one packed buffer
//! whose structure is computed once per model, and the chain of an ancestor `i` of `k` is a
//! suffix of `k`'s, so the elimination step `H[i, j] -= a H[k, j]` for all `j` in the chain
//! of `i` is one contiguous loop over two slices.

use crate::joint::Joint;
use crate::model::{Body, Link};

/// Marks a dof with no parent dof (a chain root).
pub(crate) const NONE: usize = usize::MAX;

/// The expanded parent array and the packed row structure of the mass matrix, computed
/// once by [`crate::ModelBuilder::build`].
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct DofTree {
    /// `λ(k)`: the parent dof of dof `k`, [`NONE`] for a chain root.
    pub(crate) parent: Vec<usize>,
    /// Row `k` occupies `packed[row[k]..row[k + 1]]`.
    row: Vec<usize>,
    /// Column of every packed entry: row `k` holds the chain `k, λ(k), λ(λ(k)), ...`.
    col: Vec<usize>,
    /// Start of the row of every packed entry's column, `row[col[e]]`.
    col_row: Vec<usize>,
    /// Column-major offsets `(k + nv j, j + nv k)` of every packed entry `(k, j)` and its
    /// mirror in the dense `nv x nv` matrix.
    pub(crate) dense: Vec<(usize, usize)>,
    /// `m` for the dofs of a floating root joint, whose motion subspace column in the
    /// root frame is the unit vector `e_m` (so `H[k, j] = (I^c S̄_k)[m]`), else [`NONE`].
    pub(crate) unit_axis: Vec<usize>,
    /// Number of leading entries of each row that are not such unit-axis dofs (those
    /// come last: they belong to the tree's root).
    split: Vec<usize>,
}

impl DofTree {
    /// Builds the expanded parent array (Featherstone 2008, section 6.5) of the tree
    /// given by `bodies` and `links`, and the packed rows of its ancestor chains.
    pub(crate) fn new(bodies: &[Body], links: &[Link]) -> Self {
        // Last dof of each body's joint, or the nearest ancestor's (NONE if no ancestor
        // joint moves).
        let mut last = vec![NONE; bodies.len()];
        let mut parent = Vec::new();
        for (i, (body, link)) in bodies.iter().zip(links).enumerate() {
            let inherited = body.parent.map_or(NONE, |p| last[p]);
            for k in 0..link.nv {
                parent.push(if k == 0 {
                    inherited
                } else {
                    link.v_offset + k - 1
                });
            }
            last[i] = if link.nv > 0 {
                link.v_offset + link.nv - 1
            } else {
                inherited
            };
        }
        let mut unit_axis = vec![NONE; parent.len()];
        for (body, link) in bodies.iter().zip(links) {
            if body.parent.is_none() && body.joint == Joint::Floating {
                for (m, axis) in unit_axis[link.v_offset..link.v_offset + 6]
                    .iter_mut()
                    .enumerate()
                {
                    *axis = m;
                }
            }
        }
        Self::from_parents(parent, unit_axis)
    }

    /// The packed rows of the ancestor chains of the parent array `parent`
    /// (`parent[k] < k` or [`NONE`]), with the unit-axis dofs `unit_axis`.
    fn from_parents(parent: Vec<usize>, unit_axis: Vec<usize>) -> Self {
        let mut row = vec![0];
        let mut col = Vec::new();
        for k in 0..parent.len() {
            let mut j = k;
            while j != NONE {
                col.push(j);
                j = parent[j];
            }
            row.push(col.len());
        }
        let split = (0..parent.len())
            .map(|k| {
                let cols = &col[row[k]..row[k + 1]];
                cols.iter().take_while(|&&j| unit_axis[j] == NONE).count()
            })
            .collect();
        let col_row = col.iter().map(|&j| row[j]).collect();
        let nv = parent.len();
        let dense = (0..nv)
            .flat_map(|k| col[row[k]..row[k + 1]].iter().map(move |&j| (k, j)))
            .map(|(k, j)| (k + nv * j, j + nv * k))
            .collect();
        Self {
            parent,
            row,
            col,
            col_row,
            dense,
            unit_axis,
            split,
        }
    }

    /// Number of degrees of freedom.
    pub(crate) fn nv(&self) -> usize {
        self.parent.len()
    }

    /// Number of packed entries (the lower triangle's structural non-zeros).
    pub(crate) fn nnz(&self) -> usize {
        self.col.len()
    }

    /// Packed range of row `k`.
    #[inline]
    pub(crate) fn row(&self, k: usize) -> std::ops::Range<usize> {
        self.row[k]..self.row[k + 1]
    }

    /// Columns of row `k`: `k` itself, then its ancestors, nearest first.
    #[inline]
    pub(crate) fn cols(&self, k: usize) -> &[usize] {
        &self.col[self.row(k)]
    }

    /// Row `k`'s packed range and columns, split into the entries of general dofs and
    /// the trailing entries of unit-axis dofs (see [`Self::unit_axis`]).
    #[inline]
    pub(crate) fn split_row(&self, k: usize) -> (usize, &[usize], &[usize]) {
        let start = self.row[k];
        let (general, unit) = self.cols(k).split_at(self.split[k]);
        (start, general, unit)
    }

    /// End of the entries of row `k` that the general loops handle: the row's end, or, for
    /// a row below a floating root (not of the root itself), the start of the root's six
    /// trailing entries, which the fixed-size code handles.
    #[inline]
    fn general_end(&self, k: usize) -> usize {
        let (start, end) = (self.row[k], self.row[k + 1]);
        let split = self.split[k];
        if split > 0 && end - start - split == 6 {
            start + split
        } else {
            end
        }
    }

    /// Factorises in place the packed rows of `H` into `L^T D L` (Featherstone 2008,
    /// Table 6.3): afterwards the first entry of row `k` is `D[k]` and the others are
    /// `L[k, j]` along the chain. Returns `false`, leaving `packed` partly factorised, as
    /// soon as a pivot `D[k]` is not finite and positive, i.e. `H` is not positive definite.
    pub(crate) fn factor(&self, packed: &mut [f64]) -> bool {
        let mut next = self.nv();
        while next > 0 {
            let k = next - 1;
            next = k;
            if self.unit_axis[k] == 5 {
                // The last dof of a floating root: its six rows are the 21 entries from
                // the row of its first dof, factorised by fixed-size code.
                next = k - 5;
                let base = self.row[next];
                if !factor_root_block(&mut packed[base..base + 21]) {
                    return false;
                }
                continue;
            }
            let (start, end) = (self.row[k], self.row[k + 1]);
            let (head, tail) = packed.split_at_mut(start);
            let row_k = &mut tail[..end - start];
            let d = row_k[0];
            if !(d.is_finite() && d > 0.0) {
                return false;
            }
            let inv_d = 1.0 / d;
            // A row below a floating root ends with that root's six dofs, whose rows are
            // the 21 packed entries from the root's first row on: eliminated by
            // `eliminate_into_root`, the general loop stops before them.
            let general_end = self.general_end(k);
            let split = general_end - start;
            // Entry `p` of row `k` is `H[k, i]` for the ancestor `i`, whose row holds the
            // columns of row `k` from position `p` on.
            for (p, &ri) in self.col_row[start + 1..general_end].iter().enumerate() {
                let p = p + 1;
                let n = row_k.len() - p;
                let a = row_k[p] * inv_d;
                sub_scaled(&mut head[ri..ri + n], a, &row_k[p..]);
                row_k[p] = a;
            }
            if general_end < end {
                let base = self.col_row[end - 1];
                eliminate_into_root(&mut head[base..base + 21], &mut row_k[split..], inv_d);
            }
        }
        true
    }

    /// Solves `H x = b` in place (`x` holds `b` on entry) with the factor of
    /// [`Self::factor`] (Featherstone 2008, Table 6.4): `L^T z = b` from the leaves
    /// inwards, then `L x = D^-1 z` from the roots outwards.
    pub(crate) fn solve(&self, packed: &[f64], x: &mut [f64]) {
        // A floating root's block and the trailing root entries of the rows below it run
        // in fixed-size code (the same operations in the same order as the general loops).
        let mut next = self.nv();
        while next > 0 {
            let k = next - 1;
            next = k;
            if self.unit_axis[k] == 5 {
                next = k - 5;
                let base = self.row[next];
                root_block_transpose_solve(&packed[base..base + 21], &mut x[next..next + 6]);
                continue;
            }
            let (start, end) = (self.row[k], self.row[k + 1]);
            let general_end = self.general_end(k);
            let xk = x[k];
            for (l, &j) in packed[start + 1..general_end]
                .iter()
                .zip(&self.col[start + 1..general_end])
            {
                x[j] -= l * xk;
            }
            if general_end < end {
                let root = self.col[end - 1];
                let l: &[f64; 6] = packed[general_end..end]
                    .try_into()
                    .expect("six root entries");
                let xr: &mut [f64; 6] = (&mut x[root..root + 6]).try_into().expect("six root dofs");
                for t in 0..6 {
                    xr[5 - t] -= l[t] * xk;
                }
            }
        }
        let mut k = 0;
        while k < self.nv() {
            if self.unit_axis[k] == 0 {
                let base = self.row[k];
                root_block_solve(&packed[base..base + 21], &mut x[k..k + 6]);
                k += 6;
                continue;
            }
            let (start, end) = (self.row[k], self.row[k + 1]);
            let general_end = self.general_end(k);
            let mut xk = x[k] / packed[start];
            for (l, &j) in packed[start + 1..general_end]
                .iter()
                .zip(&self.col[start + 1..general_end])
            {
                xk -= l * x[j];
            }
            if general_end < end {
                let root = self.col[end - 1];
                let l: &[f64; 6] = packed[general_end..end]
                    .try_into()
                    .expect("six root entries");
                let xr: &[f64; 6] = x[root..root + 6].try_into().expect("six root dofs");
                for t in 0..6 {
                    xk -= l[t] * xr[5 - t];
                }
            }
            x[k] = xk;
            k += 1;
        }
    }
}

/// The first half of [`DofTree::solve`], `L^T z = b`, on a floating root's six rows (the
/// 21 packed entries `block`, row `m` at `m (m + 1) / 2`, columns `m, m - 1, ..., 0`) and
/// its six entries `x`. Fixed sizes, so the loops unroll.
#[inline(always)]
fn root_block_transpose_solve(block: &[f64], x: &mut [f64]) {
    let block: &[f64; 21] = block.try_into().expect("a floating root has 21 entries");
    let x: &mut [f64; 6] = x.try_into().expect("a floating root has 6 dofs");
    for m in (0..6).rev() {
        let row = m * (m + 1) / 2;
        let xm = x[m];
        for t in 1..=m {
            x[m - t] -= block[row + t] * xm;
        }
    }
}

/// The second half of [`DofTree::solve`], `L x = D^-1 z`, on a floating root's six rows
/// (layout as in [`root_block_transpose_solve`]).
#[inline(always)]
fn root_block_solve(block: &[f64], x: &mut [f64]) {
    let block: &[f64; 21] = block.try_into().expect("a floating root has 21 entries");
    let x: &mut [f64; 6] = x.try_into().expect("a floating root has 6 dofs");
    for m in 0..6 {
        let row = m * (m + 1) / 2;
        let mut xm = x[m] / block[row];
        for t in 1..=m {
            xm -= block[row + t] * x[m - t];
        }
        x[m] = xm;
    }
}

/// The elimination steps of [`DofTree::factor`] for the six trailing entries `h` of a row
/// (pivot `1 / inv_d`) whose columns are the dofs `5, 4, ..., 0` of a floating root, whose
/// rows are packed in `block` (row `m` at `m (m + 1) / 2`, length `m + 1`). Fixed sizes, so
/// the loops unroll.
#[inline(always)]
fn eliminate_into_root(block: &mut [f64], h: &mut [f64], inv_d: f64) {
    let block: &mut [f64; 21] = block.try_into().expect("a floating root has 21 entries");
    let h: &mut [f64; 6] = h.try_into().expect("a floating root has 6 dofs");
    for t in 0..6 {
        let m = 5 - t;
        let a = h[t] * inv_d;
        let row = m * (m + 1) / 2;
        for u in 0..=m {
            block[row + u] -= a * h[t + u];
        }
        h[t] = a;
    }
}

/// [`DofTree::factor`] on the 21 packed entries of a floating root's rows (row `m` at
/// `m (m + 1) / 2`, columns `m, m - 1, ..., 0`): the same operations in the same order,
/// with fixed sizes so the loops unroll. `false` if a pivot is not finite and positive.
#[inline(always)]
fn factor_root_block(block: &mut [f64]) -> bool {
    let block: &mut [f64; 21] = block.try_into().expect("a floating root has 21 entries");
    for m in (0..6).rev() {
        let row = m * (m + 1) / 2;
        let d = block[row];
        if !(d.is_finite() && d > 0.0) {
            return false;
        }
        let inv_d = 1.0 / d;
        for t in 1..=m {
            let i = m - t;
            let a = block[row + t] * inv_d;
            let row_i = i * (i + 1) / 2;
            for u in 0..=i {
                block[row_i + u] -= a * block[row + t + u];
            }
            block[row + t] = a;
        }
    }
    true
}

/// `y -= a x` over the common length (two distinct slices, so the loop needs no overlap
/// check).
#[inline(always)]
fn sub_scaled(y: &mut [f64], a: f64, x: &[f64]) {
    for (yi, xi) in y.iter_mut().zip(x) {
        *yi -= a * xi;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{DMatrix, DVector};
    use proptest::prelude::*;

    /// A tree from parent seeds: dof `k`'s parent is `seed % (k + 1)`, or none when that
    /// equals `k`; with `floating`, dofs 0 to 5 are instead a floating root's chain (unit
    /// axes) below whose last dof every other parent in it is moved, so the fixed-size root
    /// code runs.
    fn tree(seeds: &[usize], floating: bool) -> DofTree {
        let floating = floating && seeds.len() >= 6;
        let parent: Vec<usize> = seeds
            .iter()
            .enumerate()
            .map(|(k, s)| match (floating && k < 6, s % (k + 1)) {
                (true, _) => k.checked_sub(1).unwrap_or(NONE),
                (false, p) if p == k => NONE,
                (false, p) if floating && p < 6 => 5, // joints hang below the whole root
                (false, p) => p,
            })
            .collect();
        let unit_axis = (0..parent.len())
            .map(|k| if floating && k < 6 { k } else { NONE })
            .collect();
        DofTree::from_parents(parent, unit_axis)
    }

    /// `H = L^T D L` for a random unit lower-triangular `L` with the tree's pattern and
    /// `D > 0`, returned dense and packed.
    fn random_h(t: &DofTree, values: &[f64]) -> (DMatrix<f64>, Vec<f64>) {
        let n = t.nv();
        let mut l = DMatrix::identity(n, n);
        let mut d = DMatrix::zeros(n, n);
        for k in 0..n {
            let rk = t.row(k);
            d[(k, k)] = 0.1 + values[rk.start].abs() * 10.0;
            for (p, &j) in t.cols(k).iter().enumerate().skip(1) {
                l[(k, j)] = values[rk.start + p];
            }
        }
        let h = l.transpose() * d * l;
        let mut packed = vec![0.0; t.nnz()];
        for k in 0..n {
            for (p, &j) in t.cols(k).iter().enumerate() {
                packed[t.row[k] + p] = h[(k, j)];
            }
        }
        (h, packed)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(300))]
        #[test]
        fn sparse_ltdl_solves_like_dense_cholesky(
            seeds in prop::collection::vec(0..1000usize, 1..20),
            floating in any::<bool>(),
            values in prop::collection::vec(-2.0..2.0_f64, 210),
            rhs in prop::collection::vec(-5.0..5.0_f64, 20),
        ) {
            let t = tree(&seeds, floating);
            let n = t.nv();
            let (h, mut packed) = random_h(&t, &values);
            // Entries off the ancestor chains are structural zeros of H.
            for k in 0..n {
                for j in 0..k {
                    if !t.cols(k).contains(&j) {
                        prop_assert_eq!(h[(k, j)], 0.0);
                    }
                }
            }
            prop_assert!(t.factor(&mut packed));
            let b = DVector::from_column_slice(&rhs[..n]);
            let dense = h.clone().cholesky().expect("H = L^T D L is definite").solve(&b);
            let mut x = rhs[..n].to_vec();
            t.solve(&packed, &mut x);
            // Two backward-stable solvers agree to about cond(H) times the rounding unit.
            let eig = h.clone().symmetric_eigen().eigenvalues;
            let cond = eig.amax() / eig.iter().fold(f64::INFINITY, |m, v| m.min(v.abs()));
            let scale = 1.0 + dense.amax();
            for k in 0..n {
                prop_assert!((x[k] - dense[k]).abs() <= 1e-14 * (1.0 + cond) * scale,
                    "x[{}] = {} vs dense {} (cond {})", k, x[k], dense[k], cond);
            }
            // The residual of the sparse solution is at rounding level.
            let r = &h * DVector::from_column_slice(&x) - &b;
            prop_assert!(r.amax() <= 1e-11 * (1.0 + h.amax() * scale));
        }
    }

    #[test]
    fn an_indefinite_matrix_is_refused() {
        let t = tree(&[0, 0, 1], false); // chain 0 <- 1 <- 2
                                         // H = [[1, 2, 0], [2, 1, 0], [0, 0, 1]] has eigenvalue -1.
        let mut packed = vec![1.0, 1.0, 2.0, 1.0, 0.0, 0.0];
        assert!(!t.factor(&mut packed));
        let mut nan = vec![1.0, f64::NAN, 0.0, 1.0, 0.0, 0.0];
        assert!(!t.factor(&mut nan));
    }

    #[test]
    fn chains_skip_fixed_joints_and_split_branches() {
        use crate::spatial::SpatialTransform;
        use nalgebra::{Isometry3, Matrix3, Vector3};
        let body = |parent, joint: Joint| Body {
            name: String::new(),
            parent,
            joint,
            placement: Isometry3::identity(),
            mass: 1.0,
            com: Vector3::zeros(),
            inertia: Matrix3::identity(),
        };
        let z = Vector3::z();
        let bodies = [
            body(None, Joint::Revolute { axis: z }),
            body(Some(0), Joint::Fixed),
            body(Some(1), Joint::Prismatic { axis: z }),
            body(Some(0), Joint::Revolute { axis: z }),
            body(None, Joint::Revolute { axis: z }),
        ];
        let mut v_offset = 0;
        let links: Vec<Link> = bodies
            .iter()
            .map(|b| {
                let link = Link {
                    x_tree: SpatialTransform::identity(),
                    tree_translation_only: true,
                    inertia: nalgebra::Matrix6::identity(),
                    rigid_inertia: crate::inertia::RigidInertia::zero(),
                    inertia_diagonal: true,
                    subspace: b.joint.motion_subspace(),
                    nv: b.joint.nv(),
                    q_offset: 0,
                    v_offset,
                };
                v_offset += b.joint.nv();
                link
            })
            .collect();
        let t = DofTree::new(&bodies, &links);
        assert_eq!(t.parent, vec![NONE, 0, 0, NONE]);
        assert_eq!(t.cols(1), &[1, 0]);
        assert_eq!(t.cols(2), &[2, 0]);
        assert_eq!(t.cols(3), &[3]);
        assert_eq!(t.nnz(), 6);
    }
}
