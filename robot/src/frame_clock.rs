//! The robot's global 8 ms frame clock in virtual time (robot-api 8.2.1, 8.3, 8.4, 8.6;
//! ers7-model 11).
//!
//! Why it exists: effector timing, sensor vectors, camera images and microphone blocks
//! all stamp the same frame counter, and samples correlate them by frame number
//! (BallTrackingHead7 looks up the head angles at an image's frame). Keeping the clock
//! pure — advanced by explicit `tick()` calls — makes the robot deterministic and
//! testable; the wiring decides how virtual time maps to wall time.
//!
//! Rules: the counter starts at 1, increments once per 8 ms frame, wraps from
//! `oframeMAX_NUMBER` (0x0FFFFFF0) to 1 and never takes the value 0. A sensor vector is
//! due after every 4th frame and covers the 4 frames just executed; since the counter
//! starts at 1 and 0x0FFFFFF0 is a multiple of 4, a vector never straddles the wrap and
//! consecutive vectors continue the numbering without gaps. Camera images are due at
//! 30 fps (ERS-7; 25 fps on ERS-2xx): image k is taken in the first frame whose end time
//! reaches k·1000/fps ms, so images are 4 or 5 frames apart; `frameNumber` = that frame.
//! Microphone blocks are due every 2 frames (16 ms, ERS-7) or 4 frames (32 ms, ERS-2xx).

use super::model::Design;

/// `oframeMAX_NUMBER`.
pub const FRAME_MAX: u32 = 0x0FFF_FFF0;
pub const FRAME_MS: u64 = 8;
pub const FRAMES_PER_SENSOR_VECTOR: u32 = 4;

/// The frame after `f` (wrap 0x0FFFFFF0 → 1; 0 and out-of-range values map to 1).
pub fn next_frame(f: u32) -> u32 {
    if f == 0 || f >= FRAME_MAX {
        1
    } else {
        f + 1
    }
}

/// `f + k` frames with the wrap rule.
pub fn add_frames(f: u32, k: u32) -> u32 {
    let f = if f == 0 || f > FRAME_MAX { 1 } else { f };
    (((f - 1) as u64 + k as u64) % FRAME_MAX as u64) as u32 + 1
}

/// What is due at the end of one frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Tick {
    /// Frame number executed by this tick.
    pub frame: u32,
    /// Frames executed since boot, including this one (1 for the first tick).
    pub count: u64,
    /// Virtual time at the end of this frame, ms since boot.
    pub time_ms: u64,
    /// `Some(first frame)` when a sensor vector covering 4 frames completes now.
    pub sensor_vector: Option<u32>,
    /// True when a camera image is taken in this frame.
    pub camera: bool,
    /// True when one is taken in the next frame (a simulator may start drawing it).
    pub camera_next: bool,
    /// True when a microphone block completes in this frame.
    pub mic: bool,
}

/// The frame counter.
#[derive(Clone, Debug)]
pub struct FrameClock {
    count: u64,
    frame: u32,
    sensor_first: u32,
    fps: u64,
    /// Where in its period the camera's image timing starts (ms after boot).
    camera_phase_ms: u64,
    mic_period: u64,
}

impl FrameClock {
    pub fn new(design: Design) -> FrameClock {
        FrameClock { count: 0, frame: 0, sensor_first: 1, fps: design.camera_fps() as u64, camera_phase_ms: 0, mic_period: design.mic_period_frames() as u64 }
    }

    /// Shifts the camera's image timing by `ms`: robots that booted at different moments
    /// take their pictures in different frames (a simulator of several robots then
    /// renders a few cameras per frame instead of all of them every fourth frame).
    pub fn set_camera_phase(&mut self, ms: u64) {
        self.camera_phase_ms = ms;
    }

    /// Starts counting at `first` instead of 1 (tests of the wrap). `first` is aligned
    /// down to a sensor-vector boundary (1 mod 4) so vectors keep their alignment.
    pub fn starting_at(design: Design, first: u32) -> FrameClock {
        let mut c = FrameClock::new(design);
        let f = if first == 0 || first > FRAME_MAX { 1 } else { first };
        let aligned = (f - 1) / 4 * 4 + 1;
        c.frame = if aligned == 1 { 0 } else { aligned - 1 };
        c.sensor_first = aligned;
        c
    }

    /// The last executed frame (0 before the first tick).
    pub fn frame(&self) -> u32 {
        self.frame
    }

    /// The frame the next tick will execute.
    pub fn upcoming(&self) -> u32 {
        next_frame(self.frame)
    }

    /// Frames executed since boot.
    pub fn count(&self) -> u64 {
        self.count
    }

    pub fn time_ms(&self) -> u64 {
        self.count * FRAME_MS
    }

    /// Executes one frame.
    pub fn tick(&mut self) -> Tick {
        self.frame = next_frame(self.frame);
        self.count += 1;
        let n = self.count;
        let sensor_vector = if n % FRAMES_PER_SENSOR_VECTOR as u64 == 0 {
            let first = self.sensor_first;
            self.sensor_first = next_frame(self.frame);
            Some(first)
        } else {
            None
        };
        let images = |k: u64| (k * FRAME_MS + self.camera_phase_ms) * self.fps / 1000;
        let camera = images(n) > images(n - 1);
        let camera_next = images(n + 1) > images(n);
        let mic = n % self.mic_period == 0;
        Tick { frame: self.frame, count: n, time_ms: n * FRAME_MS, sensor_vector, camera, camera_next, mic }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn starts_at_one_and_wraps() {
        let mut c = FrameClock::new(Design::Ers7);
        assert_eq!(c.frame(), 0);
        assert_eq!(c.tick().frame, 1);
        assert_eq!(c.tick().frame, 2);
        assert_eq!(next_frame(FRAME_MAX - 1), FRAME_MAX);
        assert_eq!(next_frame(FRAME_MAX), 1);
        assert_eq!(next_frame(0), 1);
        assert_eq!(add_frames(FRAME_MAX - 1, 3), 2);
        assert_eq!(add_frames(5, 0), 5);
        let mut w = FrameClock::starting_at(Design::Ers7, FRAME_MAX - 7);
        let frames: Vec<u32> = (0..12).map(|_| w.tick().frame).collect();
        assert_eq!(frames[7], FRAME_MAX);
        assert_eq!(frames[8], 1);
        assert!(!frames.contains(&0));
    }

    #[test]
    fn sensor_vectors_every_4_frames_continuous() {
        let mut c = FrameClock::starting_at(Design::Ers7, FRAME_MAX - 11);
        let mut firsts = Vec::new();
        for _ in 0..24 {
            let t = c.tick();
            if let Some(f) = t.sensor_vector {
                assert_eq!(add_frames(f, 3), t.frame);
                firsts.push(f);
            }
        }
        assert_eq!(firsts.len(), 6);
        for w in firsts.windows(2) {
            assert_eq!(add_frames(w[0], 4), w[1]);
        }
        assert!(firsts.contains(&1));
        let mut c = FrameClock::new(Design::Ers7);
        let v: Vec<u32> = (0..8).filter_map(|_| c.tick().sensor_vector).collect();
        assert_eq!(v, vec![1, 5]);
    }

    #[test]
    fn a_camera_phase_moves_the_image_frames_and_keeps_the_rate() {
        let due = |phase| {
            let mut c = FrameClock::new(Design::Ers7);
            c.set_camera_phase(phase);
            (0..125).filter_map(|_| Some(c.tick()).filter(|t| t.camera).map(|t| t.count)).collect::<Vec<_>>()
        };
        let (a, b) = (due(0), due(8));
        let mut c = FrameClock::new(Design::Ers7);
        let ticks: Vec<Tick> = (0..125).map(|_| c.tick()).collect();
        for w in ticks.windows(2) {
            assert_eq!(w[0].camera_next, w[1].camera, "frame {}", w[0].count);
        }
        assert_eq!((a.len(), b.len()), (30, 30));
        // 8 ms later in the period = one frame earlier (the images of 0 ms come at 5, 9, 13, ...).
        assert_eq!(&a[..3], &[5, 9, 13]);
        assert_eq!(&b[..3], &[4, 8, 12]);
    }

    #[test]
    fn camera_30fps_and_mic_16ms() {
        let mut c = FrameClock::new(Design::Ers7);
        let mut cams = Vec::new();
        let mut mics = 0;
        for _ in 0..375 {
            // 3 s
            let t = c.tick();
            if t.camera {
                cams.push(t.frame);
            }
            if t.mic {
                mics += 1;
            }
        }
        assert_eq!(c.time_ms(), 3000);
        assert_eq!(cams.len(), 90);
        assert!(cams.windows(2).all(|w| w[1] - w[0] == 4 || w[1] - w[0] == 5));
        assert_eq!(mics, 375 / 2);
        let mut c = FrameClock::new(Design::Ers210);
        let cams = (0..125).filter(|_| c.tick().camera).count();
        assert_eq!(cams, 25);
    }
}
