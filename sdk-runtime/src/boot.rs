//! Running a Memory Stick: load every object of OBJECT.CFG in order, then the OPEN-R
//! life cycle (object-model 2.1): Init all → connect (CONNECT.CFG) → Start all → … →
//! Stop all → Destroy all.
use std::ffi::CString;
use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicBool;
use std::sync::mpsc;
use std::sync::{Arc, Mutex};
use std::time::Duration;

use crate::cfg;
use crate::clock::Clock;
use crate::error::{Error, ErrorKind, Result};
use crate::loader::{self, Module};
use crate::ms::MsDir;
use crate::object::{self, ObjectSlot};
use crate::power::{Power, PowerState, ORSB_MOTOR_POWER, ORSB_PAUSE};
use crate::runtime::{Diag, Runtime, FIRST_OID, FIRST_SYSTEM_OID};
use crate::shm::ShmTable;
use crate::timers::Timers;

/// Options of one run.
#[derive(Debug, Clone)]
pub struct RunOptions {
    pub ms_dir: PathBuf,
    /// A base tree laid under `ms_dir` (reads fall through to it, writes stay in
    /// `ms_dir`: `ms`), as on a robot's stick.
    pub ms_base: Option<PathBuf>,
    /// Robot design name (`ERS-7`), selects CFG sections and `GetRobotDesign`.
    pub design: String,
    /// Stop cleanly after this long.
    pub run_for: Option<Duration>,
    pub diag: Diag,
    /// Skip CONNECT.CFG lines naming unregistered services with a warning, as the robot
    /// does, instead of failing.
    pub lenient_connect: bool,
    /// System objects (`OVirtualRobotComm`, …) to load before the user objects.
    pub system_objects: Vec<PathBuf>,
    /// Write the virtual robot's JSON-lines trace here.
    pub trace: Option<PathBuf>,
    /// How fast virtual time runs.
    pub speed: crate::clock::Speed,
    /// Append what the speaker plays to this WAV file.
    pub speaker_wav: Option<PathBuf>,
    /// Feed the microphones from this WAV file (silence when absent or finished).
    pub mic_wav: Option<PathBuf>,
    /// Camera frames from an image file or a directory of frames instead of the scene.
    pub images: Option<PathBuf>,
    /// Shift of the camera's image timing from boot, ms (0: the first image at 33 ms).
    pub camera_phase_ms: u64,
    /// Unix socket for pause / step / resume / speed commands.
    pub control: Option<PathBuf>,
    /// External robot peers: where they attach, whether to wait for one
    /// (docs/robot-protocol.md).
    pub peers: crate::peer::PeerOptions,
    /// Object threads trap on FP errors like the robot's CPU (off: `--no-fp-traps`).
    pub fp_traps: bool,
    /// In-process observers (the `--view` server), attached before the first frame.
    pub observers: crate::observe::Observers,
    /// Real time an object may take to answer a life-cycle call, or to run one message
    /// at `--speed max`, before it is reported stuck (lifecycle.rs, sched.rs).
    pub watchdog: Duration,
    /// Where endpoints bind, port offset and remaps (network-api 11).
    pub net: openr_ipstack::NetOptions,
}

/// How a run went.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Outcome {
    pub ended: Ended,
    /// Objects that did not answer a life-cycle call, with what they were running: the
    /// run failed even if it ended on time.
    pub failures: Vec<String>,
    /// Robot frames (8 ms) run, and how many of them started late in real time.
    pub frames: u64,
    pub late_frames: u64,
}

/// How a run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ended {
    /// `--for` elapsed.
    TimeUp,
    /// SIGINT / SIGTERM.
    Signal(i32),
    /// An object called `OPENR::Shutdown`.
    Shutdown,
    /// An object called `OPENR::Fatal` with this OFatal: the robot powered off.
    Fatal(u32),
}

/// Whether the stick at `ms_dir` is a host program of Remote Processing OPEN-R (it has a
/// HOSTGW.CFG), however it is started. libOPENR then refuses the calls Sony's host objects
/// cannot make (remote-processing 4) rather than run them on this PC's emulated robot
/// instead of the robot at the far end: the caller sets `OPENR_RP_HOST=1`, which libOPENR
/// reads, before any thread of the process exists.
pub fn is_rp_host_program(ms_dir: &Path) -> bool {
    MsDir::new(ms_dir).is_ok_and(|ms| cfg::is_rp(&ms, "HOSTGW.CFG"))
}

/// Loads and runs the stick until it ends; returns how it ended.
pub fn run(opts: &RunOptions) -> Result<Outcome> {
    let stick = read_stick(opts)?;
    let signals = take_over_process(opts)?;
    let Stick { ms, robot, object_cfg_path, objects, connect_path, connections, duplicates, design_db, images, system_images, mic_pcm, trace } = stick;
    let rt = install(opts, ms, design_db, robot, trace, mic_pcm)?;
    for (line, first) in duplicates {
        rt.diag.warn(&format!("{}:{line}: the connection of line {first} again: left out", connect_path.display()));
    }
    watch_signals(rt, signals)?;
    load_all(rt, opts, system_images, (&object_cfg_path, &objects), images)?;
    let all = rt.all_objects();
    rt.diag.info(&format!("loaded {} object(s) from {}", all.len(), object_cfg_path.display()));
    start_services(rt, opts)?;
    let mut booted = Vec::new();
    let mut failures = crate::lifecycle::Failures::default();
    let boot = crate::lifecycle::boot(rt, &all, (&connect_path, &connections), opts.lenient_connect, opts.watchdog, &mut booted, &mut failures)?;
    rt.booting.store(false, std::sync::atomic::Ordering::Release);
    let ended = match boot {
        Ok(()) => {
            rt.diag.info("all objects started");
            wait_for_end(rt, opts.run_for)
        }
        Err(crate::lifecycle::Interrupted(sig)) => Ended::Signal(sig),
    };
    let outcome = end_run(rt, opts, ended, &booted, failures);
    rt.retire();
    outcome
}

/// What the stick holds, read (and checked) before anything starts.
struct Stick {
    ms: MsDir,
    robot: crate::robot::VirtualRobot,
    object_cfg_path: PathBuf,
    objects: Vec<cfg::ObjectEntry>,
    connect_path: PathBuf,
    connections: Vec<cfg::Connection>,
    /// CONNECT.CFG lines left out as duplicates (line, first line).
    duplicates: Vec<(usize, usize)>,
    design_db: Vec<(String, String)>,
    images: Vec<Vec<u8>>,
    system_images: Vec<Vec<u8>>,
    mic_pcm: Vec<u8>,
    trace: Option<std::fs::File>,
}

/// Reads the stick, the robot's inputs and every image, so a bad file fails the run
/// before any object starts.
fn read_stick(opts: &RunOptions) -> Result<Stick> {
    let ms = MsDir::new(&opts.ms_dir).map_err(|e| Error::io(&opts.ms_dir, e))?;
    let ms = match &opts.ms_base {
        Some(base) => ms.with_base(base).map_err(|e| Error::io(base, e))?,
        None => ms,
    };
    // The design first: it selects the CFG sections read next.
    let mut robot = crate::robot::VirtualRobot::from_design_name(&opts.design).ok_or_else(|| {
        let known: Vec<&str> = crate::robot::model::Design::ALL.iter().map(|d| d.name()).collect();
        ErrorKind::Runtime(format!("unknown robot design `{}` (known: {})", opts.design, known.join(", ")))
    })?;
    let (object_cfg_path, objects) = cfg::object_cfg(&ms, &opts.design)?;
    let (connect_path, connections, duplicates) = cfg::connect_cfg(&ms, &opts.design)?;
    let design_db = cfg::design_db(&ms, &opts.design)?;
    // Read every image before starting anything, so a bad .BIN fails the run cleanly.
    let images: Vec<Vec<u8>> = objects.iter().map(|o| loader::read_bin(&o.host_path)).collect::<Result<_>>()?;
    let system_images: Vec<Vec<u8>> = opts.system_objects.iter().map(|p| loader::read_bin(p)).collect::<Result<_>>()?;
    let mic_pcm = match &opts.mic_wav {
        Some(p) => crate::audio::read_wav_as_mic(p)?,
        None => Vec::new(),
    };
    robot.set_camera_phase(opts.camera_phase_ms);
    if let Some(p) = &opts.images {
        robot.set_image_source(Some(p)).map_err(|e| Error::config(p, None, format!("cannot use as camera images: {e}")))?;
    }
    let trace = match &opts.trace {
        Some(p) => Some(std::fs::File::create(p).map_err(|e| Error::io(p, e))?),
        None => None,
    };
    Ok(Stick { ms, robot, object_cfg_path, objects, connect_path, connections, duplicates, design_db, images, system_images, mic_pcm, trace })
}

/// The process becomes the robot: signals, stdin, the crash reporter, FP traps, stdio.
fn take_over_process(opts: &RunOptions) -> Result<crate::signals::Termination> {
    let signals = crate::signals::block_termination()?;
    crate::console::input::take_over_stdin();
    crate::crash::install();
    crate::crash::set_fp_traps(opts.fp_traps);
    // Objects' printf/cout go through C stdio: line-buffer it like a console.
    // SAFETY: `stdout_file` is glibc's live `stdout`; nothing has written to it yet (setvbuf's rule).
    unsafe { libc::setvbuf(crate::console::stdout_file(), std::ptr::null_mut(), libc::_IOLBF, 0) };
    std::hint::black_box(crate::host_api::api_table());
    std::hint::black_box(crate::interpose::keep());
    Ok(signals)
}

/// Installs the process's runtime.
fn install(
    opts: &RunOptions,
    ms: MsDir,
    design_db: Vec<(String, String)>,
    robot: crate::robot::VirtualRobot,
    trace: Option<std::fs::File>,
    mic_pcm: Vec<u8>,
) -> Result<&'static Runtime> {
    let clock = Clock::new(opts.speed);
    let sched = crate::sched::Sched::default();
    sched.set_serial(opts.speed == crate::clock::Speed::Max);
    sched.set_watchdog(opts.watchdog);
    Ok(Runtime::install(Runtime {
        ms,
        design: CString::new(opts.design.clone()).map_err(|_| ErrorKind::Runtime("bad design name".into()))?,
        design_db,
        objects: Default::default(),
        registry: Mutex::new(Vec::new()),
        shm: ShmTable::new(),
        design_data: Mutex::new(Vec::new()),
        power: Power::new(crate::power::initial_state(clock.calendar().1)),
        clock,
        diag: opts.diag.clone(),
        shutdown_requested: AtomicBool::new(false),
        fatal: std::sync::atomic::AtomicU32::new(crate::runtime::NO_FATAL),
        booting: AtomicBool::new(true),
        timers: Timers::new(),
        vr: crate::vr::VrService::new(robot, trace, crate::audio::Speaker::new(opts.speaker_wav.clone()), crate::audio::Mic::new(mic_pcm)),
        vectors: Mutex::new(Vec::new()),
        sched,
        signal: std::sync::atomic::AtomicI32::new(0),
        links: Default::default(),
        net: crate::net::NetState::new(opts.net.clone()),
        gateway: Default::default(),
        console: Default::default(),
        internal_errors: std::sync::atomic::AtomicU32::new(0),
    }))
}

/// Loads the system objects, then OBJECT.CFG's, in order (their static constructors run).
fn load_all(
    rt: &'static Runtime,
    opts: &RunOptions,
    system_images: Vec<Vec<u8>>,
    cfg: (&std::path::Path, &[cfg::ObjectEntry]),
    images: Vec<Vec<u8>>,
) -> Result<()> {
    let (object_cfg_path, objects) = cfg;
    for (i, (path, image)) in opts.system_objects.iter().zip(system_images).enumerate() {
        let label = format!("/SYSTEM/OBJS/{}", path.file_name().map_or(String::new(), |n| n.to_string_lossy().into_owned()));
        load_object(rt, FIRST_SYSTEM_OID + i, &label, path, image)?;
    }
    // An RP OPEN-R host program (a HOSTGW.CFG): the host gateway comes first, as
    // `start-rp-openr` started it (remote-processing 1.2), and as a user object: its
    // channels open at its Start, once CONNECT.CFG is connected.
    let mut first = FIRST_OID;
    if let Some(hostgw) = rt.ms.existing_in_program("/MS/OPEN-R/MW/CONF/HOSTGW.CFG") {
        let image = [crate::gateway::MAGIC, crate::gateway::HOST_GATEWAY.as_bytes()].concat();
        load_object(rt, first, "tcpGateway", &hostgw, image)?;
        first += 1;
    }
    for (i, (entry, image)) in objects.iter().zip(images).enumerate() {
        load_object(rt, first + i, &entry.ms_path, &entry.host_path, image).map_err(|e| with_cfg_line(e, &object_cfg_path, entry.line))?;
    }
    Ok(())
}

/// The clock limit, the control socket, peers, observers and the frame thread.
fn start_services(rt: &'static Runtime, opts: &RunOptions) -> Result<()> {
    // Virtual time runs from here on: an object may sleep in its DoInit.
    rt.clock.set_limit(opts.run_for);
    if let Some(path) = &opts.control {
        crate::control::serve(rt, path)?;
    }
    crate::peer::serve(rt, &opts.peers)?;
    for o in &opts.observers.0 {
        o.attach(rt)?;
    }
    let _ = rt.vr.observers.set(opts.observers.clone());
    crate::runtime::spawn("openr-robot", move || crate::vr::run_frames(rt)).map_err(|e| ErrorKind::Runtime(format!("cannot start the robot thread: {e}")))?;
    Ok(())
}

/// Stop and Destroy (unless the robot powered off), then the run's outcome.
fn end_run(rt: &'static Runtime, opts: &RunOptions, ended: Ended, booted: &[Arc<ObjectSlot>], mut failures: crate::lifecycle::Failures) -> Result<Outcome> {
    rt.diag.info(&format!("shutting down ({ended:?}): Stop, then Destroy"));
    // No frame after the end; at `--speed max` the shutdown takes its turn where the
    // frame thread stopped (sched.rs), so it begins at the same message every run.
    rt.clock.freeze();
    rt.vr.peers.stop_lockstep();
    if let Ended::Fatal(kind) = ended {
        // Powered off: no Stop, no Destroy (the caller holds its turn, blocked for good).
        failures.0.push(format!("the program called OPENR::Fatal(0x{kind:x}) and the robot powered off"));
    } else {
        rt.sched.take_over(Duration::from_secs(2));
        rt.sched.release();
        crate::lifecycle::shutdown(rt, booted, opts.watchdog, &mut failures);
    }
    failures.0.extend(crate::gateway::failures(rt));
    let internal = rt.internal_errors.load(std::sync::atomic::Ordering::Acquire);
    if internal > 0 {
        failures.0.push(format!("{internal} call(s) into the runtime panicked (a bug of cargo-openr, said above)"));
    }
    rt.vr.flush_trace();
    for o in &opts.observers.0 {
        o.finish();
    }
    rt.vr.peers.close_all(&format!("the run ended ({ended:?})"));
    // stdout only: fflush(NULL) would wait for stdin's lock, held by a blocked reader.
    // SAFETY: `stdout_file` is glibc's live `stdout` stream.
    unsafe { libc::fflush(crate::console::stdout_file()) };
    let load = |c: &std::sync::atomic::AtomicU64| c.load(std::sync::atomic::Ordering::Relaxed);
    Ok(Outcome { ended, failures: failures.0, frames: load(&rt.vr.frames), late_frames: load(&rt.vr.late_frames) })
}

fn with_cfg_line(e: Error, cfg: &std::path::Path, line: usize) -> Error {
    match e.kind() {
        ErrorKind::Load { .. } => Error::config(cfg, Some(line), e.to_string()),
        _ => e,
    }
}

/// Starts the object's thread, which loads the module (static constructors run there)
/// and then serves messages.
fn load_object(rt: &'static Runtime, oid: usize, ms_path: &str, host: &std::path::Path, image: Vec<u8>) -> Result<()> {
    let slot = rt.objects.push(|index| Arc::new(ObjectSlot::new(index, oid, ms_path.to_string())));
    let index = slot.index;
    let (done_tx, done_rx) = mpsc::sync_channel::<Result<()>>(1);
    let thread_name: String = host.file_stem().map_or("object".into(), |s| s.to_string_lossy().into_owned());
    let host = host.to_path_buf();
    let worker = slot.clone();
    crate::runtime::spawn(thread_name, move || {
        object::set_current(worker.clone());
        crate::crash::arm_thread();
        if rt.clock.speed() != crate::clock::Speed::Max {
            // In real time an object's wake-up on its message is part of the robot's timing.
            crate::pace::short_slice();
        }
        match Module::load(&host, &image, index) {
            Ok(m) => {
                let _ = worker.module.set(m);
                name_thread(worker.name());
                let _ = done_tx.send(Ok(()));
            }
            Err(e) => {
                worker.mailbox.close();
                let _ = done_tx.send(Err(e));
                return;
            }
        }
        drop(image);
        crate::object::run_loop(&worker, |m| rt.diag.warn(&m));
    })
    .map_err(|e| ErrorKind::Runtime(format!("cannot start a thread for {ms_path}: {e}")))?;
    done_rx.recv().unwrap_or_else(|_| Err(Error::load(ms_path, "the loading thread died")))?;
    rt.diag.info(&format!("loaded {} as `{}` (oid {:08x})", slot.bin, slot.name(), slot.oid));
    Ok(())
}

/// Names the calling thread after its object (shown by gdb, `top -H`, `ps -L`).
fn name_thread(name: &str) {
    let short: String = name.chars().take(15).collect();
    if let Ok(c) = CString::new(short) {
        // SAFETY: `c` is a C string of at most 15 bytes (the kernel's limit), for this very thread.
        unsafe { libc::pthread_setname_np(libc::pthread_self(), c.as_ptr()) };
    }
}

/// Waits until `run_for` of virtual time has passed, a signal, or OPENR::Shutdown.
fn wait_for_end(rt: &Runtime, run_for: Option<Duration>) -> Ended {
    loop {
        if rt.shutdown_requested.load(std::sync::atomic::Ordering::Acquire) {
            return match rt.fatal.load(std::sync::atomic::Ordering::Acquire) {
                crate::runtime::NO_FATAL => Ended::Shutdown,
                kind => Ended::Fatal(kind),
            };
        }
        if run_for.is_some_and(|total| rt.clock.since_boot() >= total) {
            return Ended::TimeUp;
        }
        match rt.signal.load(std::sync::atomic::Ordering::Acquire) {
            0 => std::thread::sleep(Duration::from_millis(5)),
            sig => return Ended::Signal(sig),
        }
    }
}

/// Collects SIGINT/SIGTERM/SIGHUP (into `rt.signal`, seen by every phase, the boot
/// included) and SIGUSR1 (the pause button) on a thread of its own.
fn watch_signals(rt: &'static Runtime, signals: crate::signals::Termination) -> Result<()> {
    crate::runtime::spawn("openr-signals", move || loop {
        match signals.wait(Duration::from_secs(1)) {
            Some(libc::SIGUSR1) => press_pause_button(rt),
            Some(sig) => rt.signal.store(sig, std::sync::atomic::Ordering::Release),
            None => {}
        }
    })
    .map_err(|e| ErrorKind::Runtime(format!("cannot start the signal thread: {e}")))?;
    Ok(())
}

/// The pause button toggles orsbPAUSE; pressing it also cuts motor power, as the
/// ERS-7's does in hardware (robot-api 9.3, 9.5).
fn press_pause_button(rt: &Runtime) {
    update_power(rt, |s| {
        s.robot_status ^= ORSB_PAUSE;
        if s.robot_status & ORSB_PAUSE != 0 {
            s.robot_status &= !ORSB_MOTOR_POWER;
        }
    });
    let pressed = rt.power.state().robot_status & ORSB_PAUSE != 0;
    rt.diag.info(if pressed { "pause button pressed" } else { "pause button released" });
}

/// Changes the power state and notifies its observers (robot-api 9.3).
pub fn update_power(rt: &Runtime, change: impl FnOnce(&mut PowerState)) {
    let (state, observers) = rt.power.update(change);
    for o in observers {
        let Some(slot) = rt.object(o.oid) else { continue };
        let Some(make) = slot.module.get().and_then(|m| m.make_power) else { continue };
        // SAFETY: the object's power builder reads one PowerState (live for the call) and writes at
        // most `cap` bytes into `buf` (`build`).
        let msg = loader::build(|buf, cap| unsafe { make((&state as *const PowerState).cast(), buf, cap) });
        let _ = rt.send(o.oid, o.selector, msg);
    }
}
