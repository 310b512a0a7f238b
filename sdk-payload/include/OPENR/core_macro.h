/*
 * OPENR/core_macro.h - convenience macros for DoInit/DoStart/DoStop/
 * DoDestroy of a stubgen core class (object-model 2.9). Needs the stubgen
 * outputs "entry.h"/"def.h" next to the source and members
 * `OSubject* subject[numOfSubject]`, `OObserver* observer[numOfObserver]`.
 * Each macro is a brace block (or empty), so a trailing `;` is harmless.
 * Globals are qualified (::numOfSubject, ::Entry_Ready ...) and locals carry an
 * openr_ prefix, so the program's own names (`using namespace std`, a member
 * or global called `entry`) cannot capture them.
 */
#ifndef _core_macro_h_DEFINED
#define _core_macro_h_DEFINED

#include "entry.h"
#include <OPENR/OPENR.h>

#define NEW_ALL_SUBJECT_AND_OBSERVER                                         \
{                                                                            \
    for (int openr_i = 0; openr_i < ::numOfSubject; openr_i++)                 \
        subject[openr_i] = new ::OSubject();                                   \
    for (int openr_j = 0; openr_j < ::numOfObserver; openr_j++)                \
        observer[openr_j] = new ::OObserver();                                 \
}

#define REGISTER_ALL_ENTRY                                                   \
{                                                                            \
    for (int openr_i = 0; openr_i < ::numOfSubject; openr_i++)                 \
        RegisterServiceEntry(::OServiceEntry(myOID_, ::Entry_Control[openr_i]), \
                             ::subjectService[openr_i]);                     \
    for (int openr_j = 0; openr_j < ::numOfObserver; openr_j++)                \
        RegisterServiceEntry(::OServiceEntry(myOID_, ::Entry_Connect[openr_j]), \
                             ::observerService[openr_j]);                    \
}

#define SET_ALL_READY_AND_NOTIFY_ENTRY                                       \
{                                                                            \
    ::OServiceEntry openr_entry;                                             \
    for (int openr_i = 0; openr_i < ::numOfSubject; openr_i++) {               \
        openr_entry.Set(myOID_, ::Entry_Ready[openr_i]);                     \
        subject[openr_i]->SetReadyEntry(openr_entry);                        \
    }                                                                        \
    for (int openr_j = 0; openr_j < ::numOfObserver; openr_j++) {              \
        openr_entry.Set(myOID_, ::Entry_Notify[openr_j]);                    \
        observer[openr_j]->SetNotifyEntry(openr_entry);                      \
    }                                                                        \
}

#define ASSERT_READY_TO_ALL_OBSERVER                                         \
{                                                                            \
    for (int openr_j = 0; openr_j < ::numOfObserver; openr_j++)                \
        observer[openr_j]->AssertReady();                                    \
}

#define DEASSERT_READY_TO_ALL_OBSERVER                                       \
{                                                                            \
    for (int openr_j = 0; openr_j < ::numOfObserver; openr_j++)                \
        observer[openr_j]->DeassertReady();                                  \
}

#define ENABLE_ALL_SUBJECT

#define DISABLE_ALL_SUBJECT                                                  \
{                                                                            \
    for (int openr_i = 0; openr_i < ::numOfSubject; openr_i++)                 \
        subject[openr_i]->ClearBuffer();                                     \
}

#define DELETE_ALL_SUBJECT_AND_OBSERVER

/* legacy names */
#define ASSERT_TO_ALL_OBSERVER    ASSERT_READY_TO_ALL_OBSERVER
#define DEASSERT_TO_ALL_OBSERVER  DEASSERT_READY_TO_ALL_OBSERVER
#define NewComData                NEW_ALL_SUBJECT_AND_OBSERVER
#define DeleteComData             DELETE_ALL_SUBJECT_AND_OBSERVER
#define SetComData                REGISTER_ALL_ENTRY SET_ALL_READY_AND_NOTIFY_ENTRY

#endif /* _core_macro_h_DEFINED */
