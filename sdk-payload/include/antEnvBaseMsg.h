/*
 * antEnvBaseMsg.h - common header of every ANT message (network-api 1.3,
 * 1.5, 1.6): stack reference, continuation info and struct antEnvMsg.
 * Send/Call/Reply and antStackRef(const char*) are implemented by the
 * runtime library.
 */
#ifndef _antEnvBaseMsg_h_DEFINED
#define _antEnvBaseMsg_h_DEFINED

#include <antTypes.h>
#include <antModuleRef.h>
#include <TID.h>

#ifndef ANTENVMSG
#define ANTENVMSG void*
#endif

/* entry selectors of the IP stack object */
enum {
    Entry_antEnv_Initialize = 0,
    Entry_antEnv_HartBeat   = 1,
    Entry_antEnv_External   = 2,
    antEnv_numEntries       = 3
};

class MAV_Dispatcher;

class antStackRef {
public:
    antStackRef() : oid(), disp(0) {}
    antStackRef(const OID& o) : oid(o), disp(0) {}
    antStackRef(const MAV_Dispatcher* d) : oid(), disp((MAV_Dispatcher*)d) {}
    antStackRef(const char* name);   /* name-service lookup; runtime library */
    ~antStackRef() {}

    OID&            get_oid() { return oid; }
    MAV_Dispatcher* get_disp() { return disp; }
    bool            IsValid() { return oid.IsValid() || disp != 0; }

private:
    OID             oid;
    MAV_Dispatcher* disp;
};

enum antEnvMsgInvocation {
    ANTENVMSG_SEND = 0,
    ANTENVMSG_CALL = 1
};

/* where an asynchronous reply goes: (object, selector) */
class antEnvMsgContInfo : public TID {
public:
    antEnvMsgContInfo() : TID() {}
    antEnvMsgContInfo(const TID& t) : TID(t) {}
    antEnvMsgContInfo(OID target, uint32 selector) : TID(target, selector) {}

    OID    GetOID() { return mailer; }
    uint32 GetSelector() { return value; }
};

struct antEnvMsg {
    Selector            dstSelector;
    antModuleRef        dstModule;
    int32               dstOperation;
    OID                 sender;
    int32               msgSize;
    antEnvMsgInvocation invocationType;
    antEnvMsgContInfo   contInfo;
    void*               continuation;

    /* leaves everything uninitialised */
    antEnvMsg() {}
    /* copies only the destination (selector and module), as on the robot */
    antEnvMsg(const antEnvMsg& m) : dstSelector(m.dstSelector), dstModule(m.dstModule) {}
    antEnvMsg(int32 op, Selector sel = Entry_antEnv_External)
        : dstSelector(sel), dstModule(), dstOperation(op) {}
    antEnvMsg(antModuleRef module, int32 op, Selector sel = Entry_antEnv_External)
        : dstSelector(sel), dstModule(module), dstOperation(op) {}

    antEnvMsg& operator=(const antEnvMsg& m) {
        dstSelector = m.dstSelector;
        dstModule = m.dstModule;
        return *this;
    }

    /* asynchronous: the completed message is later sent to entry
       `selector` of object `sender` */
    antError Send(antStackRef target, const OID& sender, int32 selector, int msgSize);
    /* synchronous: blocks; the reply is copied back into this message */
    antError Call(antStackRef target, int msgSize);
    /* identity cast of an entry-point argument */
    static antEnvMsg* Receive(ANTENVMSG msg) { return (antEnvMsg*)msg; }

    int32    GetOperation() { return dstOperation; }
    OID&     GetSender() { return sender; }
    antError Reply();

private:
    static boolean myOIDValid;
    static OID     myOID;
};

#endif /* _antEnvBaseMsg_h_DEFINED */
