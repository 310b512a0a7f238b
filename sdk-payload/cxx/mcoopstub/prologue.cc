// prologue.cc - the entry layer every object needs (object-model 3): Prologue, Return,
// Exit, and the message builders the runtime asks each object for (openr_host.h).
//
// Everything here is in one translation unit on purpose: every stub refers to Prologue
// (ENTRY_UNDEF, PrologueEntry) and to Exit or Return, so linking this member from
// libmcoopstub.a also brings in the exported openr_make_* glue the loader requires.
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cxxabi.h>
#include <exception>
#include <typeinfo>

#include <MCOOP.h>
#include <ObjectEntryTable.h>
#include <OPENR/OPENR.h>
#include <OPENR/OPENRMessages.h>
#include <apsys.h>

#include "openr_host.h"

#define OPENR_EXPORT __attribute__((visibility("default")))

extern "C" {

// The runtime dlopen()s the object, which already ran its static constructors: nothing
// is left to do before the first message.
OPENR_EXPORT void Prologue(InitInfo* info)
{
    (void)info;
    ExitFromPrologue();
}

OPENR_EXPORT void ExitFromPrologue(void)
{
}

// Ends the current method.  Replies to a pending call only if nothing answered it yet
// (OObject::Init and friends already replied with their OStatusMessage).
OPENR_EXPORT void Return(void* msg, size_t size)
{
    const openr_host_api* api = openr_host();
    if (api != 0) api->reply(msg, msg != 0 ? size : 0);
}

// Ends the current method without a reply; the runtime answers a call left unanswered.
OPENR_EXPORT void Exit(void)
{
}

// A C++ exception escaped an entry (apsys.h GEN_ENTRY, OPENR/stub_macro.h): say which
// object, which entry, which exception, then abort() so the runtime's crash report
// (backtrace, non-zero exit) follows, as for any other crash.  Called inside a handler.
void openr_entry_exception(const char* entry)
{
    const openr_host_api* api = openr_host();
    const char* object = api != 0 ? api->self_name() : "?";
    std::type_info* type = abi::__cxa_current_exception_type();
    int status = -1;
    char* demangled = type != 0 ? abi::__cxa_demangle(type->name(), 0, 0, &status) : 0;
    const char* type_name = demangled != 0 ? demangled : (type != 0 ? type->name() : "unknown type");
    const char* what = 0;
    try {
        throw;
    } catch (const std::exception& e) {
        what = e.what();
    } catch (...) {
    }
    fflush(stdout);
    if (what != 0) {
        fprintf(stderr, "error: object `%s`: uncaught C++ exception %s in %s: %s\n",
                object, type_name, entry, what);
    } else {
        fprintf(stderr, "error: object `%s`: uncaught C++ exception %s in %s\n",
                object, type_name, entry);
    }
    fflush(stderr);
    abort();
}

/* ---- builders for the runtime ---- */

OPENR_EXPORT size_t openr_make_reason_message(unsigned int reason, void* buf, size_t cap)
{
    if (buf == 0 || cap < sizeof(OReasonMessage)) return 0;
    OReasonMessage m(reason);
    // Parameters of the hook (inferred, object-model 2.1): BOOT carries the Memory Stick
    // status, SHUTDOWN whether the battery had enough charge.
    if (reason == oreasonBOOT) {
        OBootParam p(omemorystickWRITABLE);
        m = OReasonMessage(reason, &p, sizeof(p));
    } else if (reason == oreasonSHUTDOWN) {
        OShutdownParam p(true);
        m = OReasonMessage(reason, &p, sizeof(p));
    }
    memcpy(buf, &m, sizeof(m));
    return sizeof(m);
}

OPENR_EXPORT size_t openr_make_connect_message(int command, void* subject_oid,
                                               unsigned int subject_selector,
                                               const char* sub_name, void* buf, size_t cap)
{
    if (buf == 0 || cap < sizeof(OConnectMessage)) return 0;
    OConnectMessage m((OConnectCmd)command);
    m.entry.Set(OID(subject_oid), subject_selector);
    if (sub_name != 0) {
        strncpy(m.subName, sub_name, sizeof(m.subName) - 1);
        m.subName[sizeof(m.subName) - 1] = '\0';
    }
    memcpy(buf, &m, sizeof(m));
    return sizeof(m);
}

OPENR_EXPORT unsigned int openr_read_status_message(const void* msg, size_t size)
{
    if (msg == 0 || size < sizeof(OStatusMessage)) return oFAIL;
    OStatusMessage m;
    memcpy(&m, msg, sizeof(m));
    return m.status;
}

OPENR_EXPORT size_t openr_make_power_status_message(const struct openr_power_state* s,
                                                    void* buf, size_t cap)
{
    if (s == 0 || buf == 0 || cap < sizeof(OPowerStatusMessage)) return 0;
    OPowerStatus ps((longword)s->robot_status, (word)s->battery_status,
                    (word)s->remaining_capacity, (word)s->temperature,
                    (word)s->fully_charged_capacity, (word)s->voltage, (sword)s->current,
                    (sbyte)s->time_dif, (byte)s->volume);
    OPowerStatusMessage m(ps);
    memcpy(buf, &m, sizeof(m));
    return sizeof(m);
}

} // extern "C"
