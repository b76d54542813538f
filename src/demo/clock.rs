//! The frame time in the demo's title, measured with the CPU clock from one
//! swap to the next.

use std::time::{Duration, Instant};

/// Mean frame time over about half a second, for the title.
pub(super) struct TitleClock {
    since: Instant,
    frames: u32,
}

impl TitleClock {
    pub(super) fn new() -> TitleClock {
        TitleClock {
            since: Instant::now(),
            frames: 0,
        }
    }

    /// Count a frame; every ~0.5 s returns the mean ms per frame since the last report.
    pub(super) fn tick(&mut self) -> Option<f64> {
        self.frames += 1;
        let elapsed = self.since.elapsed();
        if elapsed < Duration::from_millis(500) {
            return None;
        }
        let ms = elapsed.as_secs_f64() * 1000.0 / f64::from(self.frames);
        *self = TitleClock::new();
        Some(ms)
    }
}
