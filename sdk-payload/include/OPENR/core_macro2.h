/*
 * OPENR/core_macro2.h - variant of core_macro.h for the remote-processing
 * port: REGISTER_ALL_ENTRY replaces the first dot-separated part of every
 * service name with the value of a variable `myname` (const char* or
 * std::string, supplied by the caller) and stores the last non-success
 * status in a variable `result` (OStatus, supplied by the caller).
 */
#ifndef _core_macro2_h_DEFINED
#define _core_macro2_h_DEFINED

#include <string>
#include <OPENR/core_macro.h>

inline ::std::string openr_core_macro2_rename(const ::std::string& newFirst,
                                             const char* service)
{
    ::std::string s(service);
    ::std::string::size_type dot = s.find('.');
    if (dot == ::std::string::npos) return newFirst;
    return newFirst + s.substr(dot);
}

#undef REGISTER_ALL_ENTRY
#define REGISTER_ALL_ENTRY                                                   \
{                                                                            \
    for (int openr_i = 0; openr_i < ::numOfSubject; openr_i++) {               \
        ::std::string openr_name =                                             \
            ::openr_core_macro2_rename(myname, ::subjectService[openr_i]);   \
        ::OStatus openr_st = RegisterServiceEntry(                             \
            ::OServiceEntry(myOID_, ::Entry_Control[openr_i]), openr_name.c_str()); \
        if (openr_st != ::oSUCCESS) result = openr_st;                         \
    }                                                                        \
    for (int openr_j = 0; openr_j < ::numOfObserver; openr_j++) {              \
        ::std::string openr_name =                                             \
            ::openr_core_macro2_rename(myname, ::observerService[openr_j]);  \
        ::OStatus openr_st = RegisterServiceEntry(                             \
            ::OServiceEntry(myOID_, ::Entry_Connect[openr_j]), openr_name.c_str()); \
        if (openr_st != ::oSUCCESS) result = openr_st;                         \
    }                                                                        \
}

#endif /* _core_macro2_h_DEFINED */
