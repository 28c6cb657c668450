//! The replays of one record kept for reuse ([`ReplayCache`]).

use crate::DiscoveryError;
use std::collections::VecDeque;
use std::sync::Mutex;

/// The last [`CACHE_ENTRIES`] replays of one record, keyed by the vehicle-side inputs (the
/// baseline vector and the model-side effects' values, bit for bit): a fit of a sensor
/// effect (mount, misalignment) varies only what is applied after the replay, so its
/// Jacobian columns and its line searches reuse the integration instead of repeating it.
#[derive(Debug, Default)]
pub struct ReplayCache(Mutex<VecDeque<(Vec<u64>, Channels)>>);

/// Predicted series per entry of [`CHANNELS`].
pub(crate) type Channels = Vec<Option<Vec<f64>>>;

/// Replays kept per record.
pub const CACHE_ENTRIES: usize = 24;

/// Cache-key marks of `driver-throttle`'s replays: the replay that finds the following
/// setpoint, and the replay at a gain (followed by the gain's bits).
pub(crate) const FOLLOW_KEY: u64 = u64::MAX;
/// See [`FOLLOW_KEY`].
pub(crate) const GAIN_KEY: u64 = u64::MAX - 1;
/// Cache-key mark of a replay under another reading of `cam-spacing` (followed by it).
pub(crate) const READING_KEY: u64 = u64::MAX - 2;

impl Clone for ReplayCache {
    fn clone(&self) -> Self {
        Self::default()
    }
}

impl ReplayCache {
    /// The cached channels for `key`, else `run()`'s, stored.
    pub(crate) fn get_or(
        &self,
        key: Vec<u64>,
        run: impl FnOnce() -> Result<Channels, DiscoveryError>,
    ) -> Result<Channels, DiscoveryError> {
        let lock = || self.0.lock().unwrap_or_else(|e| e.into_inner());
        if let Some((_, ch)) = lock().iter().find(|(k, _)| *k == key) {
            return Ok(ch.clone());
        }
        let ch = run()?;
        let mut c = lock();
        if c.len() >= CACHE_ENTRIES {
            c.pop_front();
        }
        c.push_back((key, ch.clone()));
        Ok(ch)
    }
}
