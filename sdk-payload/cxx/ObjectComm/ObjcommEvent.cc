// ObjcommEvent.cc - out-of-line members of the objcomm events and handles
// (object-model 2.4) and the debug printers.
#include <iostream>

#include <OPENR/ObjcommEvent.h>
#include <OPENR/OObserverInfo.h>
#include <OPENR/OMemoryLocator.h>

#include "objcomm_internal.h"

OReadyEvent::~OReadyEvent()
{
}

OConnectEvent::~OConnectEvent()
{
}

OControlEvent::~OControlEvent()
{
}

// One array per object, overwritten by the next call (as Sony's library did).
const void** ONotifyEvent::Data() const
{
    static const void* data[MAX_NUM_DATA];
    for (int i = 0; i < MAX_NUM_DATA; i++) data[i] = Data(i);
    return data;
}

const ObserverID& OObserverInfo::GetObserverID() const
{
    static const ObserverID invalid;
    return info_ != 0 ? info_->id : invalid;
}

std::ostream& operator<<(std::ostream& os, const OServiceEntry& entry)
{
    std::ios::fmtflags f = os.flags();
    os << "(oid 0x" << std::hex << (unsigned long)entry.GetOID().GetAddress()
       << ", selector " << std::dec << entry.GetSelector() << ")";
    os.flags(f);
    return os;
}

std::ostream& operator<<(std::ostream& os, const OMemoryLocator& locator)
{
    os << "(memID " << locator.MemID() << ", offset " << locator.Offset() << ", size "
       << locator.Size() << ")";
    return os;
}
