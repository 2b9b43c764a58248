// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The package's one hash map: open addressing with linear probing, keys of integer or
// pointer type spread by Fibonacci hashing (the multiplicative constant 2^64 / phi), key and
// value side by side in one slot so that a lookup costs one cache line. The repairs key it
// by face and vertex addresses (Address_table), the importer by edges (two indices in one
// 64-bit key). One key value is reserved to mark a free slot: null for pointers, all bits
// set for integers. Grows by doubling at half load; erase() shifts the following entries
// back, so the table never fills with tombstones.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_HASH_MAP_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_HASH_MAP_H

#include <CGAL/Delaunay_from_prediction/internal/toolbox/code_size.h>

#include <CGAL/assertions.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// The key of the directed edge a -> b between vertices of 32-bit indices, and of the edge
// {a, b} whatever its direction.
inline std::uint64_t directed_edge_key(std::uint32_t a, std::uint32_t b) { return (std::uint64_t(a) << 32) | b; }
inline std::uint64_t undirected_edge_key(std::uint32_t a, std::uint32_t b)
{
  return a < b ? directed_edge_key(a, b) : directed_edge_key(b, a);
}

template <class Key, class Value>
class Hash_map
{
  static_assert(std::is_pointer<Key>::value || std::is_unsigned<Key>::value,
                "Hash_map keys are pointers or unsigned integers");

public:
  // The key that marks a free slot; never a key of the map.
  static constexpr Key free_key()
  {
    if constexpr(std::is_pointer<Key>::value)
      return nullptr;
    else
      return (std::numeric_limits<Key>::max)();
  }

  explicit Hash_map(std::size_t initial_capacity = 64) { resize(round_up(initial_capacity)); }

  // Inserts `key` with `value` if absent; returns a pointer to the stored value and whether
  // it was inserted. Out of line: called from many places, where a call costs little next to
  // the probe's cache miss (code_size.h).
  CGAL_DFP_OUT_OF_LINE std::pair<Value*, bool> insert(Key key, const Value& value)
  {
    CGAL_precondition(key != free_key());
    if(2 * (size_ + 1) > slots_.size())
      resize(2 * slots_.size());
    std::size_t i = home(key);
    for(; slots_[i].key != free_key(); i = (i + 1) & mask_)
      if(slots_[i].key == key)
        return {&slots_[i].value, false};
    slots_[i].key = key;
    slots_[i].value = value;
    ++size_;
    return {&slots_[i].value, true};
  }

  Value* find(Key key) { return const_cast<Value*>(static_cast<const Hash_map&>(*this).find(key)); }
  const Value* find(Key key) const
  {
    for(std::size_t i = home(key); slots_[i].key != free_key(); i = (i + 1) & mask_)
      if(slots_[i].key == key)
        return &slots_[i].value;
    return nullptr;
  }

  bool contains(Key key) const { return find(key) != nullptr; }

  // Removes `key` if present and returns true with its value in `value`.
  bool take(Key key, Value& value)
  {
    if(size_ == 0)
      return false;
    std::size_t i = home(key);
    for(; slots_[i].key != key; i = (i + 1) & mask_)
      if(slots_[i].key == free_key())
        return false;
    value = slots_[i].value;
    // Backward shift: each following entry moves into the hole unless its home lies
    // cyclically in (hole, entry].
    for(std::size_t j = i;;) {
      j = (j + 1) & mask_;
      if(slots_[j].key == free_key())
        break;
      const std::size_t k = home(slots_[j].key);
      const bool stays = (i <= j) ? (i < k && k <= j) : (i < k || k <= j);
      if(!stays) {
        slots_[i] = slots_[j];
        i = j;
      }
    }
    slots_[i].key = free_key();
    --size_;
    return true;
  }

  // Makes room for `count` keys in all without growing (each growth rehashes every key).
  void reserve(std::size_t count)
  {
    std::size_t capacity = slots_.size();
    while(2 * count > capacity)
      capacity *= 2;
    if(capacity > slots_.size())
      resize(capacity);
  }

  std::size_t size() const { return size_; }

  void clear()
  {
    for(Slot& s : slots_)
      s.key = free_key();
    size_ = 0;
  }

  template <class Visit> // visit(key, value)
  void for_each(Visit visit) const
  {
    for(const Slot& s : slots_)
      if(s.key != free_key())
        visit(s.key, s.value);
  }

private:
  struct Slot
  {
    Key key;
    Value value;
  };

  static std::size_t round_up(std::size_t capacity)
  {
    std::size_t c = 2;
    while(c < capacity)
      c *= 2;
    return c;
  }
  static std::uint64_t bits(Key key)
  {
    if constexpr(std::is_pointer<Key>::value)
      return std::uint64_t(reinterpret_cast<std::uintptr_t>(key));
    else
      return std::uint64_t(key);
  }
  std::size_t home(Key key) const { return std::size_t((bits(key) * 0x9E3779B97F4A7C15ull) >> shift_); }

  void resize(std::size_t capacity)
  {
    std::vector<Slot> old(capacity, Slot{free_key(), Value()});
    old.swap(slots_);
    mask_ = capacity - 1;
    shift_ = 64;
    for(std::size_t c = capacity; c > 1; c >>= 1)
      --shift_;
    size_ = 0;
    for(const Slot& s : old)
      if(s.key != free_key())
        insert(s.key, s.value);
  }

  std::vector<Slot> slots_;
  std::size_t mask_ = 0, size_ = 0;
  int shift_ = 64;
};

// The repairs' sets and maps of face and vertex objects, keyed by address. Sets and flags
// take std::size_t values too: a slot is 16 bytes with a char as well, and each value type
// is a table more that every program compiles (code_size.h).
template <class Value>
using Address_table = Hash_map<const void*, Value>;

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_HASH_MAP_H
