/*
 * OPENR/OObject.h - base class of every core class (object-model 2.3).
 *
 * Including this header alone makes visible everything a core class
 * traditionally relies on: OSystemEvent and the objcomm events/messages,
 * OReasonMessage/OPowerStatusMessage, MCOOP.h, OSyslog.h and the C library
 * headers <stdio.h> <stdlib.h> <string.h> <ctype.h>.
 * Non-inline members are implemented by the runtime library.
 */
#ifndef _OObject_h_DEFINED
#define _OObject_h_DEFINED

#include <string.h>
#include <MCOOP.h>
#include <OPENR/OPENR.h>
#include <OPENR/OPENREvent.h>
#include <OPENR/OPENRMessages.h>
#include <OPENR/ObjcommMessages.h>
#include <OPENR/OSyslog.h>

class OObject {
public:
    OObject();
    virtual ~OObject();

    void Init(const OSystemEvent& event);
    void Start(const OSystemEvent& event);
    void Stop(const OSystemEvent& event);
    void Destroy(const OSystemEvent& event);

    virtual OStatus DoInit(const OSystemEvent& event);
    virtual OStatus DoStart(const OSystemEvent& event);
    virtual OStatus DoStop(const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);

protected:
    OStatus RegisterServiceEntry(const OServiceEntry& entry, const char* name);

    OID myOID_;

private:
    OObject(const OObject&);
    OObject& operator=(const OObject&);

    static OID objectManager_;
    static OID serviceManager_;
};

#endif /* _OObject_h_DEFINED */
