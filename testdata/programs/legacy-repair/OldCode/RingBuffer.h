//
// RingBuffer.h : the last N samples of a sensor, oldest overwritten first.
//
// Written for gcc 3.3: the dependent types below have no "typename"
// (implicit typename, an error since gcc 3.4), and SortedRing uses its
// base class's members unqualified (found by gcc 3.3, not by two-phase
// lookup).
//

#ifndef RingBuffer_h_DEFINED
#define RingBuffer_h_DEFINED

#include <vector.h>

template <class T>
struct RingTraits {
    typedef T                  value_type;
    typedef const T&           const_reference;
    typedef unsigned int       size_type;
    typedef vector<T>          storage_type;
};

template <class T>
class RingBuffer {
public:
    typedef RingTraits<T>::size_type size_type;

    RingBuffer(RingTraits<T>::size_type n) : count(0), head(0), data(n) {}

    void Push(RingTraits<T>::const_reference v) {
        data[head] = v;
        head = (head + 1) % data.size();
        if (count < data.size()) count++;
    }

    RingTraits<T>::value_type Newest() const {
        RingTraits<T>::size_type last = (head + data.size() - 1) % data.size();
        return data[last];
    }

    RingTraits<T>::value_type Sum() const {
        RingTraits<T>::value_type sum = 0;
        for (RingTraits<T>::storage_type::const_iterator it = data.begin();
             it != data.end(); ++it) {
            sum += *it;
        }
        return sum;
    }

    static const char* File() { return __FILE__; }

protected:
    RingTraits<T>::size_type    count;
    RingTraits<T>::size_type    head;
    RingTraits<T>::storage_type data;
};

// A string constant as a char* was fine in 2003; g++ warns about it.
inline char* RingName() { return "ring"; }

//
// A ring that also knows its largest sample.
//
template <class T>
class PeakRing : public RingBuffer<T> {
public:
    PeakRing(unsigned int n) : RingBuffer<T>(n) {}

    size_type Count() const { return count; }

    T Peak() const {
        T peak = data[0];
        for (size_type i = 1; i < count; i++) {
            if (data[i] > peak) peak = data[i];
        }
        return peak;
    }
};

#endif // RingBuffer_h_DEFINED
