//! One moment of the robot as the page draws it, as JSON: virtual time, every joint's
//! measured angle and target, LEDs, ears, sensors, power. Taken under the robot's lock,
//! so it is one consistent frame.
use sdk_runtime::clock::Speed;
use sdk_runtime::robot::kinematics::LedState;
use sdk_runtime::robot::model::{degrees, PrimitiveKind, SensorKind};
use sdk_runtime::runtime::Runtime;
use serde_json::{json, Value};
use std::sync::atomic::Ordering;

/// Degrees rounded to 3 decimals, as the trace writes them.
fn deg3(urad: f64) -> f64 {
    (degrees(urad.round()) * 1000.0).round() / 1000.0
}

pub fn take(rt: &Runtime) -> Value {
    let robot = rt.vr.robot();
    let body = robot.body();
    let (mut joints, mut leds, mut ears, mut sensors) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for p in robot.model().primitives() {
        let loc = p.locator;
        match p.kind {
            PrimitiveKind::Joint2 => {
                if let Some(j) = body.joint(p.id) {
                    joints.push(json!({ "locator": loc, "deg": deg3(j.angle), "target_deg": deg3(j.reference as f64) }));
                }
            }
            PrimitiveKind::Led2 | PrimitiveKind::Led3 => match body.led(p.id) {
                Some(LedState::Led2 { on }) => leds.push(json!({ "locator": loc, "kind": 2, "value": if on { 255 } else { 0 } })),
                Some(LedState::Led3 { intensity, mode }) => leds.push(json!({ "locator": loc, "kind": 3, "value": intensity, "mode": mode })),
                None => {}
            },
            PrimitiveKind::Joint3 | PrimitiveKind::Joint4 => {
                if let Some(s) = body.ear(p.id) {
                    ears.push(json!({ "locator": loc, "state": s }));
                }
            }
            PrimitiveKind::Sensor(kind) => {
                if let Ok(v) = robot.sensor_value(p.id) {
                    sensors.push(json!({ "locator": loc, "kind": sensor_kind(kind), "value": v.value }));
                }
            }
            _ => {}
        }
    }
    let power = rt.power.state();
    let speed = match rt.clock.speed() {
        Speed::Max => "max".to_string(),
        Speed::Factor(f) => format!("{f}"),
    };
    json!({
        "design": robot.model().design().name(),
        "frame": robot.clock().frame(),
        "t_ms": rt.clock.since_boot().as_millis() as u64,
        "paused": rt.clock.paused(),
        "speed": speed,
        "motor_power": body.motor_power(),
        "camera_images": robot.camera().field_counter.saturating_sub(1),
        "face_mode": body.face_mode(),
        "joints": joints,
        "leds": leds,
        "ears": ears,
        "sensors": sensors,
        "objects": objects(rt),
        "connections": connections(rt),
        "battery": { "remaining_pct": power.remaining_capacity, "voltage_mv": power.voltage, "current_ma": power.current, "temperature_cc": power.temperature },
    })
}

/// The program's objects (OBJECT.CFG's, not the system's), in load order.
fn objects(rt: &Runtime) -> Vec<String> {
    rt.all_objects().iter().filter(|o| o.oid >= sdk_runtime::runtime::FIRST_OID).map(|o| o.name().to_string()).collect()
}

/// The made connections with the messages delivered on each so far.
pub fn connections(rt: &Runtime) -> Value {
    let links = rt.links.all().iter().map(|l| {
        json!({ "subject": l.subject, "observer": l.observer, "notify": l.notify.count.load(Ordering::Relaxed), "ready": l.ready.count.load(Ordering::Relaxed) })
    });
    Value::Array(links.collect())
}

fn sensor_kind(k: SensorKind) -> &'static str {
    match k {
        SensorKind::Switch => "switch",
        SensorKind::Touch => "touch",
        SensorKind::Pressure => "pressure",
        SensorKind::Psd => "psd",
        SensorKind::Accelerometer => "accel",
        SensorKind::Thermometer => "thermometer",
    }
}
