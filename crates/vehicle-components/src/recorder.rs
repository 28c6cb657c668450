//! A named-channel recorder: a model declares its record columns from its components
//! ([`Channels`]), then pushes one row per output sample into storage reserved once
//! ([`Recorder::with_capacity`]) and reads columns back by name.
//!
//! Storage is column-major (`data[c * capacity + row]`), so every column is one contiguous
//! slice. Capacity is bounded ([`MAX_ROWS`], [`MAX_CELLS`]) before anything is allocated,
//! because the number of output samples usually comes from the user.

use std::ops::Range;

use crate::component::ChannelInfo;
use crate::error::{check_name, ComponentError};
use crate::layout::StateLayout;

/// Most rows one recorder holds.
pub const MAX_ROWS: usize = 10_000_000;

/// Most values (rows x channels) one recorder holds: 400 MB of `f64`.
pub const MAX_CELLS: usize = 50_000_000;

/// The declared record channels of a model: names (with unit suffix) and units, in column
/// order, all distinct.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Channels {
    names: Vec<String>,
    units: Vec<String>,
}

impl Channels {
    /// No channels yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// Declare one channel; returns its column index.
    pub fn push(&mut self, name: &str, unit: &str) -> Result<usize, ComponentError> {
        check_name(name)?;
        if self.names.iter().any(|n| n == name) {
            return Err(ComponentError::InvalidName {
                name: name.to_string(),
                reason: "this channel is already declared",
            });
        }
        self.names.push(name.to_string());
        self.units.push(unit.to_string());
        Ok(self.names.len() - 1)
    }

    /// Declare a component's channels, each named `<label>_<name>` (the bare name for an
    /// empty label); returns their column range, which is where the component's
    /// [`crate::Component::record`] writes. On error nothing is declared.
    pub fn extend(
        &mut self,
        label: &str,
        channels: &[ChannelInfo],
    ) -> Result<Range<usize>, ComponentError> {
        let start = self.names.len();
        for c in channels {
            let pushed = if label.is_empty() {
                self.push(c.name, c.unit)
            } else {
                self.push(&format!("{label}_{}", c.name), c.unit)
            };
            if let Err(e) = pushed {
                self.names.truncate(start);
                self.units.truncate(start);
                return Err(e);
            }
        }
        Ok(start..self.names.len())
    }

    /// Declare every state of `layout` as a channel (its global name and unit); returns the
    /// column range, in state order. On error nothing is declared.
    pub fn extend_states(&mut self, layout: &StateLayout) -> Result<Range<usize>, ComponentError> {
        let start = self.names.len();
        for (name, unit) in layout.names().iter().zip(layout.units()) {
            if let Err(e) = self.push(name, unit) {
                self.names.truncate(start);
                self.units.truncate(start);
                return Err(e);
            }
        }
        Ok(start..self.names.len())
    }

    /// Number of channels.
    pub fn len(&self) -> usize {
        self.names.len()
    }

    /// True when no channel is declared.
    pub fn is_empty(&self) -> bool {
        self.names.is_empty()
    }

    /// Channel names in column order.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// Channel units in column order.
    pub fn units(&self) -> &[String] {
        &self.units
    }

    /// Column index of channel `name`.
    pub fn index_of(&self, name: &str) -> Option<usize> {
        self.names.iter().position(|n| n == name)
    }
}

/// Rows of a fixed set of channels, stored column by column in memory reserved up front.
#[derive(Debug, Clone, PartialEq)]
pub struct Recorder {
    channels: Channels,
    capacity: usize,
    rows: usize,
    data: Vec<f64>,
}

impl Recorder {
    /// Reserve room for `rows` rows of `channels`. Errors, before allocating: `rows` above
    /// [`MAX_ROWS`], or `rows * channels` above [`MAX_CELLS`].
    pub fn with_capacity(channels: Channels, rows: usize) -> Result<Self, ComponentError> {
        if rows > MAX_ROWS {
            return Err(ComponentError::TooLarge {
                what: "recorder rows",
                requested: rows,
                limit: MAX_ROWS,
            });
        }
        let cells = rows.saturating_mul(channels.len());
        if cells > MAX_CELLS {
            return Err(ComponentError::TooLarge {
                what: "recorder rows x channels",
                requested: cells,
                limit: MAX_CELLS,
            });
        }
        Ok(Self {
            channels,
            capacity: rows,
            rows: 0,
            data: vec![0.0; cells],
        })
    }

    /// Append one row (one value per channel, in column order). Never allocates.
    pub fn push(&mut self, row: &[f64]) -> Result<(), ComponentError> {
        if row.len() != self.channels.len() {
            return Err(ComponentError::RowLength {
                expected: self.channels.len(),
                given: row.len(),
            });
        }
        if self.rows == self.capacity {
            return Err(ComponentError::Full {
                capacity: self.capacity,
            });
        }
        for (c, &v) in row.iter().enumerate() {
            self.data[c * self.capacity + self.rows] = v;
        }
        self.rows += 1;
        Ok(())
    }

    /// Forget all rows, keeping the channels and the reserved memory.
    pub fn clear(&mut self) {
        self.rows = 0;
    }

    /// Number of rows pushed.
    pub fn len(&self) -> usize {
        self.rows
    }

    /// True when no row has been pushed.
    pub fn is_empty(&self) -> bool {
        self.rows == 0
    }

    /// Rows reserved.
    pub fn capacity(&self) -> usize {
        self.capacity
    }

    /// The declared channels.
    pub fn channels(&self) -> &Channels {
        &self.channels
    }

    /// Column `index` (the pushed rows only); `None` past the last channel.
    pub fn column_at(&self, index: usize) -> Option<&[f64]> {
        (index < self.channels.len()).then(|| {
            let start = index * self.capacity;
            &self.data[start..start + self.rows]
        })
    }

    /// Column of channel `name` (the pushed rows only).
    pub fn column(&self, name: &str) -> Option<&[f64]> {
        self.column_at(self.channels.index_of(name)?)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::component::StateInfo;
    use proptest::prelude::*;

    const TIRE: [ChannelInfo; 2] = [ChannelInfo::new("fz_n", "N"), ChannelInfo::new("fy_n", "N")];

    #[test]
    fn channels_come_from_states_and_components() {
        let mut layout = StateLayout::new();
        layout
            .add("", &[StateInfo::new("p_c_pa", "Pa", 1e7)])
            .unwrap();
        let mut ch = Channels::new();
        assert_eq!(ch.push("time_s", "s").unwrap(), 0);
        assert_eq!(ch.extend_states(&layout).unwrap(), 1..2);
        assert_eq!(ch.extend("front", &TIRE).unwrap(), 2..4);
        assert_eq!(ch.extend("rear", &TIRE).unwrap(), 4..6);
        assert_eq!(ch.names()[3], "front_fy_n");
        assert_eq!(ch.units()[1], "Pa");
        // A clash declares nothing.
        assert!(ch.extend("front", &TIRE).is_err());
        assert!(ch.extend_states(&layout).is_err());
        assert_eq!(ch.len(), 6);
        assert!(ch.push("Bad", "-").is_err());
    }

    #[test]
    fn rows_become_columns_by_name() {
        let mut ch = Channels::new();
        ch.push("time_s", "s").unwrap();
        ch.push("p_c_pa", "Pa").unwrap();
        let mut r = Recorder::with_capacity(ch, 3).unwrap();
        assert!(r.is_empty());
        r.push(&[0.0, 1e5]).unwrap();
        r.push(&[0.1, 2e5]).unwrap();
        assert_eq!(r.column("time_s").unwrap(), &[0.0, 0.1]);
        assert_eq!(r.column("p_c_pa").unwrap(), &[1e5, 2e5]);
        assert_eq!(r.column("p_r_pa"), None);
        assert_eq!(r.column_at(2), None);
        let e = r.push(&[1.0]).unwrap_err();
        assert_eq!(
            e,
            ComponentError::RowLength {
                expected: 2,
                given: 1
            }
        );
        r.push(&[0.2, 3e5]).unwrap();
        assert_eq!(
            r.push(&[0.3, 4e5]),
            Err(ComponentError::Full { capacity: 3 })
        );
        assert_eq!(r.len(), 3);
        r.clear();
        assert_eq!(r.column("time_s").unwrap(), &[] as &[f64]);
        assert_eq!(r.capacity(), 3);
    }

    #[test]
    fn capacity_is_bounded_before_allocating() {
        let mut ch = Channels::new();
        for i in 0..10 {
            ch.push(&format!("c{i}_m"), "m").unwrap();
        }
        assert!(matches!(
            Recorder::with_capacity(ch.clone(), MAX_ROWS + 1),
            Err(ComponentError::TooLarge { .. })
        ));
        assert!(matches!(
            Recorder::with_capacity(ch.clone(), MAX_CELLS / 10 + 1),
            Err(ComponentError::TooLarge { .. })
        ));
        assert!(Recorder::with_capacity(ch, usize::MAX).is_err());
    }

    proptest! {
        #[test]
        fn columns_equal_the_pushed_rows(
            n_ch in 1usize..6,
            values in prop::collection::vec(-1e6..1e6f64, 0..120),
            spare in 0usize..4,
        ) {
            let mut ch = Channels::new();
            for i in 0..n_ch {
                ch.push(&format!("c{i}_m"), "m").unwrap();
            }
            let rows: Vec<&[f64]> = values.chunks_exact(n_ch).collect();
            let mut r = Recorder::with_capacity(ch, rows.len() + spare).unwrap();
            for row in &rows {
                r.push(row).unwrap();
            }
            prop_assert_eq!(r.len(), rows.len());
            for c in 0..n_ch {
                let col = r.column(&format!("c{c}_m")).unwrap();
                let expect: Vec<f64> = rows.iter().map(|row| row[c]).collect();
                prop_assert_eq!(col, &expect[..]);
            }
        }
    }
}
