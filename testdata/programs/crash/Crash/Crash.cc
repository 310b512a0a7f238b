//
// Crash.cc
//
// Commits one CPU exception on purpose so that you can see what the
// system does with a crashing object (on the robot: the exception
// monitor writes /MS/OPEN-R/EMON.LOG).
//
// Note: like much AIBO code this file calls printf() and fopen()
// without including <stdio.h>; the OPEN-R headers make them visible.
//

#include <OPENR/OSyslog.h>
#include "Crash.h"

static const char* const CRASH_CFG = "/MS/OPEN-R/MW/CONF/CRASH.CFG";

static const char* const faultName[] = {
    "ask",
    "NULL pointer write",
    "integer divide by zero",
    "abort",
    "unusable coprocessor",
    "write to read-only shared memory",
    "endless recursion",
};
static const int NUM_FAULTS = sizeof(faultName) / sizeof(faultName[0]);

//
// The individual faults. Each one is kept in its own function so that
// the crash log shows a meaningful function name.
//

static void
null_pointer_write()
{
    // Both volatile: the compiler may neither assume the pointer is
    // NULL nor drop the store.
    volatile int* volatile p = 0;
    *p = 0x1234;                // TLB miss (store) on the robot, SIGSEGV on a PC
}

static int
divide_by_zero()
{
    volatile int zero = 0;
    volatile int x = 100;
    return x / zero;            // integer division by zero
}

static void
call_abort()
{
    abort();
}

static void
use_unusable_coprocessor()
{
    // Read the coprocessor 0 status register. User-mode objects may
    // not touch coprocessor 0: "coprocessor unusable" exception.
    asm("mfc0 $2, $12");
}

static void
write_readonly_shared_memory()
{
    MemoryRegionID memID;
    void*          base;

    sError error = NewSharedMemoryRegion(4096, MEMPROTINFO_R, &memID, &base);
    if (error != sSUCCESS) {
        printf("Crash : NewSharedMemoryRegion() FAILED %d\n", (int)error);
        return;
    }
    printf("Crash : read-only region at %p\n", base);
    *(volatile int*)base = 1;   // TLB modification exception on the robot
}

static int
recurse_forever(int depth)
{
    volatile char frame[512];
    frame[0] = (char)depth;
    return recurse_forever(depth + 1) + frame[0];
}

Crash::Crash()
{
}

OStatus
Crash::DoInit(const OSystemEvent& event)
{
    return oSUCCESS;
}

OStatus
Crash::DoStart(const OSystemEvent& event)
{
    int fault = ReadFaultNumber();

    if (fault == 0) {
        printf("Crash : select a fault\n");
        for (int i = 1; i < NUM_FAULTS; i++) {
            printf("  %d : %s\n", i, faultName[i]);
        }
        printf("> ");
        fflush(stdout);
        std::cin >> fault;
    }

    if (fault < 1 || fault >= NUM_FAULTS) {
        printf("Crash : no fault selected\n");
        return oSUCCESS;
    }

    CommitFault(fault);

    // Only reached if the fault did not stop the object.
    printf("Crash : survived fault %d\n", fault);
    return oSUCCESS;
}

OStatus
Crash::DoStop(const OSystemEvent& event)
{
    OSYSLOG1((osyslogINFO, "Crash::DoStop()"));
    return oSUCCESS;
}

OStatus
Crash::DoDestroy(const OSystemEvent& event)
{
    return oSUCCESS;
}

int
Crash::ReadFaultNumber()
{
    FILE* fp = fopen(CRASH_CFG, "r");
    if (fp == 0) {
        OSYSLOG1((osyslogWARNING, "Crash : can't open %s", CRASH_CFG));
        return -1;
    }

    int fault = -1;
    if (fscanf(fp, "%d", &fault) != 1) fault = -1;
    fclose(fp);
    return fault;
}

void
Crash::CommitFault(int fault)
{
    printf("Crash : fault %d (%s)\n", fault, faultName[fault]);
    fflush(stdout);

    switch (fault) {
    case 1:
        null_pointer_write();
        break;
    case 2:
        printf("Crash : 100 / 0 = %d\n", divide_by_zero());
        break;
    case 3:
        call_abort();
        break;
    case 4:
        use_unusable_coprocessor();
        break;
    case 5:
        write_readonly_shared_memory();
        break;
    case 6:
        printf("Crash : %d\n", recurse_forever(0));
        break;
    }
}
