//! The `#[repr(C)]` mirrors of `openr::abi` against the C++ headers they copy: g++
//! measures the SDK's own structs (sizeof/offsetof) and the test compares field by field,
//! so a change to `ObjcommMessages.h` or `OPENRMessages.h` cannot silently break Rust
//! objects talking to C++ ones.
use std::mem::{offset_of, size_of};
use std::path::Path;
use std::process::Command;

use openr::abi::*;

const PROBE: &str = r#"
#include <stdio.h>
#include <stddef.h>
#include <OPENR/ObjcommMessages.h>
#include <OPENR/OPENRMessages.h>
#define S(t) printf(#t " %zu\n", sizeof(t));
#define O(t, f) printf(#t "." #f " %zu\n", offsetof(t, f));
int main() {
    S(OServiceEntry) S(OStatusMessage) O(OStatusMessage, status)
    S(OReasonMessage) O(OReasonMessage, reason) O(OReasonMessage, paramSize) O(OReasonMessage, param)
    S(OConnectMessage) O(OConnectMessage, command) O(OConnectMessage, entry) O(OConnectMessage, subName)
    S(OControlMessage) O(OControlMessage, command) O(OControlMessage, observerID) O(OControlMessage, d_skip)
    O(OControlMessage, d_min) O(OControlMessage, d_max) O(OControlMessage, subName)
    S(OControlReplyMessage) O(OControlReplyMessage, status) O(OControlReplyMessage, subjectID) O(OControlReplyMessage, memID)
    S(OReadyMessage) O(OReadyMessage, command) O(OReadyMessage, observerID) O(OReadyMessage, numOfData) O(OReadyMessage, rcRegion)
    S(TransferedData) O(TransferedData, memID) O(TransferedData, offset) O(TransferedData, size)
    S(ONotifyMessage) O(ONotifyMessage, subjectID) O(ONotifyMessage, numOfData) O(ONotifyMessage, numOfNotify) O(ONotifyMessage, data)
    printf("omsgCONNECT %u\nomsgCONTROL %u\nomsgCONTROL_REPLY %u\nomsgREADY_V22 %u\nomsgNOTIFY_V22 %u\nomsgOSTATUS %u\nomsgREASON %u\n",
           omsgCONNECT, omsgCONTROL, omsgCONTROL_REPLY, omsgREADY_V22, omsgNOTIFY_V22, omsgOSTATUS, omsgREASON);
    printf("MAX_NUM_DATA %d\nobjcommCMD_ADDOBSERVER_V22 %d\nobjcommCMD_ASSERT_READY %d\noFAIL %d\noREFUSED %d\n",
           MAX_NUM_DATA, objcommCMD_ADDOBSERVER_V22, objcommCMD_ASSERT_READY, oFAIL, oREFUSED);
    return 0;
}
"#;

fn rust_side() -> Vec<(&'static str, usize)> {
    vec![
        ("OServiceEntry", size_of::<OServiceEntry>()),
        ("OStatusMessage", size_of::<OStatusMessage>()),
        ("OStatusMessage.status", offset_of!(OStatusMessage, status)),
        ("OReasonMessage", size_of::<OReasonMessage>()),
        ("OReasonMessage.reason", offset_of!(OReasonMessage, reason)),
        ("OReasonMessage.paramSize", offset_of!(OReasonMessage, param_size)),
        ("OReasonMessage.param", offset_of!(OReasonMessage, param)),
        ("OConnectMessage", size_of::<OConnectMessage>()),
        ("OConnectMessage.command", offset_of!(OConnectMessage, command)),
        ("OConnectMessage.entry", offset_of!(OConnectMessage, entry)),
        ("OConnectMessage.subName", offset_of!(OConnectMessage, sub_name)),
        ("OControlMessage", size_of::<OControlMessage>()),
        ("OControlMessage.command", offset_of!(OControlMessage, command)),
        ("OControlMessage.observerID", offset_of!(OControlMessage, observer_id)),
        ("OControlMessage.d_skip", offset_of!(OControlMessage, d_skip)),
        ("OControlMessage.d_min", offset_of!(OControlMessage, d_min)),
        ("OControlMessage.d_max", offset_of!(OControlMessage, d_max)),
        ("OControlMessage.subName", offset_of!(OControlMessage, sub_name)),
        ("OControlReplyMessage", size_of::<OControlReplyMessage>()),
        ("OControlReplyMessage.status", offset_of!(OControlReplyMessage, status)),
        ("OControlReplyMessage.subjectID", offset_of!(OControlReplyMessage, subject_id)),
        ("OControlReplyMessage.memID", offset_of!(OControlReplyMessage, mem_id)),
        ("OReadyMessage", size_of::<OReadyMessage>()),
        ("OReadyMessage.command", offset_of!(OReadyMessage, command)),
        ("OReadyMessage.observerID", offset_of!(OReadyMessage, observer_id)),
        ("OReadyMessage.numOfData", offset_of!(OReadyMessage, num_of_data)),
        ("OReadyMessage.rcRegion", offset_of!(OReadyMessage, rc_region)),
        ("TransferedData", size_of::<TransferedData>()),
        ("TransferedData.memID", offset_of!(TransferedData, mem_id)),
        ("TransferedData.offset", offset_of!(TransferedData, offset)),
        ("TransferedData.size", offset_of!(TransferedData, size)),
        ("ONotifyMessage", size_of::<ONotifyMessage>()),
        ("ONotifyMessage.subjectID", offset_of!(ONotifyMessage, subject_id)),
        ("ONotifyMessage.numOfData", offset_of!(ONotifyMessage, num_of_data)),
        ("ONotifyMessage.numOfNotify", offset_of!(ONotifyMessage, num_of_notify)),
        ("ONotifyMessage.data", offset_of!(ONotifyMessage, data)),
        ("omsgCONNECT", OMSG_CONNECT as usize),
        ("omsgCONTROL", OMSG_CONTROL as usize),
        ("omsgCONTROL_REPLY", OMSG_CONTROL_REPLY as usize),
        ("omsgREADY_V22", OMSG_READY_V22 as usize),
        ("omsgNOTIFY_V22", OMSG_NOTIFY_V22 as usize),
        ("omsgOSTATUS", OMSG_OSTATUS as usize),
        ("omsgREASON", OMSG_REASON as usize),
        ("MAX_NUM_DATA", MAX_NUM_DATA),
        ("objcommCMD_ADDOBSERVER_V22", CMD_ADDOBSERVER_V22 as usize),
        ("objcommCMD_ASSERT_READY", CMD_ASSERT_READY as usize),
        ("oFAIL", O_FAIL as usize),
        ("oREFUSED", O_REFUSED as usize),
    ]
}

#[test]
fn message_layouts_match_what_gxx_gives_the_sdk_headers() {
    let include = Path::new(env!("CARGO_MANIFEST_DIR")).join("../sdk-payload/include");
    let tmp = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("openr-layout-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).unwrap();
    std::fs::write(tmp.join("probe.cc"), PROBE).unwrap();
    let cxx = std::env::var("CXX").unwrap_or_else(|_| "g++".into());
    let out = Command::new(&cxx)
        .arg(format!("-I{}", include.display()))
        .arg(format!("-I{}", include.join("R4000").display()))
        .args(["-o", "probe", "probe.cc"])
        .current_dir(&tmp)
        .output()
        .unwrap_or_else(|e| panic!("cannot run {cxx}: {e}"));
    assert!(out.status.success(), "compiling the probe failed:\n{}", String::from_utf8_lossy(&out.stderr));
    let run = Command::new(tmp.join("probe")).output().unwrap();
    let measured: Vec<(String, usize)> = String::from_utf8(run.stdout)
        .unwrap()
        .lines()
        .map(|l| {
            let (k, v) = l.rsplit_once(' ').unwrap();
            (k.to_string(), v.parse().unwrap())
        })
        .collect();
    let ours = rust_side();
    assert_eq!(measured.len(), ours.len());
    for ((name, cxx_value), (rust_name, rust_value)) in measured.iter().zip(&ours) {
        assert_eq!(name, rust_name);
        assert_eq!(*cxx_value, *rust_value, "{name}: C++ {cxx_value}, Rust {rust_value}");
    }
}
