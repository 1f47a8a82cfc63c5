#pragma once
/// An array of trivially copyable values that grows with realloc. Large blocks are mapped on their own
/// (memory::returnLargeBlocksToSystem), and glibc grows a mapped block by moving its pages: the old block is not
/// held beside a copy of itself, as it is while a std::vector grows. That copy was the peak of the published Seep at
/// r = 1 cm, in the neighbour search, where a list outgrows its block part way through its assembly.
/// The elements a resize adds are left uninitialised: whoever resizes writes them next.

#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <new>
#include <type_traits>
#include <utility>

namespace poro {

template <class T> class ReallocVector {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                "realloc moves the bytes: only for values that are their bytes");
  static_assert(alignof(T) <= alignof(std::max_align_t), "realloc aligns to max_align_t only");

public:
  using value_type = T;

  ReallocVector() = default;
  ReallocVector(const ReallocVector& other) {
    resize(other.size_);
    if (size_ > 0) std::memcpy(data_, other.data_, size_ * sizeof(T));
  }
  ReallocVector(ReallocVector&& other) noexcept
      : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)),
        capacity_(std::exchange(other.capacity_, 0)) {}
  ReallocVector& operator=(ReallocVector other) noexcept {
    swap(other);
    return *this;
  }
  ~ReallocVector() { std::free(data_); }

  void swap(ReallocVector& other) noexcept {
    std::swap(data_, other.data_);
    std::swap(size_, other.size_);
    std::swap(capacity_, other.capacity_);
  }

  T* data() noexcept { return data_; }
  const T* data() const noexcept { return data_; }
  std::size_t size() const noexcept { return size_; }
  std::size_t capacity() const noexcept { return capacity_; }
  bool empty() const noexcept { return size_ == 0; }
  T* begin() noexcept { return data_; }
  T* end() noexcept { return data_ + size_; }
  const T* begin() const noexcept { return data_; }
  const T* end() const noexcept { return data_ + size_; }
  T& operator[](std::size_t i) noexcept { return data_[i]; }
  const T& operator[](std::size_t i) const noexcept { return data_[i]; }

  /// Keeps the block, like std::vector's.
  void clear() noexcept { size_ = 0; }
  /// Room for n values; the ones held are kept.
  void reserve(std::size_t n) {
    if (n <= capacity_) return;
    if (n > std::numeric_limits<std::size_t>::max() / sizeof(T)) throw std::bad_alloc();
    void* block = std::realloc(data_, n * sizeof(T));
    if (block == nullptr) throw std::bad_alloc(); // the old block is still held, and freed by the destructor
    data_ = static_cast<T*>(block);
    capacity_ = n;
  }
  /// n values: the ones held are kept, the ones added are uninitialised.
  void resize(std::size_t n) {
    reserve(n);
    size_ = n;
  }

private:
  T* data_ = nullptr;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

} // namespace poro
