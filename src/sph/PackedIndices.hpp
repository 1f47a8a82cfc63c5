#pragma once
/// The neighbour lists' storage of particle indices (NeighbourSearch.hpp).

#include "core/Memory.hpp"
#include "core/ReallocVector.hpp"
#include "core/Types.hpp"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iterator>

namespace poro {

/// Particle indices in 3 bytes each: a quarter less memory than 32-bit indices for the lists at H (38.5 MB of the
/// published Seep at r = 1 cm), read with one unaligned 4-byte load and a mask. Sets of more than 2^24 particles
/// take 4 bytes. One padding byte follows the last index, for its 4-byte load.
class PackedIndices {
public:
  using value_type = Index; ///< what the search's buffers hold before they are packed
  /// Bytes per index for a set of `particles`; empties the array.
  void setWidthFor(std::size_t particles) {
    clear();
    width_ = particles <= (std::size_t{1} << 24) ? 3u : 4u;
  }
  unsigned width() const { return width_; }
  std::uint32_t mask() const { return width_ == 3 ? 0xffffffu : 0xffffffffu; }
  /// Reads the indices in order.
  class Iterator {
  public:
    using iterator_category = std::input_iterator_tag;
    using value_type = Index;
    using difference_type = std::ptrdiff_t;
    using pointer = const Index*;
    using reference = Index;

    Iterator(const unsigned char* at, std::size_t width, std::uint32_t mask) : at_(at), width_(width), mask_(mask) {}
    Index operator*() const {
      std::uint32_t value;
      std::memcpy(&value, at_, sizeof value);
      return static_cast<Index>(value & mask_);
    }
    Iterator& operator++() {
      at_ += width_;
      return *this;
    }
    /// The iterator k indices further.
    Iterator operator+(std::size_t k) const { return {at_ + k * width_, width_, mask_}; }
    bool operator==(const Iterator& other) const { return at_ == other.at_; }
    bool operator!=(const Iterator& other) const { return at_ != other.at_; }

  private:
    const unsigned char* at_;
    std::size_t width_;
    std::uint32_t mask_;
  };
  /// The index at position k on.
  Iterator at(std::size_t k) const { return {bytes_.data() + k * width_, width_, mask()}; }
  std::size_t size() const { return size_; }
  std::size_t capacity() const { return bytes_.capacity() > 0 ? (bytes_.capacity() - 1) / width_ : 0; }
  void clear() { size_ = 0; }
  /// Room for n indices; the ones held are kept (ReallocVector).
  void reserve(std::size_t n) { bytes_.reserve(n * width_ + 1); }
  /// n indices: the ones held are kept, the ones added are unset.
  void resize(std::size_t n) {
    bytes_.resize(n * width_ + 1);
    size_ = n;
  }
  /// Writes the indices [first, last) from position `at` on.
  void store(std::size_t at, const Index* first, const Index* last) {
    if (first == last) return;
    unsigned char* out = bytes_.data() + at * width_;
    // Four bytes each (little-endian: the low ones first), the next index overwriting the fourth; the last one is
    // written byte by byte, so that another thread's run of indices after it is left alone.
    for (const Index* k = first; k + 1 < last; ++k, out += width_) {
      const std::uint32_t value = static_cast<std::uint32_t>(*k);
      std::memcpy(out, &value, sizeof value);
    }
    const std::uint32_t value = static_cast<std::uint32_t>(*(last - 1));
    for (unsigned byte = 0; byte < width_; ++byte) out[byte] = static_cast<unsigned char>(value >> (8 * byte));
  }
  /// Empties the array and gives its block back; the width stays.
  void release() {
    memory::freeAll(bytes_);
    size_ = 0;
  }

private:
  static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "indices are packed low bytes first");
  ReallocVector<unsigned char> bytes_; ///< grown in place: see ReallocVector
  std::size_t size_ = 0;
  unsigned width_ = 3;
};

} // namespace poro
