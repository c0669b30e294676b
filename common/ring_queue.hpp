#pragma once
// A first-in first-out queue on one ring of slots that grows and never
// shrinks. Why not std::deque: libstdc++'s deque holds one element per node
// once an element is larger than 256 bytes (a Block, a LookAheadPiece), so
// every push allocated and every pop freed, for every block of a program
// (issue 17: decode + plan).
#include <algorithm>
#include <cstddef>
#include <iterator>
#include <memory>
#include <type_traits>
#include <utility>

namespace hil {

template <class T>
class RingQueue {
  template <class Q, class V>
  class Iter {
   public:
    using iterator_category = std::random_access_iterator_tag;
    using value_type = T;
    using difference_type = std::ptrdiff_t;
    using pointer = V*;
    using reference = V&;

    Iter() = default;
    Iter(Q* queue, std::size_t i) : queue_(queue), i_(i) {}
    // iterator to const_iterator, as in the std containers
    template <class Q2, class V2, class = std::enable_if_t<std::is_const_v<V> && !std::is_const_v<V2>>>
    Iter(const Iter<Q2, V2>& other) : queue_(other.queue_), i_(other.i_) {}  // NOLINT: implicit on purpose
    reference operator*() const { return (*queue_)[i_]; }
    pointer operator->() const { return &(*queue_)[i_]; }
    reference operator[](difference_type n) const { return (*queue_)[i_ + static_cast<std::size_t>(n)]; }
    Iter& operator++() { return ++i_, *this; }
    Iter& operator--() { return --i_, *this; }
    Iter operator++(int) { return {queue_, i_++}; }
    Iter operator--(int) { return {queue_, i_--}; }
    Iter& operator+=(difference_type n) { return i_ += static_cast<std::size_t>(n), *this; }
    Iter& operator-=(difference_type n) { return i_ -= static_cast<std::size_t>(n), *this; }
    friend Iter operator+(Iter it, difference_type n) { return it += n; }
    friend Iter operator+(difference_type n, Iter it) { return it += n; }
    friend Iter operator-(Iter it, difference_type n) { return it -= n; }
    friend difference_type operator-(const Iter& a, const Iter& b) {
      return static_cast<difference_type>(a.i_) - static_cast<difference_type>(b.i_);
    }
    friend bool operator==(const Iter& a, const Iter& b) { return a.i_ == b.i_; }
    friend bool operator!=(const Iter& a, const Iter& b) { return a.i_ != b.i_; }
    friend bool operator<(const Iter& a, const Iter& b) { return a.i_ < b.i_; }
    friend bool operator>(const Iter& a, const Iter& b) { return a.i_ > b.i_; }
    friend bool operator<=(const Iter& a, const Iter& b) { return a.i_ <= b.i_; }
    friend bool operator>=(const Iter& a, const Iter& b) { return a.i_ >= b.i_; }
    std::size_t index() const { return i_; }

   private:
    template <class Q2, class V2>
    friend class Iter;
    Q* queue_ = nullptr;
    std::size_t i_ = 0;
  };

 public:
  using value_type = T;
  using size_type = std::size_t;
  using iterator = Iter<RingQueue, T>;
  using const_iterator = Iter<const RingQueue, const T>;

  RingQueue() = default;
  template <class InputIt>
  RingQueue(InputIt first, InputIt last) {
    for (; first != last; ++first) emplace_back(*first);
  }
  RingQueue(const RingQueue& other) {
    for (const T& x : other) push_back(x);
  }
  RingQueue(RingQueue&& other) noexcept { swap(other); }
  RingQueue& operator=(RingQueue other) noexcept {
    swap(other);
    return *this;
  }
  ~RingQueue() {
    clear();
    std::allocator<T>().deallocate(slots_, capacity_);
  }
  void swap(RingQueue& other) noexcept {
    std::swap(slots_, other.slots_);
    std::swap(capacity_, other.capacity_);
    std::swap(head_, other.head_);
    std::swap(size_, other.size_);
  }

  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  T& operator[](std::size_t i) { return slots_[(head_ + i) & (capacity_ - 1)]; }
  const T& operator[](std::size_t i) const { return slots_[(head_ + i) & (capacity_ - 1)]; }
  T& front() { return (*this)[0]; }
  const T& front() const { return (*this)[0]; }
  T& back() { return (*this)[size_ - 1]; }
  const T& back() const { return (*this)[size_ - 1]; }
  iterator begin() { return {this, 0}; }
  iterator end() { return {this, size_}; }
  const_iterator begin() const { return {this, 0}; }
  const_iterator end() const { return {this, size_}; }

  template <class... Args>
  T& emplace_back(Args&&... args) {
    if (size_ == capacity_) grow();
    T* slot = slots_ + ((head_ + size_) & (capacity_ - 1));
    ::new (static_cast<void*>(slot)) T(std::forward<Args>(args)...);
    ++size_;
    return *slot;
  }
  void push_back(const T& x) { emplace_back(x); }
  void push_back(T&& x) { emplace_back(std::move(x)); }
  void pop_front() {
    std::destroy_at(&front());
    head_ = (head_ + 1) & (capacity_ - 1);
    --size_;
  }
  void pop_back() {
    std::destroy_at(&back());
    --size_;
  }
  void clear() {
    while (!empty()) pop_back();
    head_ = 0;
  }
  // Before `pos`; moves the elements after it one slot on.
  iterator insert(const_iterator pos, T&& x) {
    const std::size_t i = pos.index();
    emplace_back(std::move(x));
    std::rotate(begin() + static_cast<std::ptrdiff_t>(i), end() - 1, end());
    return begin() + static_cast<std::ptrdiff_t>(i);
  }

 private:
  // Capacities are powers of two: a slot's index is a mask, not a division.
  void grow() {
    const std::size_t capacity = capacity_ == 0 ? 16 : 2 * capacity_;
    T* slots = std::allocator<T>().allocate(capacity);
    for (std::size_t i = 0; i < size_; ++i) {
      ::new (static_cast<void*>(slots + i)) T(std::move((*this)[i]));
      std::destroy_at(&(*this)[i]);
    }
    std::allocator<T>().deallocate(slots_, capacity_);
    slots_ = slots;
    capacity_ = capacity;
    head_ = 0;
  }

  T* slots_ = nullptr;
  std::size_t capacity_ = 0;
  std::size_t head_ = 0;
  std::size_t size_ = 0;
};

}  // namespace hil
