//! One global state vector for a vehicle, cut into contiguous blocks, one per component.
//!
//! A vehicle adds its components in order; each gets the next `n_states` entries of the
//! global vector, a [`BlockId`], and its states' global names (`<label>_<name>`, or the bare
//! name for an empty label), units and typical magnitudes. In the right-hand side the vehicle
//! hands each component [`StateLayout::slice`] of the state and
//! [`StateLayout::slice_mut`] of the derivative: plain sub-slices, no allocation.

use std::ops::Range;

use crate::component::StateInfo;
use crate::error::{check_name, ComponentError};

/// Most states one layout holds (a bound for vehicles built from user input).
pub const MAX_STATES: usize = 4096;

/// Handle of one block, valid for the layout that issued it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct BlockId(usize);

#[derive(Debug, Clone, PartialEq)]
struct Block {
    label: String,
    start: usize,
    len: usize,
}

/// Contiguous blocks of one global state vector, with the global name, unit and typical
/// magnitude of every entry.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct StateLayout {
    blocks: Vec<Block>,
    names: Vec<String>,
    units: Vec<&'static str>,
    typical: Vec<f64>,
}

impl StateLayout {
    /// An empty layout.
    pub fn new() -> Self {
        Self::default()
    }

    /// Append a block for a component labelled `label` (`[a-z0-9_]` or empty) with `states`.
    /// Errors: a bad label or state (see [`StateInfo::check`]), a global name already in
    /// the layout, or more than [`MAX_STATES`] states in all.
    pub fn add(&mut self, label: &str, states: &[StateInfo]) -> Result<BlockId, ComponentError> {
        if !label.is_empty() {
            check_name(label)?;
        }
        let requested = self.names.len() + states.len();
        if requested > MAX_STATES {
            return Err(ComponentError::TooLarge {
                what: "states in the layout",
                requested,
                limit: MAX_STATES,
            });
        }
        let mut fresh: Vec<String> = Vec::with_capacity(states.len());
        for s in states {
            s.check()?;
            let name = if label.is_empty() {
                s.name.to_string()
            } else {
                format!("{label}_{}", s.name)
            };
            if self.names.contains(&name) || fresh.contains(&name) {
                return Err(ComponentError::InvalidName {
                    name,
                    reason: "this state name is already in the layout",
                });
            }
            fresh.push(name);
        }
        let id = BlockId(self.blocks.len());
        self.blocks.push(Block {
            label: label.to_string(),
            start: self.names.len(),
            len: states.len(),
        });
        self.names.extend(fresh);
        self.units.extend(states.iter().map(|s| s.unit));
        self.typical.extend(states.iter().map(|s| s.typical));
        Ok(id)
    }

    /// Length of the global state vector.
    pub fn len(&self) -> usize {
        self.names.len()
    }

    /// True when no block holds a state.
    pub fn is_empty(&self) -> bool {
        self.names.is_empty()
    }

    /// Number of blocks (including blocks of stateless components).
    pub fn n_blocks(&self) -> usize {
        self.blocks.len()
    }

    /// Index range of block `id` in the global vector.
    ///
    /// Panics if `id` was issued by another layout with more blocks.
    pub fn range(&self, id: BlockId) -> Range<usize> {
        let b = &self.blocks[id.0];
        b.start..b.start + b.len
    }

    /// Label the block was added with.
    pub fn label(&self, id: BlockId) -> &str {
        &self.blocks[id.0].label
    }

    /// The blocks in order.
    pub fn block_ids(&self) -> impl Iterator<Item = BlockId> {
        (0..self.blocks.len()).map(BlockId)
    }

    /// Block `id` of the global vector `global`.
    ///
    /// Panics if `global` is shorter than [`StateLayout::len`].
    #[inline]
    pub fn slice<'a>(&self, id: BlockId, global: &'a [f64]) -> &'a [f64] {
        &global[self.range(id)]
    }

    /// Block `id` of the global vector `global`, mutable.
    ///
    /// Panics if `global` is shorter than [`StateLayout::len`].
    #[inline]
    pub fn slice_mut<'a>(&self, id: BlockId, global: &'a mut [f64]) -> &'a mut [f64] {
        let r = self.range(id);
        &mut global[r]
    }

    /// Global names, one per entry of the state vector.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// Units, one per entry.
    pub fn units(&self) -> &[&'static str] {
        &self.units
    }

    /// Typical magnitudes, one per entry.
    pub fn typicals(&self) -> &[f64] {
        &self.typical
    }

    /// Global index of the state called `name`.
    pub fn index_of(&self, name: &str) -> Option<usize> {
        self.names.iter().position(|n| n == name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    const STEER: [StateInfo; 3] = [
        StateInfo::new("p_c_pa", "Pa", 1e7),
        StateInfo::new("p_r_pa", "Pa", 1e7),
        StateInfo::new("theta_h_rad", "rad", 0.1),
    ];
    const TIRE: [StateInfo; 2] = [
        StateInfo::new("kappa", "-", 0.1),
        StateInfo::new("alpha_rad", "rad", 0.05),
    ];

    #[test]
    fn blocks_get_their_slices_and_global_names() {
        let mut l = StateLayout::new();
        let s = l.add("", &STEER).unwrap();
        let none = l.add("driver", &[]).unwrap();
        let f = l.add("front", &TIRE).unwrap();
        let r = l.add("rear", &TIRE).unwrap();
        assert_eq!(l.len(), 7);
        assert_eq!(l.n_blocks(), 4);
        assert_eq!(l.range(s), 0..3);
        assert_eq!(l.range(none), 3..3);
        assert_eq!(l.range(f), 3..5);
        assert_eq!(l.range(r), 5..7);
        assert_eq!(l.label(r), "rear");
        assert_eq!(l.names()[3], "front_kappa");
        assert_eq!(l.names()[6], "rear_alpha_rad");
        assert_eq!(l.units()[2], "rad");
        assert_eq!(l.typicals()[0], 1e7);
        assert_eq!(l.index_of("rear_kappa"), Some(5));
        assert_eq!(l.index_of("kappa"), None);
        let mut x = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0];
        assert_eq!(l.slice(f, &x), &[3.0, 4.0]);
        l.slice_mut(r, &mut x).copy_from_slice(&[-1.0, -2.0]);
        assert_eq!(x[5..], [-1.0, -2.0]);
        assert!(l.slice(none, &x).is_empty());
    }

    #[test]
    fn duplicate_and_bad_names_are_refused() {
        let mut l = StateLayout::new();
        l.add("front", &TIRE).unwrap();
        let e = l.add("front", &TIRE).unwrap_err().to_string();
        assert!(e.contains("front_kappa"), "{e}");
        assert!(l.add("Rear", &TIRE).is_err());
        let twice = [TIRE[0], TIRE[0]];
        assert!(l.add("rear", &twice).is_err());
        assert!(l.add("x", &[StateInfo::new("v", "m/s", -1.0)]).is_err());
        // Nothing was added by the failed calls.
        assert_eq!(l.len(), 2);
        assert_eq!(l.n_blocks(), 1);
    }

    #[test]
    fn the_state_count_is_bounded() {
        let one = [StateInfo::new("x_m", "m", 1.0)];
        let mut l = StateLayout::new();
        for i in 0..MAX_STATES {
            l.add(&format!("c{i}"), &one).unwrap();
        }
        let e = l.add("last", &one).unwrap_err();
        assert!(matches!(e, ComponentError::TooLarge { .. }), "{e}");
    }

    const POOL: [StateInfo; 4] = [
        StateInfo::new("a_m", "m", 1.0),
        StateInfo::new("b_m", "m", 1.0),
        StateInfo::new("c_m", "m", 1.0),
        StateInfo::new("d_m", "m", 1.0),
    ];

    proptest! {
        #[test]
        fn blocks_are_disjoint_and_cover_the_vector(sizes in prop::collection::vec(0usize..=4, 0..12)) {
            let mut l = StateLayout::new();
            let ids: Vec<BlockId> = sizes
                .iter()
                .enumerate()
                .map(|(i, &n)| l.add(&format!("c{i}"), &POOL[..n]).unwrap())
                .collect();
            prop_assert_eq!(l.len(), sizes.iter().sum::<usize>());
            // Every index belongs to exactly one block.
            let mut owner = vec![0usize; l.len()];
            for (&id, &n) in ids.iter().zip(&sizes) {
                let r = l.range(id);
                prop_assert_eq!(r.len(), n);
                for i in r {
                    owner[i] += 1;
                }
            }
            prop_assert!(owner.iter().all(|&c| c == 1));
            // Writing each block through its slice touches only that block.
            let mut x = vec![0.0; l.len()];
            for (k, &id) in ids.iter().enumerate() {
                for v in l.slice_mut(id, &mut x) {
                    *v = k as f64;
                }
            }
            for (k, &id) in ids.iter().enumerate() {
                prop_assert!(l.slice(id, &x).iter().all(|&v| v == k as f64));
            }
            prop_assert_eq!(l.block_ids().count(), sizes.len());
        }
    }
}
