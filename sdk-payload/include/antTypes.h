/*
 * antTypes.h - basic types of the OPEN-R networking toolkit (ANT)
 * (network-api 1.2, 2.5). The integer typedefs are identical to Types.h.
 */
#ifndef _antTypes_h_DEFINED
#define _antTypes_h_DEFINED

#include <OID.h>
#include <antIOStream.h>

typedef int            int32;
typedef unsigned int   uint32;
typedef short          int16;
typedef unsigned short uint16;
typedef unsigned char  byte;
typedef int            boolean;

#ifndef TRUE
#define TRUE  1
#endif
#ifndef FALSE
#define FALSE 0
#endif

typedef OID antObjectID;

enum antError {
    ANT_SUCCESS              = 0,
    ANT_FAIL                 = 1,
    ANT_NOMEMORY             = 2,
    ANT_INVALIDPTR           = 3,
    ANT_NO_STATE_TRANSITION  = 4,
    ANT_SDU_BADRANGE         = 5,
    ANT_SDU_NOMORE_DATACELL  = 6,
    ANT_SDU_NOOWNER          = 7,
    ANT_SDUPOOL_ALLOCATED    = 8,
    ANT_SDUPOOL_NOTASSIGNED  = 9,
    ANT_QUEUE_EMPTY          = 10,
    ANT_QUEUE_STATE          = 11,
    ANT_QUEUE_CLOSED         = 12,
    ANT_QUEUE_REJECTED       = 13,
    ANT_QUEUE_BLOCKED        = 14,
    ANT_INVALIDMODULEID      = 15,
    ANT_TMR_TYPE_INVALID     = 16,
    ANT_TMR_MAXNMBR_REACHED  = 17,
    ANT_NOMESSAGES           = 18,
    ANT_NAMING_ENTRY_EXISTS  = 19,
    ANT_NAMING_NO_SUCH_NAME  = 20,
    ANT_NAMING_NAME_INVALID  = 21,
    ANT_REGISTRY_DUPLICATE_KEY = 22,
    ANT_REGISTRY_NO_KEY      = 23,
    ANT_REGISTRY_WRONG_TYPE  = 24,
    ANT_REGISTRY_INVALID_KEY = 25,
    ANT_REGISTRY_INVALID_VALUE = 26,
    ANT_ENDPOINT_NOFACTORY   = 27,
    ANT_NOT_INITIALIZED      = 28,
    ANT_INITIALIZING         = 29
};

enum antNotification {
    ANT_SDUMEMORY_AVAILABLE = 1
};

/* name of an error ("UNKNOWN ANT ERROR" when out of range); runtime library */
const char* antErrorString(antError error);
std::ostream& operator<<(std::ostream& os, antError error);

#endif /* _antTypes_h_DEFINED */
