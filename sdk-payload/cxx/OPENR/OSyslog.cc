// OSyslog.cc - osyslog/osysprint (object-model 4.2).
//
// The text is formatted into a 244-byte buffer (at most osyslogMAX_SIZE = 243
// characters survive), then written to the console as ONE message:
//   osyslogDEBUG_NO_NEWLINE  text as formatted
//   osyslogDEBUG             text + "\n"
//   any other priority       "[oid:XXXXXXXX,prio:N] text\n"
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include <MCOOP.h>
#include <OPENR/OSyslog.h>

#include "openr_host.h"

namespace {

OStatus vlog(OSyslogPriority priority, const char* fmt, va_list ap)
{
    char text[osyslogMAX_SIZE + 1];
    if (fmt == 0) return oINVALID_ARG;
    int n = vsnprintf(text, sizeof(text), fmt, ap);
    if (n < 0) return oFAIL;

    char out[osyslogMAX_SIZE + 64];
    size_t len;
    if (priority == osyslogDEBUG_NO_NEWLINE) {
        len = strlen(text);
        memcpy(out, text, len);
    } else if (priority == osyslogDEBUG) {
        len = strlen(text);
        memcpy(out, text, len);
        out[len++] = '\n';
    } else {
        OID self;
        WhoAmI(&self);
        unsigned int oid = (unsigned int)(unsigned long)self.GetAddress();
        int m = snprintf(out, sizeof(out), "[oid:%08x,prio:%d] %s\n", oid, (int)priority, text);
        len = m < 0 ? 0 : ((size_t)m < sizeof(out) ? (size_t)m : sizeof(out) - 1);
    }

    const openr_host_api* api = openr_host();
    if (api != 0) {
        api->console_write(out, len);
    } else {
        fwrite(out, 1, len, stdout);
        fflush(stdout);
    }
    return oSUCCESS;
}

} // namespace

OStatus osyslog(OSyslogPriority priority, const char* fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    OStatus st = vlog(priority, fmt, ap);
    va_end(ap);
    return st;
}

OStatus osysprint(const char* fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    OStatus st = vlog(osyslogDEBUG_NO_NEWLINE, fmt, ap);
    va_end(ap);
    return st;
}
