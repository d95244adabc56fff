// Many short lists in one array (internal to the engine's event search: the grid's cells and the
// queue's candidates of each ball). Every list, a shelf, has the same room; when one fills, the
// room of all is doubled. So no list allocates on its own, and each is read where it lies.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <vector>

namespace cue_sim
{
namespace physics
{
/// T must be trivially copyable; slots past a shelf's size are left unset and never read.
template <typename T>
class Shelves
{
  static_assert(std::is_trivially_copyable<T>::value, "items are moved by copying their bytes' worth");

public:
  /// `shelves` empty shelves with room for `room` items each.
  explicit Shelves(std::size_t room, std::size_t shelves = 0)
    : room_(room), capacity_(shelves), sizes_(shelves, 0), slots_(shelves > 0 ? new T[shelves * room] : nullptr)
  {
  }

  /// How many shelves there are.
  std::size_t count() const { return sizes_.size(); }
  /// Adds an empty shelf; returns its number.
  int add()
  {
    if (sizes_.size() == capacity_)
      relayout(std::max<std::size_t>(1, 2 * capacity_), room_);
    sizes_.push_back(0);
    return static_cast<int>(sizes_.size() - 1);
  }

  std::size_t size(int shelf) const { return sizes_[static_cast<std::size_t>(shelf)]; }
  T* begin(int shelf) { return &slots_[static_cast<std::size_t>(shelf) * room_]; }
  const T* begin(int shelf) const { return &slots_[static_cast<std::size_t>(shelf) * room_]; }
  const T* end(int shelf) const { return begin(shelf) + size(shelf); }
  T& at(int shelf, std::size_t i) { return begin(shelf)[i]; }
  const T& at(int shelf, std::size_t i) const { return begin(shelf)[i]; }

  void push(int shelf, const T& item)
  {
    if (size(shelf) == room_)
      relayout(capacity_, 2 * room_);
    at(shelf, sizes_[static_cast<std::size_t>(shelf)]++) = item;
  }
  /// Removes item i; the last takes its place.
  void erase(int shelf, std::size_t i) { at(shelf, i) = at(shelf, --sizes_[static_cast<std::size_t>(shelf)]); }
  void clear(int shelf) { sizes_[static_cast<std::size_t>(shelf)] = 0; }

private:
  /// Storage for `capacity` shelves of `room` items; every shelf keeps its number and items.
  void relayout(std::size_t capacity, std::size_t room)
  {
    std::unique_ptr<T[]> slots(new T[capacity * room]);
    for (std::size_t s = 0; s < sizes_.size(); ++s)
      std::copy_n(&slots_[s * room_], sizes_[s], &slots[s * room]);
    slots_ = std::move(slots);
    capacity_ = capacity;
    room_ = room;
  }

  std::size_t room_;
  std::size_t capacity_;  ///< shelves the storage has room for
  std::vector<std::uint32_t> sizes_;
  std::unique_ptr<T[]> slots_;
};

}  // namespace physics
}  // namespace cue_sim
