//! A cache grid built in order, a chunk at a time, when a chunk is first read.
//!
//! A run that may stop early reads only the start of its enveloping caches: the 3-D
//! vehicle's D2 roll run ends at rollover, on the prototype after about 25 of its 45 s, and
//! building the caches of the whole path took twice as long as the run itself. A
//! [`Grid`] holds the points in chunks of [`CHUNK`] points, each set once
//! ([`OnceLock`]). Reading a chunk that is not there yet locks the builder and builds every
//! chunk up to it, in order. So a builder whose next point depends on the last one (the
//! effective track's Newton iteration starts from the previous point's wheel height) gives
//! the same points, to the bit, as building the whole grid at once. A reader on another
//! thread waits for the chunk it needs and never sees one half built.

use std::fmt;
use std::sync::{Mutex, OnceLock};

/// Points per chunk: 12.8 m of track at the 3-D vehicle's 0.05 m grid.
pub(crate) const CHUNK: usize = 256;

/// One grid point: two values (an effective track's wheel height and slope).
pub(crate) type Point = [f64; 2];

/// Computes the grid's points one after the other, from the first.
pub(crate) type NextPoint = Box<dyn FnMut() -> Point + Send>;

/// One chunk's points, set once.
type Chunk = OnceLock<Box<[Point]>>;

/// `len` points, built when read ([`Grid::on_demand`]) or at once ([`Grid::built`]).
pub(crate) struct Grid {
    len: usize,
    chunks: Box<[Chunk]>,
    builder: Mutex<Builder>,
}

/// The chunks still to build, from `next_chunk` on, and what computes their points
/// (dropped with the profile it owns once every chunk is built).
struct Builder {
    next_chunk: usize,
    next_point: Option<NextPoint>,
}

impl Grid {
    /// A grid of the given points, all built.
    pub(crate) fn built(points: Vec<Point>) -> Self {
        let len = points.len();
        let chunks: Box<[_]> = points
            .chunks(CHUNK)
            .map(|c| OnceLock::from(Box::<[Point]>::from(c)))
            .collect();
        let next_chunk = chunks.len();
        Self {
            len,
            chunks,
            builder: Mutex::new(Builder {
                next_chunk,
                next_point: None,
            }),
        }
    }

    /// A grid of `len` points that `next_point` computes in order, chunk by chunk, as they
    /// are first read. `len` is bounded by the caller before this allocates its chunk list.
    pub(crate) fn on_demand(len: usize, next_point: NextPoint) -> Self {
        Self {
            len,
            chunks: (0..len.div_ceil(CHUNK)).map(|_| OnceLock::new()).collect(),
            builder: Mutex::new(Builder {
                next_chunk: 0,
                next_point: Some(next_point),
            }),
        }
    }

    /// Number of points.
    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// Point `k` (`k < len`), building the chunks up to it first if they are not built.
    #[inline]
    pub(crate) fn get(&self, k: usize) -> Point {
        let c = k / CHUNK;
        let chunk = match self.chunks[c].get() {
            Some(chunk) => chunk,
            None => self.build_to(c),
        };
        chunk[k % CHUNK]
    }

    /// Points `k` and `k + 1` (`k + 1 < len`), the two ends of a grid cell: one chunk look-up
    /// unless the cell straddles two chunks.
    #[inline]
    pub(crate) fn cell(&self, k: usize) -> (Point, Point) {
        let (c, j) = (k / CHUNK, k % CHUNK);
        let chunk = match self.chunks[c].get() {
            Some(chunk) => chunk,
            None => self.build_to(c),
        };
        match chunk.get(j + 1) {
            Some(next) => (chunk[j], *next),
            None => (chunk[j], self.get(k + 1)),
        }
    }

    /// Build every chunk up to `last` that is not built, in order, and return chunk `last`.
    #[cold]
    #[inline(never)]
    fn build_to(&self, last: usize) -> &[Point] {
        let mut builder = self
            .builder
            .lock()
            .expect("a cache builder panicked while it held the lock");
        while builder.next_chunk <= last {
            let c = builder.next_chunk;
            let n = CHUNK.min(self.len - c * CHUNK);
            let next_point = builder
                .next_point
                .as_mut()
                .expect("the builder is kept until the last chunk is built");
            let points: Box<[Point]> = (0..n).map(|_| next_point()).collect();
            // only the holder of the lock sets a chunk, and only this one
            let _ = self.chunks[c].set(points);
            builder.next_chunk += 1;
        }
        if builder.next_chunk == self.chunks.len() {
            builder.next_point = None;
        }
        drop(builder);
        self.chunks[last]
            .get()
            .expect("chunks up to `last` were built above or before")
    }

    /// Chunks built so far.
    fn built_chunks(&self) -> usize {
        self.chunks.iter().filter(|c| c.get().is_some()).count()
    }
}

impl fmt::Debug for Grid {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Grid")
            .field("len", &self.len)
            .field("chunks", &self.chunks.len())
            .field("built_chunks", &self.built_chunks())
            .finish()
    }
}

/// Two grids are equal when they hold the same points; comparing builds every chunk of
/// both.
impl PartialEq for Grid {
    fn eq(&self, other: &Self) -> bool {
        self.len == other.len && (0..self.len).all(|k| self.get(k) == other.get(k))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering};
    use std::sync::Arc;

    /// Points that depend on every point before them, as the Newton warm start makes the
    /// effective track's: any other build order would give other values.
    fn chained(calls: Arc<AtomicUsize>) -> NextPoint {
        let (mut k, mut x) = (0usize, 0.3f64);
        Box::new(move || {
            calls.fetch_add(1, Ordering::Relaxed);
            x = (3.9 * x * (1.0 - x)).clamp(1e-9, 1.0 - 1e-9);
            k += 1;
            [k as f64, x]
        })
    }

    fn all_at_once(len: usize) -> Vec<Point> {
        let mut next = chained(Arc::new(AtomicUsize::new(0)));
        (0..len).map(|_| next()).collect()
    }

    #[test]
    fn reads_in_any_order_give_the_points_of_the_whole_build_to_the_bit() {
        let len = 5 * CHUNK + 17;
        let whole = all_at_once(len);
        let calls = Arc::new(AtomicUsize::new(0));
        let grid = Grid::on_demand(len, chained(Arc::clone(&calls)));
        // a cell across the first two chunks builds both
        assert_eq!(grid.cell(CHUNK - 1), (whole[CHUNK - 1], whole[CHUNK]));
        assert_eq!(grid.built_chunks(), 2);
        // a read in the third chunk builds it and no more
        let k = 2 * CHUNK + 5;
        assert_eq!(grid.get(k), whole[k]);
        assert_eq!(calls.load(Ordering::Relaxed), 3 * CHUNK);
        assert_eq!(grid.built_chunks(), 3);
        // then backwards, scattered and past the end of the last full chunk
        for k in (0..len)
            .rev()
            .step_by(7)
            .chain([len - 1, 0, CHUNK, CHUNK - 1])
        {
            assert_eq!(
                grid.get(k).map(f64::to_bits),
                whole[k].map(f64::to_bits),
                "{k}"
            );
        }
        assert_eq!(
            calls.load(Ordering::Relaxed),
            len,
            "every point computed once"
        );
        assert!(grid.builder.lock().unwrap().next_point.is_none());
        assert_eq!(grid, Grid::built(whole));
    }

    #[test]
    fn threads_reading_at_once_each_see_whole_chunks_built_once() {
        let len = 40 * CHUNK;
        let whole = all_at_once(len);
        let calls = Arc::new(AtomicUsize::new(0));
        let grid = Grid::on_demand(len, chained(Arc::clone(&calls)));
        std::thread::scope(|scope| {
            for t in 0..4 {
                let (grid, whole) = (&grid, &whole);
                scope.spawn(move || {
                    for k in (t..len).step_by(61 + 10 * t) {
                        assert_eq!(grid.get(k), whole[k], "thread {t}, point {k}");
                    }
                });
            }
        });
        assert_eq!(calls.load(Ordering::Relaxed), len);
    }

    #[test]
    fn a_grid_built_at_once_needs_no_builder() {
        let grid = Grid::built(all_at_once(CHUNK + 1));
        assert_eq!(grid.len(), CHUNK + 1);
        assert_eq!(grid.built_chunks(), 2);
        let whole = all_at_once(CHUNK + 1);
        assert_eq!(grid.get(CHUNK), whole[CHUNK]);
        // a cell inside a chunk and one that straddles two
        assert_eq!(grid.cell(3), (whole[3], whole[4]));
        assert_eq!(grid.cell(CHUNK - 1), (whole[CHUNK - 1], whole[CHUNK]));
        assert!(format!("{grid:?}").contains("built_chunks: 2"));
    }
}
