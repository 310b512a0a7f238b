//! Console output in the format of the C++ `osyslog` (object-model 4.2): at most 243
//! characters of text, written as one message; `DEBUG` adds a newline, `DEBUG_NO_NEWLINE`
//! (what `OSYSPRINT` uses) writes the text as is, other priorities are prefixed with
//! `[oid:XXXXXXXX,prio:N] ` and end with a newline.
use crate::host;

/// `OSyslogPriority`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Priority {
    Error,
    Warning,
    Info,
    Debug,
    DebugNoNewline,
}

impl Priority {
    pub fn value(self) -> u32 {
        match self {
            Priority::Error => 1,
            Priority::Warning => 2,
            Priority::Info => 3,
            Priority::Debug => 0xffff_ffff,
            Priority::DebugNoNewline => 0xffff_fffe,
        }
    }
}

/// `osyslogMAX_SIZE`.
pub const MAX_SIZE: usize = 243;

/// Writes `text` with `priority` (what `osyslog!` and `osysprint!` call).
pub fn osyslog(priority: Priority, text: &str) {
    let mut cut = text.len().min(MAX_SIZE);
    while !text.is_char_boundary(cut) {
        cut -= 1;
    }
    let text = &text[..cut];
    let out = match priority {
        Priority::DebugNoNewline => text.to_string(),
        Priority::Debug => format!("{text}\n"),
        p => format!("[oid:{:08x},prio:{}] {text}\n", host::self_oid() as usize as u32, p.value() as i32),
    };
    host::console_write(out.as_bytes());
}

/// `OSYSPRINT`: formats and writes the text as is.
#[macro_export]
macro_rules! osysprint {
    ($($arg:tt)*) => { $crate::console::osyslog($crate::console::Priority::DebugNoNewline, &format!($($arg)*)) };
}

/// `OSYSLOG1((priority, …))`: `osyslog!(Priority::Info, "…", …)`.
#[macro_export]
macro_rules! osyslog {
    ($prio:expr, $($arg:tt)*) => { $crate::console::osyslog($prio, &format!($($arg)*)) };
}
