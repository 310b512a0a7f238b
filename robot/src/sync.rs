//! Synchronisation keys (robot-api 4.4, 8.2.5).
//!
//! Why it exists: `NewSyncKey`/`DivideSyncKey` let several command and sound vectors
//! start on the same frame (MoNet starts a motion and a sound together). A key is a root
//! with up to 16 leaf parts; every vector carries one part. A vector whose part is
//! known waits ("arrives") at the head of its queue until a vector for **every** part of
//! its root has arrived — on any effector or speaker connection — then all start on the
//! same frame and the root is consumed (its slot is free for `NewSyncKey` again). If the
//! parts never all arrive, the group starts anyway [`SyncKeys::timeout_frames`] frames
//! after the first arrival (default 125 = 1 s) to avoid deadlock.
//!
//! A vector carrying an unknown key (never issued, cancelled or already consumed) starts
//! as if it carried none. Key values are never reused within a run and are never 0 or
//! `ovrsynckeyUNDEF`.

use std::collections::{BTreeMap, BTreeSet};

use super::status::{OStatus, O_FAIL, O_INVALID_SYNC_KEY, O_NO_SYNC_KEY, O_SUCCESS};

/// `ovrsynckeyMAX_NUM_KEY`.
pub const MAX_KEYS: usize = 8;
/// `ovrsynckeyMAX_NUM_DIVISION`.
pub const MAX_PARTS: usize = 16;
pub use super::vectors::SYNC_KEY_UNDEF;

#[derive(Clone, Debug, Default)]
struct Root {
    parts: BTreeSet<u32>,
    arrived: BTreeSet<u32>,
    first_arrival: Option<u64>,
}

/// State of one part as seen by a waiting vector.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PartState {
    /// Not a live key: start without waiting.
    Unknown,
    /// Wait.
    Waiting,
    /// Start now (and call [`SyncKeys::take`]).
    Released,
}

/// The key registry.
#[derive(Clone, Debug)]
pub struct SyncKeys {
    next: u32,
    roots: BTreeMap<u32, Root>,
    /// part → root
    part_root: BTreeMap<u32, u32>,
    /// Released parts not yet taken, with whether the release was a timeout.
    released: BTreeMap<u32, bool>,
    pub timeout_frames: u64,
}

impl Default for SyncKeys {
    fn default() -> Self {
        SyncKeys::new()
    }
}

impl SyncKeys {
    pub fn new() -> SyncKeys {
        SyncKeys { next: 1, roots: BTreeMap::new(), part_root: BTreeMap::new(), released: BTreeMap::new(), timeout_frames: 125 }
    }

    fn fresh(&mut self) -> u32 {
        let k = self.next;
        self.next = self.next.wrapping_add(1);
        if self.next == 0 || self.next == SYNC_KEY_UNDEF {
            self.next = 1;
        }
        k
    }

    /// `NewSyncKey`: a new key, or `Err(oNO_SYNC_KEY)` when 8 keys exist (the caller
    /// then stores `ovrsynckeyUNDEF`).
    pub fn new_key(&mut self) -> Result<u32, OStatus> {
        if self.roots.len() >= MAX_KEYS {
            return Err(O_NO_SYNC_KEY);
        }
        let k = self.fresh();
        let mut root = Root::default();
        root.parts.insert(k);
        self.roots.insert(k, root);
        self.part_root.insert(k, k);
        Ok(k)
    }

    /// `CancelSyncKey`: `key` may be the original key or any part; cancels the whole key.
    pub fn cancel(&mut self, key: u32) -> OStatus {
        let root = if self.roots.contains_key(&key) { key } else { *self.part_root.get(&key).unwrap_or(&SYNC_KEY_UNDEF) };
        if root == SYNC_KEY_UNDEF {
            return O_INVALID_SYNC_KEY;
        }
        if let Some(r) = self.roots.remove(&root) {
            for p in r.parts {
                self.part_root.remove(&p);
            }
        }
        O_SUCCESS
    }

    /// `DivideSyncKey`: replaces part `key` by two new parts. `oINVALID_SYNC_KEY` for an
    /// unknown key, `oFAIL` when the root already has 16 parts or the key is in use.
    pub fn divide(&mut self, key: u32) -> Result<(u32, u32), OStatus> {
        let Some(&root) = self.part_root.get(&key) else { return Err(O_INVALID_SYNC_KEY) };
        let Some(r) = self.roots.get(&root) else { return Err(O_INVALID_SYNC_KEY) };
        if r.parts.len() >= MAX_PARTS || r.arrived.contains(&key) {
            return Err(O_FAIL);
        }
        let (a, b) = (self.fresh(), self.fresh());
        if let Some(r) = self.roots.get_mut(&root) {
            r.parts.remove(&key);
            r.parts.insert(a);
            r.parts.insert(b);
        }
        self.part_root.remove(&key);
        self.part_root.insert(a, root);
        self.part_root.insert(b, root);
        Ok((a, b))
    }

    /// Number of live keys (roots).
    pub fn live_keys(&self) -> usize {
        self.roots.len()
    }

    /// A vector carrying `part` is ready to start (called once per vector, at frame
    /// count `now`).
    pub fn arrive(&mut self, part: u32, now: u64) {
        if let Some(&root) = self.part_root.get(&part) {
            if let Some(r) = self.roots.get_mut(&root) {
                r.arrived.insert(part);
                r.first_arrival.get_or_insert(now);
            }
        }
    }

    /// Releases every root whose parts have all arrived, or whose first arrival is
    /// `timeout_frames` old. Returns `(root, timed_out)` for each released root.
    pub fn resolve(&mut self, now: u64) -> Vec<(u32, bool)> {
        let done: Vec<(u32, bool)> = self
            .roots
            .iter()
            .filter_map(|(&k, r)| {
                if !r.parts.is_empty() && r.arrived.len() == r.parts.len() {
                    Some((k, false))
                } else {
                    r.first_arrival.filter(|&t| now.saturating_sub(t) >= self.timeout_frames).map(|_| (k, true))
                }
            })
            .collect();
        for &(k, timed_out) in &done {
            if let Some(r) = self.roots.remove(&k) {
                for p in r.parts {
                    self.part_root.remove(&p);
                    if r.arrived.contains(&p) {
                        self.released.insert(p, timed_out);
                    }
                }
            }
        }
        done
    }

    pub fn state(&self, part: u32) -> PartState {
        if self.released.contains_key(&part) {
            PartState::Released
        } else if self.part_root.contains_key(&part) {
            PartState::Waiting
        } else {
            PartState::Unknown
        }
    }

    /// Consumes a released part (its vector starts now).
    pub fn take(&mut self, part: u32) -> bool {
        self.released.remove(&part).is_some()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn at_most_8_keys_and_16_parts() {
        let mut s = SyncKeys::new();
        let keys: Vec<u32> = (0..8).map(|_| s.new_key().unwrap()).collect();
        assert!(keys.iter().all(|&k| k != 0 && k != SYNC_KEY_UNDEF));
        assert_eq!(s.new_key(), Err(O_NO_SYNC_KEY));
        assert_eq!(s.cancel(keys[0]), O_SUCCESS);
        assert_eq!(s.cancel(keys[0]), O_INVALID_SYNC_KEY);
        let k = s.new_key().unwrap();
        let mut parts = vec![k];
        while let Some(p) = parts.pop() {
            match s.divide(p) {
                Ok((a, b)) => {
                    parts.insert(0, a);
                    parts.insert(0, b);
                }
                Err(e) => {
                    assert_eq!(e, O_FAIL);
                    parts.push(p);
                    break;
                }
            }
        }
        assert_eq!(parts.len(), 16);
        assert_eq!(s.divide(12345), Err(O_INVALID_SYNC_KEY));
    }

    #[test]
    fn all_parts_release_together_or_timeout() {
        let mut s = SyncKeys::new();
        let k = s.new_key().unwrap();
        let (a, b) = s.divide(k).unwrap();
        assert_eq!(s.state(k), PartState::Unknown);
        s.arrive(a, 10);
        assert!(s.resolve(10).is_empty());
        assert_eq!(s.state(a), PartState::Waiting);
        s.arrive(b, 12);
        assert_eq!(s.resolve(12), vec![(k, false)]);
        assert_eq!(s.state(a), PartState::Released);
        assert!(s.take(a) && s.take(b));
        assert_eq!(s.state(a), PartState::Unknown);
        assert_eq!(s.live_keys(), 0);
        let k = s.new_key().unwrap();
        let (a, _b) = s.divide(k).unwrap();
        s.arrive(a, 100);
        assert!(s.resolve(224).is_empty());
        assert_eq!(s.resolve(225), vec![(k, true)]);
        assert_eq!(s.state(a), PartState::Released);
    }
}
