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
typedef void (*_Hook)(::OReasonMessage*);
typedef void (*_Control)(::OControlMessage*);
typedef void (*_Ready)(::OReadyMessage*);
typedef void (*_Connect)(::OConnectMessage*);
typedef void (*_Notify)(::ONotifyMessage*);

/*
 * Names in the expansions below are qualified (::Self, ::Exit, ::OSystemEvent, ...)
 * and locals carry an openr_ prefix: the expansions land after the program's own
 * header, which may say `using namespace std` or declare globals of its own.
 *
 * Each definition also catches any C++ exception its user function lets escape and
 * hands it to openr_entry_exception (apsys.h), naming the member function that ran;
 * nothing unwinds out of an entry into the runtime.
 */
extern "C" void openr_entry_exception(const char* entry) __attribute__((noreturn));

#define OPENR_STUB_TRY      try {
#define OPENR_STUB_CATCH(name) \
    } catch (...) { ::openr_entry_exception(name); }

/* declarations (stubgen puts them inside an extern "C" block) */
#define StubFuncDeclare_Basic(n) \
    void _##n(::OReasonMessage*);

#define StubFuncDeclare_Subject(i) \
    void _Control##i(::OControlMessage*); \
    void _Ready##i(::OReadyMessage*);

#define StubFuncDeclare_Observer(j) \
    void _Connect##j(::OConnectMessage*); \
    void _Notify##j(::ONotifyMessage*);

/* Init / Start / Stop / Destroy (OObject::n calls the program's Do<n>) */
#define StubFuncDefine_Basic(n)                                              \
extern "C" void _##n(::OReasonMessage* openr_msg)                            \
{                                                                            \
    OPENR_STUB_TRY                                                           \
    ::Self.n(::OSystemEvent(openr_msg->reason, openr_msg->param,             \
                            openr_msg->paramSize));                          \
    OPENR_STUB_CATCH("Do" #n)                                                \
    ::Exit();                                                                \
}

/* Control: an observer asks subject i to add/remove it. No Exit() when the
   observer lives in this object (self connection: invoked directly). */
#define StubFuncDefine_Control(i, f)                                         \
extern "C" void _Control##i(::OControlMessage* openr_msg)                    \
{                                                                            \
    OPENR_STUB_TRY                                                           \
    ::OStatus openr_status = ::Self.f(::OControlEvent(i, openr_msg->observerID, \
                                      openr_msg->subName, openr_msg->command)); \
    ::Self.subject[i]->ControlHandler(*openr_msg, openr_status);             \
    OPENR_STUB_CATCH(#f)                                                     \
    if (openr_msg->observerID.oid != ::Self.subject[i]->GetID().oid) ::Exit(); \
}

#define StubFuncDefine_Control_nofunc(i)                                     \
extern "C" void _Control##i(::OControlMessage* openr_msg)                    \
{                                                                            \
    ::Self.subject[i]->ControlHandler(*openr_msg, ::oSUCCESS);               \
    if (openr_msg->observerID.oid != ::Self.subject[i]->GetID().oid) ::Exit(); \
}

/* Ready: library handler first, then the user function */
#define StubFuncDefine_Ready(i, f)                                           \
extern "C" void _Ready##i(::OReadyMessage* openr_msg)                        \
{                                                                            \
    OPENR_STUB_TRY                                                           \
    ::Self.subject[i]->ReadyHandler(*openr_msg);                             \
    ::Self.f(::OReadyEvent(i, openr_msg->observerID, openr_msg->command));   \
    OPENR_STUB_CATCH(#f)                                                     \
    ::Exit();                                                                \
}

#define StubFuncDefine_Ready_nofunc(i)                                       \
extern "C" void _Ready##i(::OReadyMessage* openr_msg)                        \
{                                                                            \
    ::Self.subject[i]->ReadyHandler(*openr_msg);                             \
    ::Exit();                                                                \
}

/* Connect: user function first (its status is passed on), then the handler */
#define StubFuncDefine_Connect(j, f)                                         \
extern "C" void _Connect##j(::OConnectMessage* openr_msg)                    \
{                                                                            \
    OPENR_STUB_TRY                                                           \
    ::OStatus openr_status =                                                 \
        ::Self.f(::OConnectEvent(j, openr_msg->subName, openr_msg->command)); \
    ::Self.observer[j]->ConnectHandler(*openr_msg, openr_status);            \
    OPENR_STUB_CATCH(#f)                                                     \
    ::Exit();                                                                \
}

#define StubFuncDefine_Connect_nofunc(j)                                     \
extern "C" void _Connect##j(::OConnectMessage* openr_msg)                    \
{                                                                            \
    ::Self.observer[j]->ConnectHandler(*openr_msg, ::oSUCCESS);              \
    ::Exit();                                                                \
}

/* Notify: the handler fills a local event, then the user function */
#define StubFuncDefine_Notify(j, f)                                          \
extern "C" void _Notify##j(::ONotifyMessage* openr_msg)                      \
{                                                                            \
    OPENR_STUB_TRY                                                           \
    ::ONotifyEvent openr_event;                                              \
    openr_event.SetIndex(j);                                                 \
    ::Self.observer[j]->NotifyHandler(*openr_msg, &openr_event);             \
    ::Self.f(openr_event);                                                   \
    OPENR_STUB_CATCH(#f)                                                     \
    ::Exit();                                                                \
}

#define StubFuncDefine_Notify_nofunc(j)                                      \
extern "C" void _Notify##j(::ONotifyMessage* openr_msg)                      \
{                                                                            \
    ::ONotifyEvent openr_event;                                              \
    openr_event.SetIndex(j);                                                 \
    ::Self.observer[j]->NotifyHandler(*openr_msg, &openr_event);             \
    ::Exit();                                                                \
}

#endif /* _stub_macro_h_DEFINED */
