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

#include <math.h>
#include <pthread.h>
#include <unistd.h>
#include <iostream>
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
    "float to int overflow",
    "FP invalid operation (0/0)",
    "sqrt of a negative number",
    "FP divide by zero",
    "FP overflow",
    "FP denormal operand",
    "misaligned access",
    "stack smash",
    "double free",
    "_exit(3)",
    "NULL pointer write in a thread of its own",
    "print floats (no fault)",
    "long at an address aligned to 4, not 8 (no fault on the robot)",
    "a function that falls off its end without a return (no fault on the robot)",
    "__builtin_unreachable() reached (code written for a newer gcc)",
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

// Floating point: on the robot's R4000 each of these is a CPU exception that
// stops the object; a PC quietly goes on with NaN, infinity or garbage.
// volatile keeps the compiler from doing the arithmetic at compile time.

static int
float_to_int_overflow()
{
    volatile double big = 1e20;
    return (int)big;
}

static double
fp_invalid()
{
    volatile double zero = 0.0;
    return zero / zero;
}

static double
sqrt_negative()
{
    volatile double minusOne = -1.0;
    return sqrt(minusOne);
}

static double
fp_divide_by_zero()
{
    volatile double zero = 0.0;
    return 1.0 / zero;
}

static double
fp_overflow()
{
    volatile double big = 1e300;
    return big * big;
}

static double
fp_denormal_operand()
{
    volatile double tiny = 1e-310;      // below DBL_MIN: a denormal
    return tiny * 2.0;
}

static int
misaligned_access()
{
    static int words[4];
    volatile int* p = (int*)((char*)words + 2);
    *p = 42;                    // address error (store) on the robot
    return *p;
}

// A long is a 4-byte word on the robot: at an address aligned to 4 (not to 8, as the PC's
// 8-byte long would want) the robot loads and stores it without a fault.
static long
word_aligned_long()
{
    static long longs[4];
    volatile long* p = (long*)((char*)longs + 4);
    *p = 7;
    return *p;
}

// No return statement on the path the call takes: gcc 3.3 returned whatever the
// register held, and the caller here ignores the value. (g++ 8 and later treat
// the end as unreachable and run into whatever code follows.)
static int __attribute__((noinline))
count_servos(int first, int last)
{
    if (first > last) return 0;
    printf("Crash : servos %d..%d\n", first, last);
}

// gcc 4.5 and later: the program promises the end is never reached, and breaks it.
static int __attribute__((noinline))
servo_gain(int servo)
{
    switch (servo) {
    case 0: return 10;
    case 1: return 20;
    }
    __builtin_unreachable();
}

static void
copy_name(char* to, const char* from)
{
    while ((*to++ = *from++) != 0) {
    }
}

// noinline: its own stack frame, with its return address right above name[].
static void __attribute__((noinline))
smash_stack()
{
    char name[8];
    copy_name(name, "a name much too long for the eight bytes of its buffer: it runs over "
                    "the saved registers and the return address of this function");
    printf("Crash : name %s\n", name);
}

static void
double_free()
{
    char* volatile p = (char*)malloc(32);  // volatile: the pair is not optimised away
    free(p);
    free(p);
}

static void*
thread_body(void*)
{
    null_pointer_write();
    return 0;
}

static void
fault_in_own_thread()
{
    pthread_t t;
    pthread_create(&t, 0, thread_body, 0);
    pthread_join(t, 0);
}

static void
print_floats()
{
    // NaN and infinity made without arithmetic (strtod), then printed both
    // ways: the C library must not trip the FP traps.  (A denormal would: any
    // FP instruction on one faults on the robot, printf's included.)
    double nan = strtod("nan", 0);
    double inf = strtod("-inf", 0);
    printf("Crash : printf %f %g %e %.3f\n", nan, inf, 1e-300, 3.14159);
    std::cout << "Crash : cout " << nan << " " << inf << " " << 1e-300 << " " << 2.5 << std::endl;
    printf("Crash : math %.4f %.4f %.4f\n", sin(1.0), exp(2.0), atan2(1.0, 2.0));
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
    case 7:
        printf("Crash : (int)1e20 = %d\n", float_to_int_overflow());
        break;
    case 8:
        printf("Crash : 0.0 / 0.0 = %f\n", fp_invalid());
        break;
    case 9:
        printf("Crash : sqrt(-1) = %f\n", sqrt_negative());
        break;
    case 10:
        printf("Crash : 1.0 / 0.0 = %f\n", fp_divide_by_zero());
        break;
    case 11:
        printf("Crash : 1e300 * 1e300 = %f\n", fp_overflow());
        break;
    case 12:
        printf("Crash : 1e-310 * 2 = %g\n", fp_denormal_operand());
        break;
    case 13:
        printf("Crash : misaligned word = %d\n", misaligned_access());
        break;
    case 14:
        smash_stack();
        break;
    case 15:
        double_free();
        break;
    case 16:
        printf("Crash : this line has no newline yet...");
        _exit(3);
        break;
    case 17:
        fault_in_own_thread();
        break;
    case 18:
        print_floats();
        break;
    case 19:
        printf("Crash : word-aligned long = %ld\n", word_aligned_long());
        break;
    case 20:
        count_servos(1, 3);
        printf("Crash : count_servos returned\n");
        break;
    case 21:
        printf("Crash : gain %d\n", servo_gain(2));
        break;
    }
}
