// A per-step array whose storage is not cleared when it grows: every element
// is written before it is read, so zero-filling a fresh block each step (as
// std::vector::resize does) would only cost time. For plain-data element
// types (trivially copyable and destructible aggregates): C++20 lets such
// objects begin their lifetime in storage from an allocation function.
#pragma once

#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>

namespace i2d::detail {

template <class T>
class ScratchArray {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T> &&
                      (std::is_aggregate_v<T> || std::is_arithmetic_v<T>),
                  "ScratchArray leaves its elements uninitialised: plain data only");

public:
    /// n elements with unspecified values; keeps the storage when it is large enough.
    void resizeForOverwrite(std::size_t n) {
        if (n > capacity_) {
            data_.reset(static_cast<T*>(::operator new(n * sizeof(T))));
            capacity_ = n;
        }
        size_ = n;
    }
    /// n copies of `value` (what a vector's assign does).
    void assign(std::size_t n, const T& value) {
        resizeForOverwrite(n);
        for (std::size_t i = 0; i < n; ++i) data_.get()[i] = value;
    }
    /// Frees the storage.
    void release() {
        data_.reset();
        size_ = capacity_ = 0;
    }
    std::size_t size() const { return size_; }
    std::size_t capacity() const { return capacity_; }
    T& operator[](std::size_t i) { return data_.get()[i]; }
    const T& operator[](std::size_t i) const { return data_.get()[i]; }
    T* data() { return data_.get(); }
    const T* data() const { return data_.get(); }
    T& back() { return data_.get()[size_ - 1]; }
    const T& back() const { return data_.get()[size_ - 1]; }
    T* begin() { return data_.get(); }
    T* end() { return data_.get() + size_; }
    const T* begin() const { return data_.get(); }
    const T* end() const { return data_.get() + size_; }

private:
    struct Free {
        void operator()(T* p) const { ::operator delete(p); }
    };
    std::unique_ptr<T, Free> data_;
    std::size_t size_ = 0, capacity_ = 0;
};

}  // namespace i2d::detail
