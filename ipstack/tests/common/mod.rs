//! A [`Host`] that records what the stack sends and says, and serves stick files from a list.
#![allow(dead_code)] // each test file uses part of it

use std::sync::mpsc::{self, Receiver, Sender};
use std::sync::Mutex;

use openr_ipstack::{Host, Report, Selector};

pub struct Recorder {
    sent: Mutex<Sender<(usize, u32, Vec<u8>)>>,
    /// What `send` was given, in order.
    pub replies: Mutex<Receiver<(usize, u32, Vec<u8>)>>,
    lines: Mutex<Vec<String>>,
    stick: Vec<(&'static str, &'static str)>,
}

impl Recorder {
    pub fn new(stick: Vec<(&'static str, &'static str)>) -> Recorder {
        let (tx, rx) = mpsc::channel();
        Recorder { sent: Mutex::new(tx), replies: Mutex::new(rx), lines: Mutex::new(Vec::new()), stick }
    }

    /// Every warning (`warning: …`), info and trace line so far.
    pub fn lines(&self) -> Vec<String> {
        self.lines.lock().unwrap().clone()
    }
}

impl Report for Recorder {
    fn warn(&self, msg: &str) {
        self.lines.lock().unwrap().push(format!("warning: {msg}"));
    }
    fn info(&self, line: &str) {
        self.lines.lock().unwrap().push(line.to_string());
    }
    fn trace(&self, line: &str) {
        self.lines.lock().unwrap().push(line.to_string());
    }
}

impl Host for Recorder {
    fn send(&self, oid: usize, selector: Selector, message: Vec<u8>) {
        let _ = self.sent.lock().unwrap().send((oid, selector.0, message));
    }
    fn read_stick(&self, path: &str) -> Option<String> {
        self.stick.iter().find(|(p, _)| *p == path).map(|(_, t)| t.to_string())
    }
}
