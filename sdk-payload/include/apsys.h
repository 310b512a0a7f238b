/*
 * apsys.h - low-level entry glue and raw console I/O.
 *
 * GEN_ENTRY(ENTRYNAME, FUNNAME), written at namespace scope and followed by
 * `;`, defines a C-linkage function `void ENTRYNAME(void* msg)` that calls
 * FUNNAME with `msg` converted to FUNNAME's parameter type. The runtime calls
 * entries through the ObjectEntryTable with one argument: the message pointer.
 * (On the robot this was an assembler trampoline; the host needs none.)
 * Usable from C and C++.
 */
#ifndef _apsys_h_DEFINED
#define _apsys_h_DEFINED

#ifdef __cplusplus

/* Call FUNNAME with the message pointer converted to its parameter type
   (OReasonMessage*, OControlMessage*, InitInfo*, void* ...). */
template <class R, class T>
inline void openr_gen_entry_call(R (*f)(T*), void* msg)
{
    f(static_cast<T*>(msg));
}

template <class R>
inline void openr_gen_entry_call(R (*f)(void*), void* msg)
{
    f(msg);
}

template <class R>
inline void openr_gen_entry_call(R (*f)(), void*)
{
    f();
}

/* Reports a C++ exception that escaped the entry `entry` of the calling object on
   stderr (type, what()) and ends the object the way a crash does (abort). Call it only
   from inside a catch handler. Implemented in libmcoopstub (prologue.cc). */
extern "C" void openr_entry_exception(const char* entry) __attribute__((noreturn));

/* Every name is qualified (::FUNNAME, ::openr_gen_entry_call): with `using namespace
   std` in a header, an unqualified `_Destroy` or `_Construct` would also find
   libstdc++'s std::_Destroy / std::_Construct and become an ambiguous overload set.
   No exception may unwind out of an entry into the runtime's message loop. */
#define GEN_ENTRY(ENTRYNAME, FUNNAME)                                        \
    extern "C" __attribute__((visibility("default"), used))                 \
    void ENTRYNAME(void* openr_entry_msg)                                    \
    {                                                                        \
        try {                                                                \
            ::openr_gen_entry_call(::FUNNAME, openr_entry_msg);              \
        } catch (...) {                                                      \
            ::openr_entry_exception(#FUNNAME);                               \
        }                                                                    \
    }                                                                        \
    extern "C" void ENTRYNAME(void* openr_entry_msg)

extern "C" {
#else

#define GEN_ENTRY(ENTRYNAME, FUNNAME)                                        \
    __attribute__((visibility("default"), used))                            \
    void ENTRYNAME(void* openr_entry_msg)                                    \
    {                                                                        \
        void (*openr_entry_fn)(void*) = (void (*)(void*))(FUNNAME);          \
        openr_entry_fn(openr_entry_msg);                                     \
    }                                                                        \
    void ENTRYNAME(void* openr_entry_msg)

#endif

int  apsysWrite(int fd, const void* buf, int size);
int  apsysRead(int fd, void* buf, int size);
void apsysPut(const char* str);
void apsysPutHex(unsigned int value);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* _apsys_h_DEFINED */
