/*
 * OPENR/ArrayStack.h - fixed-capacity stack in an array. Header-only.
 */
#ifndef _ArrayStack_h_DEFINED
#define _ArrayStack_h_DEFINED

#include <Types.h>

template <class T, int N>
class ArrayStack {
public:
    ArrayStack() : top_(0) {}

    bool Push(const T& v) {
        if (top_ >= N) return false;
        data_[top_++] = v;
        return true;
    }
    bool Pop(T* v) {
        if (top_ <= 0) return false;
        *v = data_[--top_];
        return true;
    }
    T&   Top() { return data_[top_ - 1]; }
    bool IsEmpty() const { return top_ == 0; }
    bool IsFull() const { return top_ >= N; }
    int  Size() const { return top_; }
    int  Capacity() const { return N; }
    void Clear() { top_ = 0; }

private:
    T   data_[N];
    int top_;
};

#endif /* _ArrayStack_h_DEFINED */
