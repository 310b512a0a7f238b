//
// OldCode.cc
//
// One object that uses code written for the gcc 3.3 of the OPEN-R SDK.
// g++ 12 rejects each of these habits; the SDK's compiler repairs them in
// a private copy and says so in a note (the sources stay as they are):
//
//   RingBuffer.h   implicit typename, names from a dependent base class
//   Stats.cc       old for-scope
//   Registry.h     friend injection
//   Gain.h/.cc     explicit specialization without "template <>"
//   Tracker.h      a parameter name repeated in one declaration
//   Clock.cc       "int ::GetNowMSec();"
//   OldCode.cc     ios::nocreate
//   Pixels.c       casts used as lvalues (C, mipsel-linux-gcc)
//   Label.cc       C library functions without their headers
//   Cycles.cc      MIPS inline assembly (left out by the SDK's gcc plugin)
//
// Permissive.h/.cc holds habits that -fpermissive still accepts.
//

#include <iostream.h>
#include <fstream.h>
#include <OPENR/OSyslog.h>
#include <OPENR/core_macro.h>
#include "OldCode.h"
#include "RingBuffer.h"
#include "Tracker.h"
#include "Registry.h"
#include "Gain.h"
#include "Permissive.h"
#include "Pixels.h"

int FindFirst(const int* values, int num, int key);
int CountAbove(const int* values, int num, int limit);
int GetNowMSec();
std::string MakeLabel(const char* part, int value);
int LabelValue(const std::string& label);
unsigned int ReadCycles();

static const char* const CONFIG_FILE = "/MS/OPEN-R/MW/CONF/OLDCODE.CFG";

OldCode::OldCode() : numSamples(0)
{
}

OStatus
OldCode::DoInit(const OSystemEvent& event)
{
    NEW_ALL_SUBJECT_AND_OBSERVER;
    REGISTER_ALL_ENTRY;
    SET_ALL_READY_AND_NOTIFY_ENTRY;
    return oSUCCESS;
}

OStatus
OldCode::DoStart(const OSystemEvent& event)
{
    ReadConfig();

    PeakRing<int> ring(4);
    for (int s = 0; s < numSamples; s++) ring.Push(samples[s]);
    cout << "OldCode : ring newest " << ring.Newest() << " sum " << ring.Sum()
         << " peak " << ring.Peak() << " count " << ring.Count() << endl;
    cout << "OldCode : " << RingName() << " header " << RingBuffer<int>::File() << endl;

    cout << "OldCode : first 7 at " << FindFirst(samples, numSamples, 7)
         << ", first 99 at " << FindFirst(samples, numSamples, 99)
         << ", above 5: " << CountAbove(samples, numSamples, 5) << endl;

    Registry* a = new Registry;
    Registry* b = new Registry;
    cout << "OldCode : registry " << RegistryCount();
    delete a;
    cout << " -> " << RegistryCount() << endl;
    delete b;

    cout << "OldCode : clip " << Clip<int>(250) << " " << Clip<short>(-5)
         << " " << Clip<short>(1234) << " max " << Range<short>::Max() << endl;

    Tracker tracker(0.5);
    double pan, tilt;
    tracker.Track(3.0, -40.0, &pan, &tilt);
    tracker.Limit(10.0, &pan, &tilt);
    cout << "OldCode : track pan " << pan << " tilt " << tilt << endl;

    int t0 = GetNowMSec();
    int t1 = GetNowMSec();
    cout << "OldCode : clock " << ((t0 >= 0 && t1 >= t0) ? "ok" : "BROKEN") << endl;

    unsigned char row[8] = { 1, 2, 3, 4, 5, 6, 7, 8 };
    FillRow(row, 8, 2, 10);
    cout << "OldCode : row sum " << SumRow(row, 8) << endl;

    std::string label = MakeLabel("HEADPAN", 42);
    cout << "OldCode : label " << label << " value " << LabelValue(label) << endl;
    cout << "OldCode : cycle counter " << ReadCycles() << endl;

    Servo servo(3);
    Quadrupler<int> quad;
    cout << "OldCode : servo " << servo.Id() << " scaled " << servo.Scaled(21)
         << " four " << quad.Four(5) << " servos " << ServoCount() << endl;

    ENABLE_ALL_SUBJECT;
    ASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
OldCode::DoStop(const OSystemEvent& event)
{
    cout << "OldCode : stop" << endl;
    DISABLE_ALL_SUBJECT;
    DEASSERT_READY_TO_ALL_OBSERVER;
    return oSUCCESS;
}

OStatus
OldCode::DoDestroy(const OSystemEvent& event)
{
    DELETE_ALL_SUBJECT_AND_OBSERVER;
    return oSUCCESS;
}

//
// OLDCODE.CFG holds the samples, one per line. ios::nocreate: do not
// create the file if it is missing (pre-standard iostreams).
//
void
OldCode::ReadConfig()
{
    ifstream in(CONFIG_FILE, ios::in | ios::nocreate);
    if (!in) {
        cout << "OldCode : can't open " << CONFIG_FILE << endl;
        return;
    }
    int value;
    while (numSamples < 8 && in >> value) samples[numSamples++] = value;
    cout << "OldCode : " << numSamples << " samples" << endl;
}
