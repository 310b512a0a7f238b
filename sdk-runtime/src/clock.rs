//! Time as objects see it: time since boot (`GetSystemTime`) and the robot's calendar
//! clock (`OPENR::GetTime`, seconds since 2000-01-01 UTC, robot-api 9.6).
use std::sync::Mutex;
use std::time::{Duration, Instant, SystemTime, UNIX_EPOCH};

/// Seconds from the Unix epoch to 2000-01-01 00:00:00 UTC.
pub const EPOCH_2000: i64 = 946_684_800;

pub struct Clock {
    boot: Instant,
    /// Offset added to the host clock by `OPENR::SetTime`, and the time difference.
    calendar: Mutex<(i64, i32)>,
}

impl Clock {
    pub fn new() -> Clock {
        Clock { boot: Instant::now(), calendar: Mutex::new((0, 0)) }
    }

    pub fn since_boot(&self) -> Duration {
        self.boot.elapsed()
    }

    /// Seconds since 2000-01-01 UTC and the time difference in hours.
    pub fn calendar(&self) -> (i64, i32) {
        let host = SystemTime::now().duration_since(UNIX_EPOCH).map_or(0, |d| d.as_secs() as i64);
        let (offset, dif) = *self.calendar.lock().unwrap_or_else(|p| p.into_inner());
        (host - EPOCH_2000 + offset, dif)
    }

    pub fn set_calendar(&self, sec_since_2000: i64, time_dif: i32) {
        let host = SystemTime::now().duration_since(UNIX_EPOCH).map_or(0, |d| d.as_secs() as i64);
        *self.calendar.lock().unwrap_or_else(|p| p.into_inner()) = (sec_since_2000 - (host - EPOCH_2000), time_dif);
    }
}

impl Default for Clock {
    fn default() -> Clock {
        Clock::new()
    }
}
