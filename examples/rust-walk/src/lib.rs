//! RustWalk: moves the left front leg's J1 (`PRM:/r2/c1-Joint2:21`) from where it is to
//! +30° and back to 0° with `odataJOINT_COMMAND2` command vectors of 16 frames (8 ms
//! each), one vector per READY of `OVirtualRobotComm.Effector`, printing when the
//! commanded angle reaches each end. The Rust twin of the SDK samples' one-joint moves.
use openr::robot::{self, CommandVector, Gain, PrimitiveId, MAX_FRAMES};
use openr::{osysprint, Context, Object, ReadyEvent, Subject};

const LF_J1: &str = "PRM:/r2/c1-Joint2:21";
/// Vectors in flight: the effector holds one while the next is being filled.
const NUM_VECTORS: usize = 2;
/// Commanded speed: 0.5° per 8 ms frame (well below J1's 4.865 rad/s).
const STEP_URAD: i32 = 8_727;
/// Vectors to hold each end, so the joint settles there.
const HOLD_VECTORS: u32 = 4;

fn urad(deg: f64) -> i32 {
    (deg.to_radians() * 1e6).round() as i32
}

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Phase {
    Up,
    Down,
    Done,
}

struct RustWalk {
    out: Subject<CommandVector>,
    joint: Option<PrimitiveId>,
    vectors: Vec<CommandVector>,
    angle: i32,
    phase: Phase,
    hold: u32,
}

impl RustWalk {
    fn setup() -> Result<(PrimitiveId, Vec<CommandVector>), robot::OStatus> {
        let id = robot::open_primitive(LF_J1)?;
        robot::set_motor_power(true)?;
        robot::enable_joint_gain(id)?;
        robot::set_joint_gain(id, Gain::LEG_J1)?;
        let mut vectors = Vec::new();
        for _ in 0..NUM_VECTORS {
            let mut v = CommandVector::new(1)?;
            v.set_num_data(1)?;
            vectors.push(v);
        }
        Ok((id, vectors))
    }

    /// The next 16 frames of the move, and what to print once they are sent.
    fn frames(&mut self) -> ([i32; MAX_FRAMES], Option<&'static str>) {
        let mut frames = [0; MAX_FRAMES];
        let mut reached = None;
        for f in &mut frames {
            let target = match self.phase {
                Phase::Up => urad(30.0),
                Phase::Down | Phase::Done => 0,
            };
            let d = (target - self.angle).clamp(-STEP_URAD, STEP_URAD);
            self.angle += d;
            *f = self.angle;
            if self.angle == target && reached.is_none() && self.phase != Phase::Done {
                reached = Some(if self.phase == Phase::Up { "RustWalk : LF J1 reached 30 degrees\n" } else { "RustWalk : LF J1 back at 0 degrees\n" });
            }
        }
        (frames, reached)
    }
}

impl Object for RustWalk {
    fn init(ctx: &mut Context) -> Self {
        let out = ctx.subject("RustWalk.Move.OCommandVectorData.S");
        let (joint, vectors) = match RustWalk::setup() {
            Ok((id, v)) => (Some(id), v),
            Err(e) => {
                osysprint!("RustWalk : setup failed: {e}\n");
                (None, Vec::new())
            }
        };
        let angle = joint.and_then(|id| robot::joint_value(id).ok()).map_or(0, |v| v.value_urad);
        osysprint!("RustWalk : {} LF J1 at {:.1} degrees\n", robot::robot_design().unwrap_or_default(), (angle as f64 / 1e6).to_degrees());
        RustWalk { out, joint, vectors, angle, phase: Phase::Up, hold: 0 }
    }

    fn ready(&mut self, ctx: &mut Context, event: ReadyEvent) {
        if !self.out.is(&event) || !event.is_assert() {
            return;
        }
        let Some(id) = self.joint else { return };
        let Some(k) = self.vectors.iter().position(|v| !v.in_use()) else { return };
        let (frames, reached) = if self.hold > 0 {
            self.hold -= 1;
            if self.hold == 0 && self.phase == Phase::Up {
                self.phase = Phase::Down;
            }
            ([self.angle; MAX_FRAMES], None)
        } else {
            self.frames()
        };
        if let Err(e) = self.vectors[k].set_joint2(0, id, &frames) {
            osysprint!("RustWalk : set_joint2: {e}\n");
            return;
        }
        self.out.send_vector(ctx, &self.vectors[k]);
        if let Some(text) = reached {
            osysprint!("{text}");
            match self.phase {
                Phase::Up => self.hold = HOLD_VECTORS,
                _ => self.phase = Phase::Done,
            }
        }
    }
}

openr::object!(RustWalk, "RustWalk");
