// An immutable array that copies of a model, and bodies built alike, share:
// a pile of 10,000 equal boxes keeps one copy of their contact points, so
// the points stay in cache and a model costs little to copy (retuned()
// copies it). Reads as a const std::vector.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

namespace rigid_body_sim::core {

template <class T>
class SharedArray {
 public:
  SharedArray() = default;
  SharedArray(std::vector<T> values)  // NOLINT(google-explicit-constructor): filled like the vector it stands for
      : values_(values.empty() ? nullptr : std::make_shared<const std::vector<T>>(std::move(values))) {}

  const std::vector<T>& get() const { return values_ ? *values_ : none(); }
  operator const std::vector<T>&() const { return get(); }  // NOLINT(google-explicit-constructor)
  std::size_t size() const { return get().size(); }
  bool empty() const { return get().empty(); }
  const T& operator[](std::size_t i) const { return get()[i]; }
  const T& front() const { return get().front(); }
  const T* data() const { return get().data(); }
  typename std::vector<T>::const_iterator begin() const { return get().begin(); }
  typename std::vector<T>::const_iterator end() const { return get().end(); }
  /// Whether two arrays are one (shared), not merely equal.
  bool sameAs(const SharedArray& o) const { return values_ == o.values_; }

 private:
  static const std::vector<T>& none() {
    static const std::vector<T> nothing;
    return nothing;
  }
  std::shared_ptr<const std::vector<T>> values_;
};

}  // namespace rigid_body_sim::core
