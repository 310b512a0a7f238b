/*
 * OPENR/stub_macro.h - macros used by stubgen2 output (<Obj>Stub.h,
 * <Obj>Stub.cc) to declare and define the entry functions of an object
 * (object-model 1.2.3, 1.2.4, 2.8, 2.9).
 *
 * Every StubFuncDefine_* macro expands to a complete function definition
 * with C linkage that refers to the global core-class instance `Self`.
 */
#ifndef _stub_macro_h_DEFINED
#define _stub_macro_h_DEFINED

#include <OPENR/OSubject.h>
#include <OPENR/OObserver.h>
#include <OPENR/ObjcommMessages.h>
#include <OPENR/OPENREvent.h>
#include <MCOOP.h>

/* entry-function names */
#define _Hook(n)     _##n
#define _Control(n)  _Control##n
#define _Ready(n)    _Ready##n
#define _Connect(n)  _Connect##n
#define _Notify(n)   _Notify##n

/* entry-function pointer types (only the non-GNU stub branch uses them) */
typedef void (*_Hook)(OReasonMessage*);
typedef void (*_Control)(OControlMessage*);
typedef void (*_Ready)(OReadyMessage*);
typedef void (*_Connect)(OConnectMessage*);
typedef void (*_Notify)(ONotifyMessage*);

/* declarations (stubgen puts them inside an extern "C" block) */
#define StubFuncDeclare_Basic(n) \
    void _##n(OReasonMessage* msg);

#define StubFuncDeclare_Subject(i) \
    void _Control##i(OControlMessage* msg); \
    void _Ready##i(OReadyMessage* msg);

#define StubFuncDeclare_Observer(j) \
    void _Connect##j(OConnectMessage* msg); \
    void _Notify##j(ONotifyMessage* msg);

/* Init / Start / Stop / Destroy */
#define StubFuncDefine_Basic(n)                                              \
extern "C" void _##n(OReasonMessage* msg)                                    \
{                                                                            \
    Self.n(OSystemEvent(msg->reason, msg->param, msg->paramSize));           \
    Exit();                                                                  \
}

/* Control: an observer asks subject i to add/remove it. No Exit() when the
   observer lives in this object (self connection: invoked directly). */
#define StubFuncDefine_Control(i, f)                                         \
extern "C" void _Control##i(OControlMessage* msg)                            \
{                                                                            \
    OStatus status =                                                         \
        Self.f(OControlEvent(i, msg->observerID, msg->subName, msg->command)); \
    Self.subject[i]->ControlHandler(*msg, status);                           \
    if (msg->observerID.oid != Self.subject[i]->GetID().oid) Exit();         \
}

#define StubFuncDefine_Control_nofunc(i)                                     \
extern "C" void _Control##i(OControlMessage* msg)                            \
{                                                                            \
    Self.subject[i]->ControlHandler(*msg, oSUCCESS);                         \
    if (msg->observerID.oid != Self.subject[i]->GetID().oid) Exit();         \
}

/* Ready: library handler first, then the user function */
#define StubFuncDefine_Ready(i, f)                                           \
extern "C" void _Ready##i(OReadyMessage* msg)                                \
{                                                                            \
    Self.subject[i]->ReadyHandler(*msg);                                     \
    Self.f(OReadyEvent(i, msg->observerID, msg->command));                   \
    Exit();                                                                  \
}

#define StubFuncDefine_Ready_nofunc(i)                                       \
extern "C" void _Ready##i(OReadyMessage* msg)                                \
{                                                                            \
    Self.subject[i]->ReadyHandler(*msg);                                     \
    Exit();                                                                  \
}

/* Connect: user function first (its status is passed on), then the handler */
#define StubFuncDefine_Connect(j, f)                                         \
extern "C" void _Connect##j(OConnectMessage* msg)                            \
{                                                                            \
    OStatus status = Self.f(OConnectEvent(j, msg->subName, msg->command));   \
    Self.observer[j]->ConnectHandler(*msg, status);                          \
    Exit();                                                                  \
}

#define StubFuncDefine_Connect_nofunc(j)                                     \
extern "C" void _Connect##j(OConnectMessage* msg)                            \
{                                                                            \
    Self.observer[j]->ConnectHandler(*msg, oSUCCESS);                        \
    Exit();                                                                  \
}

/* Notify: the handler fills a local event, then the user function */
#define StubFuncDefine_Notify(j, f)                                          \
extern "C" void _Notify##j(ONotifyMessage* msg)                              \
{                                                                            \
    ONotifyEvent event;                                                      \
    event.SetIndex(j);                                                       \
    Self.observer[j]->NotifyHandler(*msg, &event);                           \
    Self.f(event);                                                           \
    Exit();                                                                  \
}

#define StubFuncDefine_Notify_nofunc(j)                                      \
extern "C" void _Notify##j(ONotifyMessage* msg)                              \
{                                                                            \
    ONotifyEvent event;                                                      \
    event.SetIndex(j);                                                       \
    Self.observer[j]->NotifyHandler(*msg, &event);                           \
    Exit();                                                                  \
}

#endif /* _stub_macro_h_DEFINED */
