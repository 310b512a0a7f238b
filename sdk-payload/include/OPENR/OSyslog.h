/*
 * OPENR/OSyslog.h - console output and system log (object-model 4.2).
 *
 *   OSYSPRINT(("fmt", ...))   always printed, text as formatted
 *   OSYSDEBUG(("fmt", ...))   only when OPENR_DEBUG is defined
 *   OSYSLOG1((prio, "fmt", ...)) .. OSYSLOG4  printed as
 *       "[oid:XXXXXXXX,prio:N] text\n" when OSYSLOG_SHOW >= 1..4
 */
#ifndef _OSyslog_h_DEFINED
#define _OSyslog_h_DEFINED

#include <Types.h>
#include <OPENR/OPENR.h>

typedef longword OSyslogPriority;
const OSyslogPriority osyslogERROR            = 1;
const OSyslogPriority osyslogWARNING          = 2;
const OSyslogPriority osyslogINFO             = 3;
const OSyslogPriority osyslogDEBUG            = 0xffffffff;
const OSyslogPriority osyslogDEBUG_NO_NEWLINE = 0xfffffffe;

const size_t osyslogMAX_SIZE = 243;

OStatus osyslog(OSyslogPriority priority, const char* fmt, ...)
    __attribute__((format(printf, 2, 3)));
OStatus osysprint(const char* fmt, ...)
    __attribute__((format(printf, 1, 2)));

/* qualified: a member or using-directive of the program cannot capture the call */
#define OSYSPRINT(x) (::osysprint x)

#ifdef OPENR_DEBUG
#define OSYSDEBUG(x) (::osysprint x)
#else
#define OSYSDEBUG(x)
#endif

#ifndef OSYSLOG_SHOW
#if defined(SYSMSGSHOW) && (SYSMSGSHOW > 0)
#define OSYSLOG_SHOW 4
#else
#define OSYSLOG_SHOW 1
#endif
#endif

#if OSYSLOG_SHOW >= 1
#define OSYSLOG1(x) (::osyslog x)
#else
#define OSYSLOG1(x)
#endif

#if OSYSLOG_SHOW >= 2
#define OSYSLOG2(x) (::osyslog x)
#else
#define OSYSLOG2(x)
#endif

#if OSYSLOG_SHOW >= 3
#define OSYSLOG3(x) (::osyslog x)
#else
#define OSYSLOG3(x)
#endif

#if OSYSLOG_SHOW >= 4
#define OSYSLOG4(x) (::osyslog x)
#else
#define OSYSLOG4(x)
#endif

#endif /* _OSyslog_h_DEFINED */
