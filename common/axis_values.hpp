#pragma once
// One value per machine axis (a position, a tangent), in machine axis
// order. Up to inline_capacity axes the values live in the object itself:
// every block's motion and path segment carries a few of these, and as
// std::vector they cost an allocation each, several per block (issue 17:
// decode + plan). More axes go to the heap, as a vector would.
#include <algorithm>
#include <cstddef>
#include <initializer_list>
#include <iterator>
#include <memory>
#include <vector>

namespace hil {

class AxisValues {
 public:
  static constexpr std::size_t inline_capacity = 8;

  AxisValues() = default;
  explicit AxisValues(std::size_t n, double value = 0) { assign(n, value); }
  AxisValues(std::initializer_list<double> values) { assign(values.begin(), values.end()); }
  // Implicit both ways: positions also come from and go to std::vector
  // (machine configuration, messages, tests).
  AxisValues(const std::vector<double>& values) { assign(values.begin(), values.end()); }  // NOLINT
  operator std::vector<double>() const { return {begin(), end()}; }                         // NOLINT
  AxisValues(const AxisValues& other) { copy(other); }
  AxisValues(AxisValues&& other) noexcept { take(other); }
  AxisValues& operator=(const AxisValues& other) {
    if (this != &other) copy(other);
    return *this;
  }
  AxisValues& operator=(AxisValues&& other) noexcept {
    if (this != &other) {
      heap_.reset();
      take(other);
    }
    return *this;
  }
  ~AxisValues() = default;

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  double* data() { return heap_ ? heap_.get() : inline_; }
  const double* data() const { return heap_ ? heap_.get() : inline_; }
  double* begin() { return data(); }
  double* end() { return data() + size_; }
  const double* begin() const { return data(); }
  const double* end() const { return data() + size_; }
  double& operator[](std::size_t i) { return data()[i]; }
  double operator[](std::size_t i) const { return data()[i]; }
  double& front() { return data()[0]; }
  double front() const { return data()[0]; }
  double& back() { return data()[size_ - 1]; }
  double back() const { return data()[size_ - 1]; }

  void clear() { size_ = 0; }
  void reserve(std::size_t n) {
    if (n <= capacity()) return;
    auto heap = std::make_unique<double[]>(n);
    std::copy(begin(), end(), heap.get());
    heap_ = std::move(heap);
    heap_capacity_ = n;
  }
  void resize(std::size_t n, double value = 0) {
    reserve(n);
    if (n > size_) std::fill(data() + size_, data() + n, value);
    size_ = n;
  }
  void assign(std::size_t n, double value) {
    size_ = 0;
    resize(n, value);
  }
  template <class It>
  void assign(It first, It last) {
    const auto n = static_cast<std::size_t>(std::distance(first, last));
    size_ = 0;
    reserve(n);
    std::copy(first, last, data());
    size_ = n;
  }
  void push_back(double value) {
    if (size_ == capacity()) reserve(2 * capacity());
    data()[size_++] = value;
  }

  friend bool operator==(const AxisValues& a, const AxisValues& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end());
  }
  friend bool operator!=(const AxisValues& a, const AxisValues& b) { return !(a == b); }

 private:
  std::size_t capacity() const { return heap_ ? heap_capacity_ : inline_capacity; }
  void copy(const AxisValues& other) {
    if (other.heap_ || heap_) return assign(other.begin(), other.end());
    copy_inline(other);
  }
  // All of the array: a copy of fixed length the compiler unrolls, where
  // one of size_ would be a loop or a call to memcpy.
  void copy_inline(const AxisValues& other) {
    for (std::size_t i = 0; i < inline_capacity; ++i) inline_[i] = other.inline_[i];
    size_ = other.size_;
  }
  // From a moved-from `other`, which is left empty.
  void take(AxisValues& other) {
    size_ = other.size_;
    if (other.heap_) {
      heap_ = std::move(other.heap_);
      heap_capacity_ = other.heap_capacity_;
    } else {
      copy_inline(other);
    }
    other.size_ = 0;
  }

  std::size_t size_ = 0;
  std::unique_ptr<double[]> heap_;
  std::size_t heap_capacity_ = 0;
  double inline_[inline_capacity] = {};
};

}  // namespace hil
