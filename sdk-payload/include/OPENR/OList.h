/*
 * OPENR/OList.h - OList<T, MaxSize>: a list of at most MaxSize elements
 * (MaxSize 0 = unbounded). Header-only.
 *
 * Elements are kept in a growable ring buffer; an Iterator is a (list,
 * position) pair, position 0 = Begin(), GetSize() = End(). T must be default
 * constructible and assignable.
 */
#ifndef _OList_h_DEFINED
#define _OList_h_DEFINED

#include <new>
#include <OPENR/ODebug.h>
#include <OPENR/OTLStatus.h>
#include <Types.h>

template <class T, int MaxSize = 0>
class OList {
public:
    class Iterator {
    public:
        Iterator() : list_(0), index_(0) {}
        Iterator(OList* list, int index) : list_(list), index_(index) {}

        T& operator*() const { return list_->At(index_); }
        T* operator->() const { return &list_->At(index_); }

        Iterator operator++() { ++index_; return *this; }
        Iterator operator++(int) { Iterator old(*this); ++index_; return old; }
        Iterator operator--() { --index_; return *this; }
        Iterator operator--(int) { Iterator old(*this); --index_; return old; }

        bool operator==(const Iterator& it) const {
            return list_ == it.list_ && index_ == it.index_;
        }
        bool operator!=(const Iterator& it) const { return !(*this == it); }

        int Index() const { return index_; }

    private:
        OList* list_;
        int    index_;
    };

    OList() : elems_(0), capacity_(0), head_(0), size_(0) {}

    OList(const OList& other) : elems_(0), capacity_(0), head_(0), size_(0) {
        CopyFrom(other);
    }

    OList& operator=(const OList& other) {
        if (this != &other) {
            Clear();
            CopyFrom(other);
        }
        return *this;
    }

    ~OList() { delete[] elems_; }

    OTLStatus PushFront(const T& value) {
        OTLStatus st = Reserve(size_ + 1);
        if (st != otlSUCCESS) return st;
        head_ = (head_ + capacity_ - 1) % capacity_;
        elems_[head_] = value;
        ++size_;
        return otlSUCCESS;
    }

    OTLStatus PushBack(const T& value) {
        OTLStatus st = Reserve(size_ + 1);
        if (st != otlSUCCESS) return st;
        elems_[(head_ + size_) % capacity_] = value;
        ++size_;
        return otlSUCCESS;
    }

    OTLStatus PopFront() {
        if (size_ == 0) return otlUNDERFLOW;
        elems_[head_] = T();
        head_ = (head_ + 1) % capacity_;
        --size_;
        return otlSUCCESS;
    }

    OTLStatus PopBack() {
        if (size_ == 0) return otlUNDERFLOW;
        elems_[(head_ + size_ - 1) % capacity_] = T();
        --size_;
        return otlSUCCESS;
    }

    T&       Front() { return At(0); }
    const T& Front() const { return At(0); }
    T&       Back() { return At(size_ - 1); }
    const T& Back() const { return At(size_ - 1); }

    void Clear() {
        for (int i = 0; i < size_; i++) At(i) = T();
        head_ = 0;
        size_ = 0;
    }

    int  GetSize() const { return size_; }
    int  GetMaxSize() const { return MaxSize; }
    bool IsEmpty() const { return size_ == 0; }
    bool IsFull() const { return MaxSize > 0 && size_ >= MaxSize; }

    Iterator Begin() { return Iterator(this, 0); }
    Iterator End() { return Iterator(this, size_); }

    T&       At(int i) { return elems_[(head_ + i) % capacity_]; }
    const T& At(int i) const { return elems_[(head_ + i) % capacity_]; }

private:
    OTLStatus Reserve(int n) {
        if (MaxSize > 0 && n > MaxSize) return otlOVERFLOW;
        if (n <= capacity_) return otlSUCCESS;
        int cap = capacity_ ? capacity_ * 2 : 8;
        if (cap < n) cap = n;
        if (MaxSize > 0 && cap > MaxSize) cap = MaxSize;
        T* p = new (std::nothrow) T[cap];
        if (p == 0) return otlNOMEMORY;
        for (int i = 0; i < size_; i++) p[i] = At(i);
        delete[] elems_;
        elems_ = p;
        capacity_ = cap;
        head_ = 0;
        return otlSUCCESS;
    }

    void CopyFrom(const OList& other) {
        for (int i = 0; i < other.size_; i++) PushBack(other.At(i));
    }

    T*  elems_;
    int capacity_;
    int head_;
    int size_;
};

#endif /* _OList_h_DEFINED */
