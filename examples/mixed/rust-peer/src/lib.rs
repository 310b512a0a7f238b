//! RustPeer: sends three strings to whoever observes `RustPeer.SendString.char.S` (the
//! C++ object), one per ASSERT READY, and prints what arrives at
//! `RustPeer.ReceiveString.char.O` — the Rust twin of `CxxPeer.cc`.
use openr::{osysprint, Context, NotifyEvent, Object, Observer, ReadyEvent, Subject};

struct RustPeer {
    send: Subject<str>,
    receive: Observer<str>,
    sent: u32,
}

impl Object for RustPeer {
    fn init(ctx: &mut Context) -> Self {
        RustPeer { send: ctx.subject("RustPeer.SendString.char.S"), receive: ctx.observer("RustPeer.ReceiveString.char.O"), sent: 0 }
    }

    fn ready(&mut self, ctx: &mut Context, event: ReadyEvent) {
        if !self.send.is(&event) || !event.is_assert() || self.sent >= 3 {
            return;
        }
        self.sent += 1;
        self.send.send(ctx, &format!("hello {} from Rust", self.sent));
    }

    fn notify(&mut self, ctx: &mut Context, event: NotifyEvent) {
        if self.receive.is(&event) {
            let text = self.receive.data(&event, 0).unwrap_or("<not a string>");
            osysprint!("RustPeer::Notify() {text}\n");
            self.receive.assert_ready(ctx);
        }
    }
}

openr::object!(RustPeer, "rustPeer");
