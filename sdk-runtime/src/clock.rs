//! Time as objects see it. Virtual time advances only in 8 ms robot frames, driven by the
//! frame thread (`vr::run_frames`) at the chosen speed: 1 = real time, 4 = four times
//! faster, `max` = as fast as the objects keep up. `GetSystemTime`, `SetTimeEvent`
//! timers, `Wait` and the sleeps of objects all follow it, so a run at `--speed max` does
//! the same thing as one in real time, only sooner. The robot's calendar clock
//! (`OPENR::GetTime`, seconds since 2000-01-01 UTC, robot-api 9.6) is the host's wall
//! clock at boot plus virtual time.
use std::sync::{Condvar, Mutex};
use std::time::{Duration, SystemTime, UNIX_EPOCH};

/// Seconds from the Unix epoch to 2000-01-01 00:00:00 UTC.
pub const EPOCH_2000: i64 = 946_684_800;
/// One robot frame.
pub const FRAME: Duration = Duration::from_millis(8);

/// The factors `--speed` and the control socket accept: a frame of 8 ms takes from
/// 0.8 s (0.01) down to 8 us (1000) of real time. Slower is a pause (use `pause`), faster
/// is what `max` does without dropping frames.
pub const SPEED_RANGE: (f64, f64) = (0.01, 1000.0);

/// How fast virtual time runs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Speed {
    /// Virtual seconds per real second.
    Factor(f64),
    /// No waiting between frames beyond what the objects need.
    Max,
}

impl std::str::FromStr for Speed {
    type Err = String;
    fn from_str(s: &str) -> Result<Speed, String> {
        if s.eq_ignore_ascii_case("max") {
            return Ok(Speed::Max);
        }
        match s.parse::<f64>() {
            Ok(f) if (SPEED_RANGE.0..=SPEED_RANGE.1).contains(&f) => Ok(Speed::Factor(f)),
            Ok(_) => Err(format!("speed `{s}` is out of range: give a factor from {} to {} (1 = real time) or `max`", SPEED_RANGE.0, SPEED_RANGE.1)),
            _ => Err(format!("`{s}` is not a speed: give a factor from {} to {} (1 = real time) or `max`", SPEED_RANGE.0, SPEED_RANGE.1)),
        }
    }
}

struct State {
    now: Duration,
    speed: Speed,
    paused: bool,
    /// Frames still to run while paused (`step`).
    steps: u64,
    /// Virtual time stops here (`--for`), so a run ends on the same frame every time.
    limit: Option<Duration>,
    /// The frame thread is parked in `wait_runnable` (no frame in progress).
    parked: bool,
    /// Threads waiting on `tick`: a frame wakes them only when there are any (a futex
    /// wake is a system call even with nobody waiting, and frames are the hot path).
    waiters: usize,
}

pub struct Clock {
    state: Mutex<State>,
    tick: Condvar,
    boot_wall: i64,
    /// Offset added by `OPENR::SetTime`, and the time difference.
    calendar: Mutex<(i64, i32)>,
}

impl Clock {
    pub fn new(speed: Speed) -> Clock {
        let wall = SystemTime::now().duration_since(UNIX_EPOCH).map_or(0, |d| d.as_secs() as i64);
        Clock {
            state: Mutex::new(State { now: Duration::ZERO, speed, paused: false, steps: 0, limit: None, parked: false, waiters: 0 }),
            tick: Condvar::new(),
            boot_wall: wall,
            calendar: Mutex::new((0, 0)),
        }
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// Virtual time since boot.
    pub fn since_boot(&self) -> Duration {
        self.lock().now
    }

    pub fn speed(&self) -> Speed {
        self.lock().speed
    }

    pub fn set_speed(&self, speed: Speed) {
        self.lock().speed = speed;
        self.tick.notify_all();
    }

    pub fn paused(&self) -> bool {
        self.lock().paused
    }

    pub fn set_paused(&self, paused: bool) {
        let mut s = self.lock();
        s.paused = paused;
        s.steps = 0;
        self.tick.notify_all();
    }

    /// While paused, lets `frames` more frames run.
    pub fn step(&self, frames: u64) {
        let mut s = self.lock();
        s.steps += frames;
        self.tick.notify_all();
    }

    /// Stops virtual time once it reaches `limit`.
    pub fn set_limit(&self, limit: Option<Duration>) {
        self.lock().limit = limit;
        self.tick.notify_all();
    }

    fn blocked(s: &State) -> bool {
        (s.paused && s.steps == 0) || s.limit.is_some_and(|l| s.now >= l)
    }

    /// Frame thread: blocks while paused with no steps left, or at the limit; consumes
    /// one step.
    pub fn wait_runnable(&self) {
        self.park_until_runnable();
        while !self.try_runnable() {
            self.park_until_runnable();
        }
    }

    /// Frame thread: whether a frame may run now (consuming a step when paused).
    pub fn try_runnable(&self) -> bool {
        let mut s = self.lock();
        if Self::blocked(&s) {
            return false;
        }
        s.parked = false;
        if s.paused {
            s.steps -= 1;
        }
        true
    }

    /// Frame thread: blocks while paused with no steps left, or at the limit.
    pub fn park_until_runnable(&self) {
        let mut s = self.lock();
        while Self::blocked(&s) {
            s.parked = true;
            self.tick.notify_all();
            s = self.wait(s);
        }
    }

    /// Whether virtual time has reached its limit.
    pub fn at_limit(&self) -> bool {
        let s = self.lock();
        s.limit.is_some_and(|l| s.now >= l)
    }

    /// Stops virtual time where it is now (the end of a run).
    pub fn freeze(&self) {
        let mut s = self.lock();
        s.limit = Some(s.limit.map_or(s.now, |l| l.min(s.now)));
        drop(s);
        self.tick.notify_all();
    }

    /// Pauses and returns once no frame is in progress: the time returned is the time
    /// at which the robot stands still. `timeout` bounds the wait (frame thread absent).
    pub fn pause_settled(&self, timeout: Duration) -> Duration {
        let mut s = self.lock();
        s.paused = true;
        s.steps = 0;
        let deadline = std::time::Instant::now() + timeout;
        while !s.parked {
            let now = std::time::Instant::now();
            if now >= deadline {
                break;
            }
            s.waiters += 1;
            s = self.tick.wait_timeout(s, deadline - now).unwrap_or_else(|p| p.into_inner()).0;
            s.waiters -= 1;
        }
        s.now
    }

    /// Waits on `tick`, counted in `waiters`.
    fn wait<'a>(&self, mut s: std::sync::MutexGuard<'a, State>) -> std::sync::MutexGuard<'a, State> {
        s.waiters += 1;
        s = self.tick.wait(s).unwrap_or_else(|p| p.into_inner());
        s.waiters -= 1;
        s
    }

    /// Frame thread: one frame has run.
    pub fn advance(&self) -> Duration {
        let mut s = self.lock();
        s.now += FRAME;
        let (now, waiters) = (s.now, s.waiters);
        drop(s);
        if waiters > 0 {
            self.tick.notify_all();
        }
        now
    }

    /// Blocks the calling thread until virtual time has advanced by `d`.
    pub fn sleep(&self, d: Duration) {
        let until = self.since_boot() + d;
        self.wait_until(until);
    }

    /// Blocks the calling thread until virtual time has reached `t` (since boot).
    pub fn wait_until(&self, t: Duration) {
        let mut s = self.lock();
        while s.now < t {
            s = self.wait(s);
        }
    }

    /// Seconds since 2000-01-01 UTC and the time difference in hours.
    pub fn calendar(&self) -> (i64, i32) {
        let (offset, dif) = *self.calendar.lock().unwrap_or_else(|p| p.into_inner());
        (self.boot_wall + self.since_boot().as_secs() as i64 - EPOCH_2000 + offset, dif)
    }

    pub fn set_calendar(&self, sec_since_2000: i64, time_dif: i32) {
        let current = self.calendar().0 - self.calendar.lock().unwrap_or_else(|p| p.into_inner()).0;
        *self.calendar.lock().unwrap_or_else(|p| p.into_inner()) = (sec_since_2000 - current, time_dif);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn speeds_parse_and_time_advances_by_frames() {
        assert_eq!("max".parse::<Speed>(), Ok(Speed::Max));
        assert_eq!("2.5".parse::<Speed>(), Ok(Speed::Factor(2.5)));
        assert!("0".parse::<Speed>().is_err() && "fast".parse::<Speed>().is_err());
        for bad in ["1e-300", "0.001", "1001", "inf", "NaN", "-1"] {
            let e = bad.parse::<Speed>().unwrap_err();
            assert!(e.contains("0.01 to 1000"), "{bad}: {e}");
        }
        assert_eq!("0.01".parse::<Speed>(), Ok(Speed::Factor(0.01)));
        assert_eq!("1000".parse::<Speed>(), Ok(Speed::Factor(1000.0)));
        let c = Clock::new(Speed::Max);
        assert_eq!(c.since_boot(), Duration::ZERO);
        c.advance();
        c.advance();
        assert_eq!(c.since_boot(), Duration::from_millis(16));
    }

    #[test]
    fn sleepers_wake_when_virtual_time_passes() {
        // An absolute target, so the sleeper's start (late on a busy machine) cannot
        // move it past the frames this test runs.
        let c = std::sync::Arc::new(Clock::new(Speed::Max));
        let c2 = c.clone();
        let t = std::thread::spawn(move || {
            c2.wait_until(Duration::from_millis(20));
            c2.since_boot()
        });
        c.advance();
        c.advance();
        std::thread::sleep(Duration::from_millis(20));
        assert!(!t.is_finished(), "woke at 16 ms of virtual time");
        c.advance();
        assert_eq!(t.join().unwrap(), Duration::from_millis(24));
    }

    #[test]
    fn paused_clock_runs_only_the_steps_asked_for() {
        let c = Clock::new(Speed::Max);
        c.set_paused(true);
        c.step(2);
        c.wait_runnable();
        c.wait_runnable();
        assert!(c.paused());
        c.set_calendar(100, 9);
        assert_eq!(c.calendar(), (100, 9));
    }
}
