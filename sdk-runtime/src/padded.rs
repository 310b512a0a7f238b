//! A value on a cache line of its own. Per-object counters and flags that sit side by
//! side are written by different objects' threads on every message; sharing a line,
//! each write would take the line from the other core (false sharing).
use std::ops::Deref;

#[repr(align(64))]
#[derive(Debug, Default)]
pub struct Line<T>(pub T);

impl<T> Deref for Line<T> {
    type Target = T;
    fn deref(&self) -> &T {
        &self.0
    }
}
