//! What a peer sends once attached: one handler per message type (READINGS, IMAGE, MIC,
//! CLOCK, BYE, ERROR), each validating the message against the peer's roles and the
//! lockstep state before filing it in the [`Hub`]; a refused message ends the connection.
use std::io::Read;

use super::wire::*;
use super::{payload, Hub, Peer, MIC_QUEUE_MAX};
use crate::runtime::Runtime;

/// Why a peer's connection ends, as a message handler sees it.
enum Leave {
    /// Its message is refused: ERROR (code, text) goes out, then the connection closes.
    Refuse(u16, String),
    /// It left, or it can no longer be written to: the reason for the log.
    Quit(String),
}

type Handled = std::result::Result<(), Leave>;

/// Reads a peer's messages until it leaves; returns why it left.
pub(super) fn serve_peer(rt: &Runtime, peer: &Peer, reader: &mut impl Read) -> String {
    let hub = &rt.vr.peers;
    loop {
        let (h, payload) = match read_message(reader) {
            Ok(Some(Ok(m))) => m,
            Ok(Some(Err(Refusal(code, text)))) => return refuse_peer(rt, peer, code, text),
            Ok(None) => return "it closed the connection".into(),
            Err(e) => return format!("connection lost: {e}"),
        };
        let handled = match h.kind {
            READINGS => on_readings(rt, peer, h.frame, &payload),
            IMAGE => on_image(rt, peer, &payload),
            MIC => on_mic(hub, peer, &payload),
            CLOCK => on_clock(hub, peer, &payload),
            BYE => Err(Leave::Quit("BYE".into())),
            ERROR => {
                let mut i = In::new(&payload);
                let code = i.u16().unwrap_or(0);
                let text = i.str().unwrap_or_default();
                Err(Leave::Quit(format!("it reported error {code}: {text}")))
            }
            HELLO => Err(Leave::Refuse(E_BAD_STATE, "HELLO twice".into())),
            k => Err(Leave::Refuse(E_BAD_TYPE, format!("message type {k} is not accepted from a peer"))),
        };
        match handled {
            Ok(()) => {}
            Err(Leave::Refuse(code, text)) => return refuse_peer(rt, peer, code, text),
            Err(Leave::Quit(why)) => return why,
        }
    }
}

/// Sends a peer its last message, an ERROR; returns why it left.
fn refuse_peer(rt: &Runtime, peer: &Peer, code: u16, text: String) -> String {
    let frame = rt.vr.peers.lock().last_frame;
    rt.diag.warn(&format!("robot peer `{}`: {text} (error {code}; connection closed)", peer.name));
    // The queue closes behind the ERROR: no FRAME can follow it.
    peer.send_last(ERROR, frame, &error(code, &text));
    format!("error {code}: {text}")
}

/// READINGS: the clock owner's answer to the awaited frame, or another peer's values for
/// the next frame.
fn on_readings(rt: &Runtime, peer: &Peer, frame: u32, payload: &[u8]) -> Handled {
    let hub = &rt.vr.peers;
    let r = parse_readings(payload).map_err(|e| Leave::Refuse(E_BAD_PAYLOAD, format!("READINGS: {e}")))?;
    payload::check_readings(rt.vr.robot().model(), peer.roles, &r).map_err(|(code, text)| Leave::Refuse(code, text))?;
    let mut st = hub.lock();
    if st.clock != Some(peer.id) {
        st.pending.push(r);
        return Ok(());
    }
    match st.awaiting {
        Some((o, n)) if o == peer.id && n == frame => {
            st.lockstep = Some(r);
            st.awaiting = None;
            drop(st);
            hub.cv.notify_all();
            Ok(())
        }
        Some((_, n)) => Err(Leave::Refuse(E_BAD_FRAME, format!("READINGS for frame {frame}, expected frame {n}"))),
        None => {
            let last = st.last_frame;
            Err(Leave::Refuse(E_BAD_FRAME, format!("READINGS for frame {frame} while no frame awaits readings (last FRAME sent: {last})")))
        }
    }
}

/// IMAGE: the camera's picture from the next frame on.
fn on_image(rt: &Runtime, peer: &Peer, payload: &[u8]) -> Handled {
    if peer.roles & ROLE_CAMERA == 0 {
        return Err(Leave::Refuse(E_ROLE, "IMAGE without the camera role".into()));
    }
    let robot = rt.vr.robot();
    let (w, h) = (robot.camera().rgb.width, robot.camera().rgb.height);
    drop(robot);
    let rgb = payload::parse_image(payload, w, h).map_err(|e| Leave::Refuse(E_BAD_PAYLOAD, e))?;
    rt.vr.peers.lock().image = Some(rgb.to_vec());
    Ok(())
}

/// MIC: sound appended to the microphone queue.
fn on_mic(hub: &Hub, peer: &Peer, payload: &[u8]) -> Handled {
    if peer.roles & ROLE_MIC == 0 {
        return Err(Leave::Refuse(E_ROLE, "MIC without the mic role".into()));
    }
    payload::check_mic(payload).map_err(|e| Leave::Refuse(E_BAD_PAYLOAD, e))?;
    let mut st = hub.lock();
    if st.mic.len() + payload.len() > MIC_QUEUE_MAX {
        return Err(Leave::Refuse(E_OVERFLOW, format!("MIC: more than {MIC_QUEUE_MAX} bytes queued")));
    }
    st.mic.extend(payload.iter().copied());
    Ok(())
}

/// CLOCK: takes or gives up the clock, and answers with the peer's resulting state.
fn on_clock(hub: &Hub, peer: &Peer, payload: &[u8]) -> Handled {
    let flags = payload::parse_clock(payload).map_err(|e| Leave::Refuse(E_BAD_PAYLOAD, e))?;
    let mut st = hub.lock();
    if flags & FLAG_CLOCK != 0 {
        if st.clock.is_none() {
            st.clock = Some(peer.id);
        }
    } else if st.clock == Some(peer.id) {
        st.clock = None;
    }
    let owns = st.clock == Some(peer.id);
    let frame = st.last_frame;
    drop(st);
    hub.cv.notify_all();
    let mut o = Out::default();
    o.u32(if owns { FLAG_CLOCK } else { 0 });
    peer.send(CLOCK, frame, &o.0).map_err(Leave::Quit)
}
