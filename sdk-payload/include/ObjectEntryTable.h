/*
 * ObjectEntryTable.h - selector -> entry function table of an object
 * (object-model section 3). Each object defines `ObjectEntryTable`, terminated
 * by {UNDEF, ENTRY_UNDEF}; the runtime finds it in the dynamic symbol table.
 */
#ifndef _ObjectEntryTable_h_DEFINED
#define _ObjectEntryTable_h_DEFINED

#include <Types.h>

#ifdef __cplusplus

struct InitInfo;

struct ObjectEntry {
    Selector selector;
    Entry    entry;
};

extern ObjectEntry ObjectEntryTable[] __attribute__((visibility("default")));

extern "C" void Prologue(InitInfo* info);

#else

struct InitInfo;
typedef struct InitInfo InitInfo;

typedef struct ObjectEntry {
    Selector selector;
    Entry    entry;
} ObjectEntry;

extern ObjectEntry ObjectEntryTable[] __attribute__((visibility("default")));

void Prologue(InitInfo* info);

#endif

#ifdef __cplusplus
#define ENTRY_UNDEF ((Entry)::Prologue)
#else
#define ENTRY_UNDEF ((Entry)Prologue)
#endif

#endif /* _ObjectEntryTable_h_DEFINED */
