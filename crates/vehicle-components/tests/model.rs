//! A small model built the way a vehicle uses the layer: two components in one state
//! layout, record channels declared from them, Euler steps recorded into a recorder, and no
//! allocation inside the loop (counted by a global allocator; one test in this binary, so
//! no other thread allocates meanwhile).

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

use vehicle_components::{ChannelInfo, Channels, Component, Recorder, StateInfo, StateLayout};

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// `dx/dt = (u - x) / tau`, output `x`.
struct Lag {
    tau: f64,
}

const LAG_STATES: [StateInfo; 1] = [StateInfo::new("x_m", "m", 0.1)];
const LAG_CHANNELS: [ChannelInfo; 1] = [ChannelInfo::new("rate_m_per_s", "m/s")];

impl Component for Lag {
    type Input = f64;
    type Output = f64;
    fn states(&self) -> &[StateInfo] {
        &LAG_STATES
    }
    fn channels(&self) -> &[ChannelInfo] {
        &LAG_CHANNELS
    }
    fn initial_state(&self, input: &f64, state: &mut [f64]) {
        state[0] = *input;
    }
    fn evaluate(&self, input: &f64, state: &[f64], d_state: &mut [f64]) -> f64 {
        d_state[0] = (input - state[0]) / self.tau;
        d_state[0]
    }
    fn record(&self, output: &f64, row: &mut [f64]) {
        row[0] = *output;
    }
}

#[test]
fn a_two_component_model_records_by_name_without_allocating() {
    // Two lags in series: u = 1 -> fast (tau 0.1) -> slow (tau 0.5).
    let fast = Lag { tau: 0.1 };
    let slow = Lag { tau: 0.5 };
    let mut layout = StateLayout::new();
    let fast_id = layout.add("fast", fast.states()).unwrap();
    let slow_id = layout.add("slow", slow.states()).unwrap();
    let mut channels = Channels::new();
    let time_col = channels.push("time_s", "s").unwrap();
    let states = channels.extend_states(&layout).unwrap();
    let fast_cols = channels.extend("fast", fast.channels()).unwrap();
    let slow_cols = channels.extend("slow", slow.channels()).unwrap();
    assert_eq!(
        channels.names(),
        [
            "time_s",
            "fast_x_m",
            "slow_x_m",
            "fast_rate_m_per_s",
            "slow_rate_m_per_s"
        ]
    );
    let steps = 1000;
    let h = 1e-3;
    let mut rec = Recorder::with_capacity(channels, steps).unwrap();
    let mut x = vec![0.0; layout.len()];
    let mut dx = vec![0.0; layout.len()];
    let mut row = vec![0.0; rec.channels().len()];
    fast.initial_state(&0.0, layout.slice_mut(fast_id, &mut x));
    slow.initial_state(&0.0, layout.slice_mut(slow_id, &mut x));

    let before = ALLOCATIONS.load(Ordering::SeqCst);
    for k in 0..steps {
        let fast_out = {
            let (s, d) = (
                layout.slice(fast_id, &x),
                layout.slice_mut(fast_id, &mut dx),
            );
            fast.evaluate(&1.0, s, d)
        };
        let fast_x = layout.slice(fast_id, &x)[0];
        let slow_out = slow.evaluate(
            &fast_x,
            layout.slice(slow_id, &x),
            layout.slice_mut(slow_id, &mut dx),
        );
        row[time_col] = k as f64 * h;
        row[states.clone()].copy_from_slice(&x);
        fast.record(&fast_out, &mut row[fast_cols.clone()]);
        slow.record(&slow_out, &mut row[slow_cols.clone()]);
        rec.push(&row).unwrap();
        for (xi, di) in x.iter_mut().zip(&dx) {
            *xi += h * di;
        }
    }
    let allocated = ALLOCATIONS.load(Ordering::SeqCst) - before;
    assert_eq!(
        allocated, 0,
        "the stepping loop allocated {allocated} times"
    );

    // Columns by name: the fast lag follows 1 - exp(-t/0.1) (Euler, 1 ms step), its rate
    // column is (1 - x)/0.1, and the slow lag trails it.
    let t = rec.column("time_s").unwrap();
    let xf = rec.column("fast_x_m").unwrap();
    let rf = rec.column("fast_rate_m_per_s").unwrap();
    let xs = rec.column("slow_x_m").unwrap();
    assert_eq!(t.len(), steps);
    for k in [100, 500, 999] {
        let exact = 1.0 - (-t[k] / 0.1).exp();
        assert!((xf[k] - exact).abs() < 5e-3, "{k}: {} vs {exact}", xf[k]);
        assert!((rf[k] - (1.0 - xf[k]) / 0.1).abs() < 1e-12);
        assert!(xs[k] < xf[k] && xs[k] > 0.0);
    }
}
