//
// MotionPlayer.cc
//
// Loads a key-frame motion file with libMTN, checks it with the C
// function mtn_checksum() and prints it.
//

#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "MotionPlayer.h"
#include "checksum.h"

static const char* const MOTION_FILE = "/MS/OPEN-R/MW/DATA/P/WAVE.MTN";

MotionPlayer::MotionPlayer()
{
}

OStatus
MotionPlayer::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;

    // The header must be 5 longwords + the name, whatever the host.
    if (sizeof(MTNHeader) != 5 * 4 + MTN_NAME_MAX) {
        OSYSLOG1((osyslogERROR, "MotionPlayer : sizeof(MTNHeader) is %d, not %d",
                  (int)sizeof(MTNHeader), 5 * 4 + MTN_NAME_MAX));
    }

    int result = motion.Load(MOTION_FILE);
    if (result != 0) {
        OSYSLOG1((osyslogERROR, "MotionPlayer : can't load %s (error %d)",
                  MOTION_FILE, result));
        return oFAIL;
    }
    return oSUCCESS;
}

OStatus
MotionPlayer::DoStart(const OSystemEvent& event)
{
    PrintMotion();

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
MotionPlayer::DoStop(const OSystemEvent& event)
{
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
MotionPlayer::DoDestroy(const OSystemEvent& event)
{
    motion.Unload();
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

void
MotionPlayer::PrintMotion()
{
    if (motion.GetNumKeyFrames() == 0) return;

    longword sum = mtn_checksum(motion.GetRecords(), motion.GetNumRecordWords());

    OSYSPRINT(("MotionPlayer : WAVE.MTN %s %d joints %d key frames checksum %s\n",
               motion.GetName(), motion.GetNumJoints(), motion.GetNumKeyFrames(),
               (sum == motion.GetChecksum()) ? "OK" : "NG"));

    for (int k = 0; k < motion.GetNumKeyFrames(); k++) {
        OSYSPRINT(("  key frame %d :", k));
        for (int j = 0; j < motion.GetNumJoints(); j++) {
            OSYSPRINT((" %4d", mtn_udeg(motion.GetAngle(k, j))));
        }
        OSYSPRINT(("   (%d steps)\n", (int)motion.GetSteps(k)));
    }

    //
    // Joint 0 from key frame 0 to key frame 1, as a motion agent would
    // send it to the effector (one value per 8 ms frame).
    //
    int numSteps = (int)motion.GetSteps(0);
    OSYSPRINT(("  joint 0 :"));
    for (int s = 0; s <= numSteps; s++) {
        slongword v = MTNInterpolate(motion.GetAngle(0, 0), motion.GetAngle(1, 0),
                                     s, numSteps);
        OSYSPRINT((" %d", mtn_udeg(v)));
    }
    OSYSPRINT(("\n"));
}
