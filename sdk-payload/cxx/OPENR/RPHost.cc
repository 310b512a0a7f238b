//
// RPHost.cc: the OPEN-R calls Remote Processing OPEN-R host objects cannot make
// (remote-processing 4, IG4.3). They return oFAIL there and say so once each.
//
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "openr_host.h"

namespace {

const char* const unavailable[] = {
    "ControlPrimitive", "NewSoundVectorData", "DeleteSoundVectorData", "NewCdtVectorData",
    "DeleteCdtVectorData", "SetCdtVectorData", "Shutdown", "ObservePowerStatus",
    "UnobservePowerStatus", "FindDesignData", "DeleteDesignData", "Fatal",
};
const int numUnavailable = sizeof(unavailable) / sizeof(unavailable[0]);
int reported[sizeof(unavailable) / sizeof(unavailable[0])];

bool rpHost()
{
    const char* v = getenv("OPENR_RP_HOST");
    return v != 0 && strcmp(v, "1") == 0;
}

}  // namespace

extern "C" int openr_rp_unavailable(const char* function)
{
    if (!rpHost()) return 0;
    for (int i = 0; i < numUnavailable; i++) {
        if (strcmp(function, unavailable[i]) != 0) continue;
        if (__sync_bool_compare_and_swap(&reported[i], 0, 1)) {
            fprintf(stderr, "OPENR::%s: not available to Remote Processing OPEN-R host objects; returns oFAIL\n", function);
        }
        return 1;
    }
    return 0;
}
