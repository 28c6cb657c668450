//! Zero crossings of user functions g(t, y), located on the dense output.

use crate::kernel::Kernel;
use crate::Workspace;

/// Which sign changes of g count as an event.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    /// g goes from negative to zero or positive.
    Rising,
    /// g goes from positive to zero or negative.
    Falling,
    /// Either.
    Either,
}

impl Direction {
    /// Does the change of g from `a` (start of a step) to `b` (end) cross zero this way?
    /// A step that starts exactly on zero does not count (that crossing was the previous one).
    pub(crate) fn crosses(self, a: f64, b: f64) -> bool {
        let rising = a < 0.0 && b >= 0.0;
        let falling = a > 0.0 && b <= 0.0;
        match self {
            Direction::Rising => rising,
            Direction::Falling => falling,
            Direction::Either => rising || falling,
        }
    }
}

/// An event function g(t, y): the driver watches its sign after every step, locates a
/// crossing with the method's dense output to within [`crate::Integrator::event_tol`]
/// seconds and reports it to the observer as [`crate::SampleKind::Event`]. A terminal
/// event ends the run at the crossing. One crossing per event and step is located (the
/// step size bounds how close two crossings of one function may be).
pub struct Event<'a> {
    /// The function whose zero crossings are events. Must not allocate.
    pub g: &'a dyn Fn(f64, &[f64]) -> f64,
    /// Which crossings count.
    pub direction: Direction,
    /// Whether the run ends at the crossing.
    pub terminal: bool,
}

impl<'a> Event<'a> {
    /// Event on the crossings of `g` in `direction`; not terminal.
    pub fn new(g: &'a dyn Fn(f64, &[f64]) -> f64, direction: Direction) -> Self {
        Self {
            g,
            direction,
            terminal: false,
        }
    }

    /// Same event, ending the run at its first crossing.
    pub fn terminal(mut self) -> Self {
        self.terminal = true;
        self
    }
}

/// Crossing time of `ev` inside the step `(t, t + h]`, where g went from `g_a` to `g_b`:
/// Illinois (modified regula falsi) on the dense output until the bracket is shorter than
/// `tol` seconds. Leaves the interpolated state at the returned time in `ws.y_out`.
pub(crate) fn locate<K: Kernel>(
    kernel: &K,
    ev: &Event<'_>,
    (t, h): (f64, f64),
    (g_a, g_b): (f64, f64),
    tol: f64,
    ws: &mut Workspace,
) -> f64 {
    let (mut a, mut b) = (0.0_f64, 1.0_f64);
    let (mut fa, mut fb) = (g_a, g_b);
    let mut side = 0i8;
    let mut root = 1.0;
    for _ in 0..200 {
        if (b - a) * h <= tol || fb == 0.0 {
            root = b;
            break;
        }
        let c = (a * fb - b * fa) / (fb - fa);
        let c = if c > a && c < b { c } else { 0.5 * (a + b) };
        kernel.dense(c, h, ws);
        let fc = (ev.g)(t + c * h, &ws.y_out);
        if fc == 0.0 {
            root = c;
            break;
        }
        if (fc < 0.0) == (fb < 0.0) {
            b = c;
            fb = fc;
            if side == 1 {
                fa *= 0.5;
            }
            side = 1;
        } else {
            a = c;
            fa = fc;
            if side == -1 {
                fb *= 0.5;
            }
            side = -1;
        }
        root = b;
    }
    kernel.dense(root, h, ws);
    t + root * h
}
