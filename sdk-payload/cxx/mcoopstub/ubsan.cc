// ubsan.cc - the alignment trap of mipsel-linux-g++ (-fsanitize=alignment).
//
// The robot's MIPS CPU faults on a load or store that is not aligned to its size (an
// address error exception); x86 quietly does it.  gcc checks every such access and
// calls the handler below with the source position and the type.  The handler faults
// the object (SIGBUS, with a note for the runtime's crash report) when the robot would
// have: a word at most needs 4-byte alignment there (LP64's 8-byte long and pointers
// are 4-byte words on the robot), a double 8 (ldc1/sdc1).  Otherwise it returns and
// the access goes ahead -- except from the _abort handler, which gcc calls instead when
// the build says -fno-sanitize-recover: gcc assumes that one never returns, so it faults
// every access misaligned for the PC's type, saying the flag made it fatal.
//
// With the SDK root's gcc plugin (sdk-payload/plugin/openr-align.cc, the usual case) the
// code checks the robot's alignment itself and calls only the _abort handler, only for an
// access the robot would refuse (or, under -fno-sanitize-recover, the PC's type would);
// for `p->d` it names the double member, where gcc's own check names the whole struct.
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

namespace {

// gcc's (libsanitizer's) data layouts for the checks.
struct SourceLocation {
    const char*  file;
    unsigned int line;
    unsigned int column;
};

struct TypeDescriptor {
    unsigned short kind;    // 0 integer, 1 float, 0xffff other
    unsigned short info;    // float: its width in bits
    char           name[1];
};

struct TypeMismatchData {
    SourceLocation        loc;
    const TypeDescriptor* type;
    unsigned char         logAlignment;
    unsigned char         typeCheckKind;
};

const char* const checkKinds[] = {
    "load of", "store to", "reference binding to", "member access within",
    "member call on", "constructor call on", "downcast of", "downcast of",
    "upcast of", "cast to virtual base of",
};

// One note per object (each object links its own copy); the process ends after it.
char note[768];

unsigned long robotAlignment(const TypeDescriptor* type, unsigned long hostAlignment)
{
    // A double (the robot's long double is one too) is loaded with ldc1; one the PC's
    // type says is less aligned (packed, aligned(4)) was less aligned on the robot too.
    if (type->kind == 1 && type->info >= 64) return hostAlignment < 8 ? hostAlignment : 8;
    return hostAlignment < 4 ? hostAlignment : 4;
}

// Whether it faulted the object (queued SIGBUS, delivered before this returns).
bool check(const TypeMismatchData* data, unsigned long pointer, bool mayReturn)
{
    if (pointer == 0) return false;   // NULL is -fsanitize=null's business, not enabled
    unsigned long host = 1UL << data->logAlignment;
    unsigned long need = robotAlignment(data->type, host);
    bool robotFaults = (pointer & (need - 1)) != 0;
    if (!robotFaults && (mayReturn || (pointer & (host - 1)) == 0)) return false;
    unsigned int k = data->typeCheckKind;
    const char* kind = k < sizeof(checkKinds) / sizeof(checkKinds[0]) ? checkKinds[k] : "access to";
    if (robotFaults)
        snprintf(note, sizeof(note),
                 "%s address %#lx for type %s, which the robot's CPU needs %lu-byte aligned, at %s:%u:%u",
                 kind, pointer, data->type->name, need, data->loc.file, data->loc.line, data->loc.column);
    else
        snprintf(note, sizeof(note),
                 "%s address %#lx for type %s, which the PC wants %lu-byte aligned (the robot "
                 "would not fault; -fno-sanitize-recover made it fatal), at %s:%u:%u",
                 kind, pointer, data->type->name, host, data->loc.file, data->loc.line, data->loc.column);
    union sigval value;
    value.sival_ptr = note;
    pthread_sigqueue(pthread_self(), SIGBUS, value);
    return true;
}

} // namespace

extern "C" {

void __ubsan_handle_type_mismatch_v1(const TypeMismatchData* data, unsigned long pointer)
{
    check(data, pointer, true);
}

void __ubsan_handle_type_mismatch_v1_abort(const TypeMismatchData* data, unsigned long pointer)
{
    // Never return (gcc assumed so): the signal faults the object.
    if (!check(data, pointer, false)) abort();
    for (;;) pause();
}

// -fsanitize=unreachable is in the compiler's flags so that a function that flows off its
// end without a return returns, as with gcc 3.3. What is left for this handler: the
// program reached a __builtin_unreachable() of its own (or of a header's).
struct UnreachableData {
    SourceLocation loc;
};

void __ubsan_handle_builtin_unreachable(const UnreachableData* data)
{
    snprintf(note, sizeof(note), "reached __builtin_unreachable() at %s:%u:%u", data->loc.file, data->loc.line,
             data->loc.column);
    union sigval value;
    value.sival_ptr = note;
    pthread_sigqueue(pthread_self(), SIGILL, value);
    abort();
}

} // extern "C"
