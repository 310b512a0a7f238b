//! The robot's power state and its observers (robot-api 9): edge-triggered bit
//! observation, "every change" / "not notify" / target values for the scalar fields.
use std::sync::Mutex;

use openr_sys::Selector;

/// `struct openr_power_state` (openr-sys).
pub use openr_sys::openr_power_state as PowerState;

pub const ORSB_MOTOR_POWER: u32 = 0x0000_0002;
pub const ORSB_PAUSE: u32 = 0x0000_0001;
pub const ORSB_BATTERY_CONNECTED: u32 = 0x0000_0040;
pub const ORSB_BATTERY_CAPACITY_LOW: u32 = 0x0000_0200;
pub const ORSB_OPEN_R_POWER_GOOD: u32 = 0x0000_8000;
const OBSB_DISCHARGING: u32 = 0x0040;
const OBSB_INITIALIZED: u32 = 0x0080;

/// A freshly charged ERS-7 battery, discharging (robot-api 9.2 emulator defaults).
pub fn initial_state(time_dif: i32) -> PowerState {
    PowerState {
        robot_status: ORSB_BATTERY_CONNECTED | ORSB_OPEN_R_POWER_GOOD,
        battery_status: OBSB_INITIALIZED | OBSB_DISCHARGING,
        remaining_capacity: 100,
        temperature: 3031,
        fully_charged_capacity: 2000,
        voltage: 8000,
        current: -1000,
        time_dif,
        volume: 3,
    }
}

/// One `ObservePowerStatus` registration.
#[derive(Debug, Clone, Copy)]
pub struct Observer {
    pub oid: usize,
    pub selector: Selector,
    pub filter: PowerState,
}

impl Observer {
    /// Whether going from `old` to `new` is an event for this observer.
    pub fn wants(&self, old: &PowerState, new: &PowerState) -> bool {
        let f = &self.filter;
        let bits = ((old.robot_status ^ new.robot_status) & f.robot_status) != 0 || ((old.battery_status ^ new.battery_status) & f.battery_status) != 0;
        // Scalars: "every change" value, "not notify" value, else a target value.
        let scalar = |every: u32, never: u32, want: u32, o: u32, n: u32| -> bool {
            if want == never || o == n {
                false
            } else {
                want == every || n == want
            }
        };
        bits || scalar(0xFFFF, 0xFFFE, f.remaining_capacity, old.remaining_capacity, new.remaining_capacity)
            || scalar(0xFFFF, 0xFFFE, f.temperature, old.temperature, new.temperature)
            || scalar(0x7F, 0x7E, f.time_dif as u32 & 0xFF, old.time_dif as u32 & 0xFF, new.time_dif as u32 & 0xFF)
            || scalar(0xFF, 0xFE, f.volume, old.volume, new.volume)
    }
}

pub struct Power {
    inner: Mutex<(PowerState, Vec<Observer>)>,
}

impl Power {
    pub fn new(state: PowerState) -> Power {
        Power { inner: Mutex::new((state, Vec::new())) }
    }

    pub fn state(&self) -> PowerState {
        self.inner.lock().unwrap_or_else(|p| p.into_inner()).0
    }

    pub fn observe(&self, obs: Observer) {
        let mut g = self.inner.lock().unwrap_or_else(|p| p.into_inner());
        g.1.retain(|o| !(o.oid == obs.oid && o.selector == obs.selector));
        g.1.push(obs);
    }

    pub fn unobserve(&self, oid: usize, selector: Selector) -> bool {
        let mut g = self.inner.lock().unwrap_or_else(|p| p.into_inner());
        let before = g.1.len();
        g.1.retain(|o| !(o.oid == oid && o.selector == selector));
        g.1.len() != before
    }

    /// Applies `change` and returns the observers to notify with the new state.
    pub fn update(&self, change: impl FnOnce(&mut PowerState)) -> (PowerState, Vec<Observer>) {
        let mut g = self.inner.lock().unwrap_or_else(|p| p.into_inner());
        let old = g.0;
        change(&mut g.0);
        let new = g.0;
        (new, g.1.iter().filter(|o| o.wants(&old, &new)).copied().collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn observer(filter: PowerState) -> Observer {
        Observer { oid: 1, selector: Selector(8), filter }
    }

    #[test]
    fn bits_notify_on_both_edges() {
        let o = observer(PowerState {
            robot_status: ORSB_MOTOR_POWER,
            remaining_capacity: 0xFFFE,
            temperature: 0xFFFE,
            time_dif: 0x7E,
            volume: 0xFE,
            ..Default::default()
        });
        let a = initial_state(0);
        let mut b = a;
        b.robot_status |= ORSB_MOTOR_POWER;
        assert!(o.wants(&a, &b) && o.wants(&b, &a));
        let mut c = a;
        c.remaining_capacity = 99;
        c.robot_status |= ORSB_PAUSE;
        assert!(!o.wants(&a, &c), "unselected bit and not-notify capacity");
    }

    #[test]
    fn scalar_targets_fire_once_on_arrival() {
        let o = observer(PowerState { remaining_capacity: 20, temperature: 0xFFFF, time_dif: 0x7E, volume: 0xFE, ..Default::default() });
        let a = initial_state(0);
        let mut b = a;
        b.remaining_capacity = 21;
        assert!(!o.wants(&a, &b));
        let mut c = b;
        c.remaining_capacity = 20;
        assert!(o.wants(&b, &c));
        let mut d = c;
        d.remaining_capacity = 19;
        assert!(!o.wants(&c, &d), "leaving the target is not an event");
        let mut e = a;
        e.temperature += 1;
        assert!(o.wants(&a, &e), "every change");
    }
}
