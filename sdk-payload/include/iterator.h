/*
 * iterator.h - pre-standard C++ header (gcc 3.3 "backward" header, legacy-code.md 1):
 * includes the standard header and declares its std:: names globally.
 */
#ifndef _OPENR_COMPAT_iterator_h
#define _OPENR_COMPAT_iterator_h

#include <iterator>
#include <iostream.h>

using std::input_iterator_tag;
using std::output_iterator_tag;
using std::forward_iterator_tag;
using std::bidirectional_iterator_tag;
using std::random_access_iterator_tag;
using std::iterator;
using std::iterator_traits;
using std::distance;
using std::advance;
using std::reverse_iterator;
using std::back_insert_iterator;
using std::back_inserter;
using std::front_insert_iterator;
using std::front_inserter;
using std::insert_iterator;
using std::inserter;
using std::istream_iterator;
using std::ostream_iterator;

#endif /* _OPENR_COMPAT_iterator_h */
