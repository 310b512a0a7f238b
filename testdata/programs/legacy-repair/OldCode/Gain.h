//
// Gain.h : saturating arithmetic for servo gains.
//
// The specializations for short are written without "template <>":
// gcc 3.3 accepted that.
//

#ifndef Gain_h_DEFINED
#define Gain_h_DEFINED

template <class T>
struct Range {
    static T Max() { return 100; }
};

struct Range<short> {
    static short Max() { return 32767; }
};

template <class T>
T Clip(T v)
{
    return (v > Range<T>::Max()) ? Range<T>::Max() : v;
}

short Clip<short>(short v);

#endif // Gain_h_DEFINED
