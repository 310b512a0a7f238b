// OObject.cc - base class of every core class (object-model 2.3).
#include <OPENR/OObject.h>

#include "openr_host.h"

OID OObject::objectManager_;
OID OObject::serviceManager_;

namespace {

// The hooks arrive as calls: answer with the status the DoXxx returned.
void replyStatus(OStatus status)
{
    OStatusMessage msg(status);
    const openr_host_api* api = openr_host();
    if (api != 0) api->reply(&msg, sizeof(msg));
}

} // namespace

OObject::OObject()
{
    WhoAmI(&myOID_);
}

OObject::~OObject()
{
}

void OObject::Init(const OSystemEvent& event)
{
    replyStatus(DoInit(event));
}

void OObject::Start(const OSystemEvent& event)
{
    replyStatus(DoStart(event));
}

void OObject::Stop(const OSystemEvent& event)
{
    replyStatus(DoStop(event));
}

void OObject::Destroy(const OSystemEvent& event)
{
    OStatus status = DoDestroy(event);
    const openr_host_api* api = openr_host();
    if (api != 0) api->unregister_services();
    replyStatus(status);
}

OStatus OObject::DoInit(const OSystemEvent&)
{
    return oSUCCESS;
}

OStatus OObject::DoStart(const OSystemEvent&)
{
    return oSUCCESS;
}

OStatus OObject::DoStop(const OSystemEvent&)
{
    return oSUCCESS;
}

OStatus OObject::DoDestroy(const OSystemEvent&)
{
    return oSUCCESS;
}

OStatus OObject::RegisterServiceEntry(const OServiceEntry& entry, const char* name)
{
    const openr_host_api* api = openr_host();
    if (api == 0 || name == 0 || name[0] == '\0' || strlen(name) > oserviceNAME_MAX) return oFAIL;
    switch (api->register_service(name, entry.GetOID().GetAddress(), entry.GetSelector())) {
    case 0:  return oSUCCESS;
    case 1:  return oALREADY_EXIST;
    default: return oFAIL;
    }
}
