//! The virtual robot ("Virtual ERS-7"): a pure-Rust, deterministic model of the robot
//! behind the OPENR:: API and the `OVirtualRobotComm` / `OVirtualRobotAudioComm`
//! services (robot-api 4, 6, 8; ers7-model).
//!
//! Why it exists: recompiled OPEN-R objects expect a robot — primitive IDs, gains,
//! joint readings from boot on, an effector that paces their command vectors,
//! sensor vectors every 32 ms, camera and microphone timing. [`VirtualRobot`] is that
//! robot without threads or shared memory: the runtime's system objects call it and
//! move bytes between it and the objects' regions. Virtual time advances only through
//! [`VirtualRobot::step_frame`] (one 8 ms frame per call).
//!
//! Pieces:
//! * [`model`] / `model_ers2xx` — locators, IDs, limits, gains, sensor order;
//! * [`vectors`] / [`image`] — byte layouts of the data vectors;
//! * [`effector`] + [`sync`] — command queues, frame timing, sync keys;
//! * [`kinematics`] — servos, ears, LEDs; [`scene`] — posture and sensors;
//! * [`frame_clock`] — the frame counter; [`trace`] — JSON-lines trace;
//! * [`status`] — `OStatus` codes returned by the facade.
//!
//! Wiring sketch (done elsewhere): on an Effector NOTIFY, for each data item call
//! [`VirtualRobot::submit_command`] with the region's bytes and remember token →
//! region; after each [`VirtualRobot::step_frame`], write `frameNumber` for
//! `started` vectors ([`write_frame_numbers`]), release and ASSERT-READY each
//! `completed` token, publish `sensor_vector` if present, capture an image if
//! `camera_due`, a mic block if `mic_due`, and append `trace` lines.

pub mod camera;
pub mod effector;
pub mod frame_clock;
mod id_map;
pub mod image;
pub mod kinematics;
pub mod model;
mod model_ers2xx;
pub mod render;
pub mod scene;
pub mod status;
pub mod sync;
pub mod trace;
pub mod vectors;

use std::collections::BTreeSet;

use rustc_hash::FxHashMap as HashMap;

pub use effector::{Completed, ConnectionId, Started, Token};
pub use model::{Design, Gain, PrimitiveId, RobotModel, PRIMITIVE_ID_UNDEF};
pub use status::OStatus;
pub use vectors::{FrameCommand, JointValue, SensorValue, VectorError};

use effector::{ClampRule, Effector};
use frame_clock::FrameClock;
use kinematics::{Body, Change, LedState};
use model::{degrees, Leg, Part, PrimitiveKind};
use scene::{Scene, SensorSynth};
use status::*;
use sync::SyncKeys;
use trace::{SlotSummary, TraceEvent, TraceRecord};
use vectors::{CommandValues, CommandVector, FrameValue, SensorEntry};

/// Everything one frame produced.
#[derive(Clone, Debug, Default)]
pub struct FrameOutput {
    /// Frame number executed.
    pub frame: u32,
    /// Virtual time at the end of the frame, ms since boot.
    pub time_ms: u64,
    /// Vectors that started: write `frame` into their `OCommandInfo.frameNumber`.
    pub started: Vec<Started>,
    /// Vectors that finished: release the region, then ASSERT-READY to the subject.
    pub completed: Vec<Completed>,
    /// A complete `OSensorFrameVectorData` (exact size, `totalSize` = its length) when
    /// one is due (every 4th frame).
    pub sensor_vector: Option<Vec<u8>>,
    /// A camera image is taken in this frame (`frameNumber` = `frame`).
    pub camera_due: bool,
    /// A microphone block ends in this frame.
    pub mic_due: bool,
    pub trace: Vec<TraceRecord>,
}

/// Writes `started.frame` into `OCommandInfo[i].frameNumber` of every slot the vector
/// had (the effector's only write into a command vector, robot-api 7).
pub fn write_frame_numbers(bytes: &mut [u8], started: &Started) -> Result<(), VectorError> {
    for s in &started.slots {
        vectors::write_command_frame_number(bytes, s.index, started.frame)?;
    }
    Ok(())
}

/// The virtual robot.
#[derive(Clone, Debug)]
pub struct VirtualRobot {
    model: RobotModel,
    clock: FrameClock,
    effector: Effector,
    body: Body,
    synth: SensorSynth,
    sync: SyncKeys,
    scene: Scene,
    opened: BTreeSet<PrimitiveId>,
    next_token: Token,
    window: Vec<Vec<FrameValue>>,
    window_optional: Option<(u32, Vec<u8>)>,
    latest: HashMap<PrimitiveId, SensorValue>,
    pending_trace: Vec<TraceEvent>,
    trace_enabled: bool,
    camera: camera::Camera,
    /// Non-joint readings supplied from outside (an external robot peer): they replace
    /// the synthesized values until cleared ([`VirtualRobot::apply_readings`]).
    sensor_override: HashMap<PrimitiveId, SensorValue>,
    /// A camera picture supplied from outside (sensor-resolution RGB), used for every
    /// image until cleared ([`VirtualRobot::set_camera_rgb`]).
    external_rgb: Option<Vec<u8>>,
}

/// Readings measured outside the model (an external robot peer) for the frame in
/// progress: joint angles (µrad) and non-joint sensor values (the sensor's `value`
/// unit: µm/s², µm, 0/1, …).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Readings {
    pub joints: Vec<(PrimitiveId, i32)>,
    pub sensors: Vec<(PrimitiveId, i32)>,
}

/// A frame whose commands have been applied but whose sensors are not sampled yet
/// ([`VirtualRobot::begin_frame`] / [`VirtualRobot::end_frame`]).
#[derive(Debug)]
pub struct PendingFrame {
    tick: frame_clock::Tick,
    ef: effector::EffectorFrame,
    events: Vec<TraceEvent>,
}

impl PendingFrame {
    /// Frame number in progress.
    pub fn frame(&self) -> u32 {
        self.tick.frame
    }
    /// Virtual time at the end of the frame, ms since boot.
    pub fn time_ms(&self) -> u64 {
        self.tick.time_ms
    }
    /// A sensor vector completes with this frame.
    pub fn sensor_due(&self) -> bool {
        self.tick.sensor_vector.is_some()
    }
    pub fn camera_due(&self) -> bool {
        self.tick.camera
    }
    /// A camera image is taken in the next frame.
    pub fn camera_next(&self) -> bool {
        self.tick.camera_next
    }
    pub fn mic_due(&self) -> bool {
        self.tick.mic
    }
}

impl VirtualRobot {
    /// Shifts the camera's 30 fps image timing by `ms` from boot (see
    /// [`FrameClock::set_camera_phase`]).
    pub fn set_camera_phase(&mut self, ms: u64) {
        self.clock.set_camera_phase(ms);
    }

    /// A robot of `design` in its boot state (sleep posture, gains disabled, motor
    /// power off, frame counter before frame 1).
    pub fn new(design: Design) -> VirtualRobot {
        let model = RobotModel::new(design);
        let body = Body::new(model.clone());
        let mut synth = SensorSynth::new();
        let scene = Scene::default();
        let latest = synth.sample(&body, &scene, 0);
        VirtualRobot {
            clock: FrameClock::new(design),
            effector: Effector::new(model.clone()),
            model,
            body,
            synth,
            sync: SyncKeys::new(),
            scene,
            opened: BTreeSet::new(),
            next_token: 1,
            window: Vec::with_capacity(4),
            window_optional: None,
            latest,
            pending_trace: Vec::new(),
            trace_enabled: true,
            camera: camera::Camera::new(design),
            sensor_override: HashMap::default(),
            external_rgb: None,
        }
    }

    /// [`VirtualRobot::new`] from a `GetRobotDesign` string.
    pub fn from_design_name(name: &str) -> Option<VirtualRobot> {
        Design::from_name(name).map(VirtualRobot::new)
    }

    pub fn design(&self) -> Design {
        self.model.design()
    }

    pub fn model(&self) -> &RobotModel {
        &self.model
    }

    /// Turns trace collection on or off (default on).
    pub fn set_trace(&mut self, on: bool) {
        self.trace_enabled = on;
        if !on {
            self.pending_trace.clear();
        }
    }

    // -- primitives -----------------------------------------------------------------

    /// `OpenPrimitive`: the global ID of `locator`, or `oNOT_FOUND`. Opening twice is
    /// fine; opened joints are what `oprimitiveID_UNDEF` means in the gain calls.
    pub fn open_primitive(&mut self, locator: &str) -> Result<PrimitiveId, OStatus> {
        let id = self.model.open_primitive(locator).ok_or(O_NOT_FOUND)?;
        self.opened.insert(id);
        Ok(id)
    }

    /// `ClosePrimitive`.
    pub fn close_primitive(&mut self, id: PrimitiveId) -> OStatus {
        if self.model.primitive(id).is_none() {
            return O_INVALID_PRIMITIVE_ID;
        }
        self.opened.remove(&id);
        O_SUCCESS
    }

    // -- gains (robot-api 4.3, 11) ----------------------------------------------------

    /// Joint2 primitives a gain call addresses: UNDEF = every opened servo joint; an
    /// ear (Joint3/4) is accepted and ignored (no servo gains); anything else is
    /// `oINVALID_PRIMITIVE_ID` (including 0 = `oprimitiveUNDEF`).
    fn gain_targets(&self, id: PrimitiveId) -> Result<Vec<PrimitiveId>, OStatus> {
        if id == PRIMITIVE_ID_UNDEF {
            return Ok(self.opened.iter().copied().filter(|i| self.body.joint(*i).is_some()).collect());
        }
        match self.model.primitive(id).map(|p| p.kind) {
            Some(PrimitiveKind::Joint2) => Ok(vec![id]),
            Some(PrimitiveKind::Joint3 | PrimitiveKind::Joint4) => Ok(vec![]),
            _ => Err(O_INVALID_PRIMITIVE_ID),
        }
    }

    fn trace_gain(&mut self, id: PrimitiveId) {
        if let (Some(j), Some(locator)) = (self.body.joint(id), self.model.locator(id)) {
            let g = if j.gain.enabled { j.gain.loaded } else { Gain::default() };
            let ev = TraceEvent::Gain { locator, enabled: j.gain.enabled, p: g.p, i: g.i, d: g.d };
            if self.trace_enabled {
                self.pending_trace.push(ev);
            }
        }
    }

    /// `EnableJointGain`: the loaded (initially the registered) gains become effective.
    pub fn enable_joint_gain(&mut self, id: PrimitiveId) -> OStatus {
        let targets = match self.gain_targets(id) {
            Ok(t) => t,
            Err(e) => return e,
        };
        for t in targets {
            if let Some(j) = self.body.joint_mut(t) {
                j.gain.enabled = true;
            }
            self.trace_gain(t);
        }
        O_SUCCESS
    }

    /// `DisableJointGain`: the servo stops driving; the joint becomes limp.
    pub fn disable_joint_gain(&mut self, id: PrimitiveId) -> OStatus {
        let targets = match self.gain_targets(id) {
            Ok(t) => t,
            Err(e) => return e,
        };
        for t in targets {
            if let Some(j) = self.body.joint_mut(t) {
                j.gain.enabled = false;
            }
            self.trace_gain(t);
        }
        O_SUCCESS
    }

    /// `SetJointGain`: loads `gain` into every addressed joint whose gain is enabled;
    /// `oGAIN_DISABLED` if any addressed joint is not enabled.
    pub fn set_joint_gain(&mut self, id: PrimitiveId, gain: Gain) -> OStatus {
        self.load_gain(id, |_| gain)
    }

    /// `SetDefaultJointGain`: loads the registered set (same return codes).
    pub fn set_default_joint_gain(&mut self, id: PrimitiveId) -> OStatus {
        self.load_gain(id, |j| j.gain.registered)
    }

    fn load_gain(&mut self, id: PrimitiveId, f: impl Fn(&kinematics::JointState) -> Gain) -> OStatus {
        let targets = match self.gain_targets(id) {
            Ok(t) => t,
            Err(e) => return e,
        };
        let mut status = O_SUCCESS;
        for t in targets {
            match self.body.joint_mut(t) {
                Some(j) if j.gain.enabled => {
                    j.gain.loaded = f(j);
                }
                _ => {
                    status = O_GAIN_DISABLED;
                    continue;
                }
            }
            self.trace_gain(t);
        }
        status
    }

    /// `RegisterDefaultJointGain`: stores a default set without loading it.
    pub fn register_default_joint_gain(&mut self, id: PrimitiveId, gain: Gain) -> OStatus {
        match self.gain_targets(id) {
            Ok(t) => {
                for t in t {
                    if let Some(j) = self.body.joint_mut(t) {
                        j.gain.registered = gain;
                    }
                }
                O_SUCCESS
            }
            Err(e) => e,
        }
    }

    /// `GetJointGain`: the loaded set, or an error (`oGAIN_DISABLED` when not
    /// effective; the caller then reports all six words as 0).
    pub fn get_joint_gain(&self, id: PrimitiveId) -> Result<Gain, OStatus> {
        let j = self.body.joint(id).ok_or(O_INVALID_PRIMITIVE_ID)?;
        if j.gain.enabled {
            Ok(j.gain.loaded)
        } else {
            Err(O_GAIN_DISABLED)
        }
    }

    /// `GetDefaultJointGain` (`oFAIL` for anything but a servo joint).
    pub fn get_default_joint_gain(&self, id: PrimitiveId) -> Result<Gain, OStatus> {
        self.body.joint(id).map(|j| j.gain.registered).ok_or(O_FAIL)
    }

    // -- power and readings -------------------------------------------------------------

    /// `SetMotorPower` (idempotent).
    pub fn set_motor_power(&mut self, on: bool) -> OStatus {
        if self.body.motor_power() != on && self.trace_enabled {
            self.pending_trace.push(TraceEvent::MotorPower { on });
        }
        self.body.set_motor_power(on);
        O_SUCCESS
    }

    pub fn motor_power(&self) -> bool {
        self.body.motor_power()
    }

    /// `GetJointValue`: the newest frame's `OJointValue` (valid from boot on).
    pub fn joint_value(&self, id: PrimitiveId) -> Result<JointValue, OStatus> {
        self.body.joint_value(id).ok_or(O_INVALID_PRIMITIVE_ID)
    }

    /// `GetSensorValue`: the newest frame's reading of a non-joint sensor.
    pub fn sensor_value(&self, id: PrimitiveId) -> Result<SensorValue, OStatus> {
        self.latest.get(&id).copied().ok_or(O_INVALID_PRIMITIVE_ID)
    }

    // -- effector -------------------------------------------------------------------------

    /// Parses and queues one command vector received on `connection` (call once per
    /// data item of a NOTIFY, in order). The returned token identifies it in
    /// [`FrameOutput::started`] / [`FrameOutput::completed`]. Malformed vectors are
    /// rejected; the wiring should then release the region and send ASSERT-READY at once.
    pub fn submit_command(&mut self, connection: ConnectionId, bytes: &[u8]) -> Result<Token, VectorError> {
        let v = vectors::parse_command_vector(bytes)?;
        Ok(self.submit_parsed(connection, &v))
    }

    /// [`VirtualRobot::submit_command`] for an already parsed vector.
    pub fn submit_parsed(&mut self, connection: ConnectionId, vector: &CommandVector) -> Token {
        let token = self.next_token;
        self.next_token += 1;
        self.effector.enqueue(connection, vector, token);
        token
    }

    /// Immediate single-frame command (`ControlPrimitive` JOINT2/LED2/LED3/JOINT4
    /// `_SET_COMMAND`), applied in the next frame. `oINVALID_ARG` when the command
    /// does not fit the primitive.
    pub fn immediate_command(&mut self, id: PrimitiveId, command: FrameCommand) -> OStatus {
        let Some(p) = self.model.primitive(id) else { return O_INVALID_PRIMITIVE_ID };
        let fits = matches!(
            (command, p.kind),
            (FrameCommand::Joint(_), PrimitiveKind::Joint2)
                | (FrameCommand::State(_), PrimitiveKind::Joint3 | PrimitiveKind::Joint4)
                | (FrameCommand::Led2(_), PrimitiveKind::Led2)
                | (FrameCommand::Led3(_), PrimitiveKind::Led3)
        );
        if !fits {
            return O_INVALID_ARG;
        }
        self.effector.immediate(id, command);
        O_SUCCESS
    }

    /// Forgets every vector of a connection (its subject died); returns their tokens.
    pub fn drop_connection(&mut self, connection: ConnectionId) -> Vec<Token> {
        self.effector.drop_connection(connection)
    }

    pub fn effector(&self) -> &Effector {
        &self.effector
    }

    // -- sync keys (robot-api 4.4) ---------------------------------------------------

    /// `NewSyncKey`: `Err(oNO_SYNC_KEY)` when 8 keys exist.
    pub fn new_sync_key(&mut self) -> Result<u32, OStatus> {
        self.sync.new_key()
    }

    /// `CancelSyncKey`.
    pub fn cancel_sync_key(&mut self, key: u32) -> OStatus {
        self.sync.cancel(key)
    }

    /// `DivideSyncKey`.
    pub fn divide_sync_key(&mut self, key: u32) -> Result<(u32, u32), OStatus> {
        self.sync.divide(key)
    }

    /// The key registry, for the speaker wiring (`arrive`/`state`/`take`).
    pub fn sync_keys_mut(&mut self) -> &mut SyncKeys {
        &mut self.sync
    }

    // -- world ----------------------------------------------------------------------------

    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// Touch pads, switches, wall distance, lifting (takes effect next frame).
    pub fn scene_mut(&mut self) -> &mut Scene {
        &mut self.scene
    }

    pub fn body(&self) -> &Body {
        &self.body
    }

    /// Direct access (e.g. [`Body::move_by_hand`], posture setup).
    pub fn body_mut(&mut self) -> &mut Body {
        &mut self.body
    }

    /// Frame clock (current frame, virtual time).
    pub fn clock(&self) -> &FrameClock {
        &self.clock
    }

    /// The camera's image-vector layout.
    pub fn image_layout(&self) -> image::ImageLayout {
        image::ImageLayout::new(self.design())
    }

    pub fn primitive_of(&self, part: Part) -> Option<PrimitiveId> {
        self.model.by_part(part).map(|p| p.id)
    }

    // -- camera (robot-api 6.6, 6.7, 8.4) ---------------------------------------------

    /// `SetCdtVectorData`: loads the first `numData` colour-detection tables of an
    /// `OCdtVectorData` (effective from the next image). oSUCCESS, oINVALID_ARG (channel
    /// 0, not a single bit, or channel 7 on ERS-7), oINVALID_PRIMITIVE_ID (not the
    /// camera), oINVALID_DATA_TYPE (vector or info type), oFAIL (truncated/too many).
    pub fn set_cdt(&mut self, bytes: &[u8]) -> OStatus {
        let Some(cam) = self.primitive_of(Part::Camera) else { return O_FAIL };
        match camera::parse_cdt(bytes, cam, self.design()) {
            Ok(tables) => {
                for t in &tables {
                    self.camera.lut.load(t);
                }
                O_SUCCESS
            }
            Err(e) => e,
        }
    }

    /// Replaces the rendered scene by an image file or a directory of frames (binary
    /// PPM P6 or uncompressed 24/32-bit BMP, any size, scaled nearest-neighbour to the
    /// sensor resolution; frames cycled in file-name order, one per image). `None`
    /// returns to the rendered scene. Returns the number of frames.
    pub fn set_image_source(&mut self, path: Option<&std::path::Path>) -> Result<usize, camera::ImageError> {
        self.camera.source = match path {
            Some(p) => Some(camera::FileSource::open(p)?),
            None => None,
        };
        Ok(self.camera.source.as_ref().map_or(0, |s| s.paths.len()))
    }

    /// `ControlPrimitive` on the camera: `oprmreqCAM_SET_WHITE_BALANCE` (384),
    /// `_SET_GAIN` (385), `_SET_SHUTTER_SPEED` (386) with an `ocamparam*` value 1..3
    /// (effects: [`camera::CameraSettings`]). oINVALID_PRIMITIVE_ID for an unknown ID,
    /// oINVALID_ARG for another primitive or a bad value, oNOT_SUPPORTED for other
    /// camera requests.
    pub fn camera_control(&mut self, id: PrimitiveId, request: u32, camparam: u32) -> OStatus {
        match self.model.primitive(id) {
            None => O_INVALID_PRIMITIVE_ID,
            Some(p) if p.part != Part::Camera => O_INVALID_ARG,
            Some(_) => self.camera.settings.control(request, camparam),
        }
    }

    /// The camera pinhole model at the current joint angles and posture.
    pub fn camera_model(&self) -> render::PinholeCamera {
        render::PinholeCamera::new(self.design(), render::camera_pose(&self.body, &self.scene))
    }

    /// Takes a picture now: renders the scene (or the next replacement frame) and
    /// writes a complete `OFbkImageVectorData` into `out` (resized to
    /// [`image::ImageLayout::size`]): header type 1027, 4 infos with the camera's
    /// primitive ID and `frameNumber` = `frame`, H/M/L/C layers and tags. The field
    /// counter advances by one per call.
    pub fn render_image(&mut self, frame: u32, out: &mut Vec<u8>) {
        out.resize(self.camera.vector_size(), 0);
        self.render_image_into(frame, out);
    }

    /// Bytes of one image vector.
    pub fn image_vector_size(&self) -> usize {
        self.camera.vector_size()
    }

    /// [`VirtualRobot::render_image`] into `out` of [`VirtualRobot::image_vector_size`]
    /// bytes (the shared region the vector is delivered in).
    pub fn render_image_into(&mut self, frame: u32, out: &mut [u8]) {
        if let Some(rgb) = &self.external_rgb {
            self.camera.fill_from(rgb);
        } else if !self.camera.fill_from_source() {
            let cam = self.camera_model();
            self.camera.render_scene(&cam, &self.scene.camera, self.scene.wall_mm);
        }
        let id = self.primitive_of(Part::Camera).unwrap_or(PRIMITIVE_ID_UNDEF);
        self.camera.build_vector(id, frame, out);
    }

    /// The sensor-resolution RGB image of the last [`VirtualRobot::render_image`].
    pub fn camera_rgb(&self) -> &camera::RgbImage {
        &self.camera.rgb
    }

    /// Camera state (CDT tables, field counter, last CDT counts).
    pub fn camera(&self) -> &camera::Camera {
        &self.camera
    }

    // -- the frame ---------------------------------------------------------------------

    fn locator(&self, id: PrimitiveId) -> &'static str {
        self.model.locator(id).unwrap_or("?")
    }

    // -- readings from outside (external robot peers) ----------------------------------

    /// Replaces measured values for the frame in progress (call between
    /// [`VirtualRobot::begin_frame`] and [`VirtualRobot::end_frame`]): each joint's
    /// measured angle becomes the given µrad (it stays there — the built-in servo model
    /// continues from it when no more readings come); each non-joint sensor reports the
    /// given value (its `signal` derived as the model does) until
    /// [`VirtualRobot::clear_sensor_overrides`]. Unknown IDs are errors.
    pub fn apply_readings(&mut self, r: &Readings) -> Result<(), PrimitiveId> {
        for &(id, _) in r.joints.iter() {
            if self.body.joint(id).is_none() {
                return Err(id);
            }
        }
        for &(id, _) in r.sensors.iter() {
            match self.model.primitive(id) {
                Some(p) if matches!(p.kind, PrimitiveKind::Sensor(_)) => {}
                _ => return Err(id),
            }
        }
        for &(id, v) in &r.joints {
            if let Some(j) = self.body.joint_mut(id) {
                j.angle = v as f64;
            }
        }
        for &(id, v) in &r.sensors {
            if let Some(p) = self.model.primitive(id) {
                self.sensor_override.insert(id, SensorValue { value: v, signal: scene::signal_for(p.part, v) });
            }
        }
        Ok(())
    }

    /// Drops the outside values of these sensors (all when `ids` is `None`): the model
    /// synthesizes them again from the next frame on.
    pub fn clear_sensor_overrides(&mut self, ids: Option<&[PrimitiveId]>) {
        match ids {
            None => self.sensor_override.clear(),
            Some(ids) => {
                for id in ids {
                    self.sensor_override.remove(id);
                }
            }
        }
    }

    /// Supplies the camera picture (sensor-resolution RGB, `width × height × 3` bytes of
    /// [`camera::Camera::rgb`]) used for every image from now on; `None` returns to the
    /// image file source or the rendered scene.
    pub fn set_camera_rgb(&mut self, rgb: Option<Vec<u8>>) -> Result<(), String> {
        if let Some(data) = &rgb {
            let n = self.camera.rgb.width * self.camera.rgb.height * 3;
            if data.len() != n {
                return Err(format!("camera image of {} bytes, expected {n} ({}x{} RGB)", data.len(), self.camera.rgb.width, self.camera.rgb.height));
            }
        }
        self.external_rgb = rgb;
        Ok(())
    }

    /// Executes one 8 ms frame.
    pub fn step_frame(&mut self) -> FrameOutput {
        let p = self.begin_frame();
        self.end_frame(p)
    }

    /// First half of a frame: the effector's commands of the frame are applied (targets,
    /// LEDs, ears) and the servos advanced. Readings from outside may then replace the
    /// measured state ([`VirtualRobot::apply_readings`]) before [`VirtualRobot::end_frame`]
    /// samples the sensors.
    pub fn begin_frame(&mut self) -> PendingFrame {
        let tick = self.clock.tick();
        let ef = self.effector.step(tick.count, tick.frame, &mut self.sync);
        let mut events: Vec<TraceEvent> = std::mem::take(&mut self.pending_trace);
        let tracing = self.trace_enabled;

        if tracing {
            for &(key, timed_out) in &ef.sync_released {
                events.push(TraceEvent::Sync { key, timed_out });
            }
            for s in &ef.started {
                events.push(TraceEvent::VectorStart {
                    conn: s.connection,
                    token: s.token,
                    duration_frames: s.duration,
                    slots: s.slots.iter().map(|q| self.slot_summary(q)).collect(),
                });
            }
            for c in &ef.clamps {
                events.push(TraceEvent::Clamp {
                    locator: self.locator(c.primitive),
                    requested_deg: degrees(c.requested as f64),
                    clamped_deg: degrees(c.clamped as f64),
                    combined: c.rule == ClampRule::Combined,
                });
            }
        }
        let mut changes = self.body.apply(&ef.applied, tick.count);
        changes.extend(self.body.step(tick.count));
        if tracing {
            for ch in changes {
                events.push(match ch {
                    Change::Led { primitive, state: LedState::Led2 { on } } => TraceEvent::Led2 { locator: self.locator(primitive), on },
                    Change::Led { primitive, state: LedState::Led3 { intensity, mode } } => {
                        TraceEvent::Led3 { locator: self.locator(primitive), intensity, mode }
                    }
                    Change::FaceMode { mode } => TraceEvent::FaceMode { mode },
                    Change::Ear { primitive, state } => TraceEvent::Ear { locator: self.locator(primitive), state },
                    Change::EarHeldTooLong { primitive } => TraceEvent::EarHeld { locator: self.locator(primitive) },
                });
            }
        }
        PendingFrame { tick, ef, events }
    }

    /// Second half of a frame: samples the sensors, completes the sensor vector when due.
    pub fn end_frame(&mut self, pending: PendingFrame) -> FrameOutput {
        let PendingFrame { tick, ef, mut events } = pending;
        let tracing = self.trace_enabled;
        // sensors of this frame
        self.synth.sample_into(&self.body, &self.scene, tick.frame, &mut self.latest);
        for (id, v) in &self.sensor_override {
            self.latest.insert(*id, *v);
        }
        // Sized up front: collected from a filtering iterator, it would grow five times.
        let mut snapshot = Vec::with_capacity(self.model.sensor_count());
        snapshot.extend(self.model.sensor_entries().map(|p| match self.body.joint_value(p.id) {
            Some(j) => FrameValue::Joint(j),
            None => FrameValue::Sensor(self.latest.get(&p.id).copied().unwrap_or_default()),
        }));
        self.window.push(snapshot);
        if ef.optional.is_some() {
            self.window_optional = ef.optional.clone();
        }
        let mut sensor_vector = None;
        if let Some(first) = tick.sensor_vector {
            let start = self.window.len().saturating_sub(4);
            let frames = &self.window[start..];
            if frames.len() == 4 {
                let mut entries = Vec::with_capacity(self.model.sensor_count());
                entries.extend(self.model.sensor_entries().enumerate().map(|(i, p)| SensorEntry {
                    data_type: p.kind.sensor_data_type(),
                    primitive: p.id,
                    frames: [0, 1, 2, 3].map(|k| frames[k].get(i).copied().unwrap_or(FrameValue::Sensor(SensorValue::default()))),
                }));
                let opt = self.window_optional.as_ref().map(|(o, b)| (*o, b.as_slice()));
                sensor_vector = vectors::build_sensor_vector(first, &entries, opt).ok();
                if tracing {
                    events.push(self.sensor_summary(first));
                }
            }
            self.window.clear();
            self.window_optional = None;
        }
        if tracing {
            for c in &ef.completed {
                events.push(TraceEvent::VectorDone { conn: c.connection, token: c.token });
            }
        }
        FrameOutput {
            frame: tick.frame,
            time_ms: tick.time_ms,
            started: ef.started,
            completed: ef.completed,
            sensor_vector,
            camera_due: tick.camera,
            mic_due: tick.mic,
            trace: events.into_iter().map(|event| TraceRecord { t_ms: tick.time_ms, frame: tick.frame, event }).collect(),
        }
    }

    fn slot_summary(&self, q: &effector::QueuedSlot) -> SlotSummary {
        let held = |v: &[vectors::Held<u32>]| v.iter().map(|h| vec![h.value as f64, h.period as f64]).collect();
        let values = match &q.values {
            CommandValues::Joint2(v) => v.iter().map(|&x| vec![degrees(x as f64)]).collect(),
            CommandValues::Joint3(v) => v.iter().map(|&x| vec![x as f64]).collect(),
            CommandValues::Joint4(v) | CommandValues::Led2(v) | CommandValues::LegacyLed(v) => held(v),
            CommandValues::Led3(v) => v.iter().map(|h| vec![h.value.intensity as f64, h.value.mode as f64, h.period as f64]).collect(),
            CommandValues::Unsupported(_) => Vec::new(),
        };
        SlotSummary {
            index: q.index,
            locator: self.model.locator(q.primitive),
            primitive: q.primitive,
            type_name: q.values.type_name(),
            ignored: !q.active,
            values,
        }
    }

    fn sensor_summary(&self, first_frame: u32) -> TraceEvent {
        let joints = self.model.sensor_entries().filter_map(|p| self.body.joint(p.id).map(|j| (p.locator, degrees(j.angle)))).collect();
        let acc = |i: u8| self.primitive_of(Part::Accel(i)).and_then(|id| self.latest.get(&id)).map_or(0.0, |v| v.value as f64 / 1e6);
        let paw = |l: Leg| self.primitive_of(Part::PawSwitch(l)).and_then(|id| self.latest.get(&id)).is_some_and(|v| v.value != 0);
        TraceEvent::Sensor {
            first_frame,
            joints,
            accel: [acc(0), acc(1), acc(2)],
            paws: [paw(Leg::LeftFront), paw(Leg::LeftRear), paw(Leg::RightFront), paw(Leg::RightRear)],
        }
    }
}

#[cfg(test)]
mod tests;
