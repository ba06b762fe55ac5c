//! The clock of an animation driven by frames (the 3D view's turn and flow): how much
//! time a frame moves it on, capped so a stalled frame does not jump.

/// Longest step between two frames, seconds.
pub const MAX_STEP_S: f64 = 0.25;

/// When the animation last stepped (none while it stands).
#[derive(Clone, Copy, Debug, Default)]
pub struct StepClock {
    last_ms: Option<f64>,
}

impl StepClock {
    /// Seconds since the last step (0 for the first, at most [`MAX_STEP_S`]), and
    /// marks this one.
    pub fn step(&mut self) -> f64 {
        let now = crate::platform::now_ms();
        let dt = self
            .last_ms
            .map_or(0.0, |last| ((now - last) / 1000.0).clamp(0.0, MAX_STEP_S));
        self.last_ms = Some(now);
        dt
    }

    /// The animation stands: the next step starts from 0.
    pub fn stop(&mut self) {
        self.last_ms = None;
    }
}
