// Typed element handles and per-element data, in the style of geometry-central: a Face can
// never be used where an Edge is meant, and data is looked up by handle, never by string.
#pragma once

#include <compare>
#include <cstdint>
#include <limits>
#include <vector>

namespace skein {

template <class Tag>
class Handle {
 public:
  static constexpr std::uint32_t kInvalid = std::numeric_limits<std::uint32_t>::max();
  constexpr Handle() = default;
  constexpr explicit Handle(std::uint32_t index) : index_(index) {}
  constexpr std::uint32_t index() const { return index_; }
  constexpr bool valid() const { return index_ != kInvalid; }
  constexpr auto operator<=>(const Handle&) const = default;

 private:
  std::uint32_t index_ = kInvalid;
};

struct VertexTag {};
struct HalfedgeTag {};
struct EdgeTag {};
struct FaceTag {};
using Vertex = Handle<VertexTag>;
using Halfedge = Handle<HalfedgeTag>;
using Edge = Handle<EdgeTag>;
using Face = Handle<FaceTag>;

// A contiguous range of handles [0, n), iterated as `for (Face f : mesh.faces())`.
template <class H>
class HandleRange {
 public:
  class iterator {
   public:
    constexpr explicit iterator(std::uint32_t i) : i_(i) {}
    constexpr H operator*() const { return H(i_); }
    constexpr iterator& operator++() {
      ++i_;
      return *this;
    }
    constexpr bool operator==(const iterator&) const = default;

   private:
    std::uint32_t i_;
  };
  constexpr HandleRange(std::uint32_t begin, std::uint32_t end) : begin_(begin), end_(end) {}
  constexpr iterator begin() const { return iterator(begin_); }
  constexpr iterator end() const { return iterator(end_); }
  constexpr std::uint32_t size() const { return end_ - begin_; }

 private:
  std::uint32_t begin_, end_;
};

// Data stored per element of one kind, indexed by that kind's handle only.
template <class H, class T>
class MeshData {
 public:
  MeshData() = default;
  explicit MeshData(std::size_t n, T initial = T{}) : values_(n, initial) {}
  T& operator[](H h) { return values_[h.index()]; }
  const T& operator[](H h) const { return values_[h.index()]; }
  std::size_t size() const { return values_.size(); }
  void resize(std::size_t n, T initial = T{}) { values_.resize(n, initial); }
  void reserve(std::size_t n) { values_.reserve(n); }
  void push_back(T value) { values_.push_back(std::move(value)); }
  const std::vector<T>& raw() const { return values_; }

 private:
  std::vector<T> values_;
};

template <class T>
using VertexData = MeshData<Vertex, T>;
template <class T>
using HalfedgeData = MeshData<Halfedge, T>;
template <class T>
using EdgeData = MeshData<Edge, T>;
template <class T>
using FaceData = MeshData<Face, T>;

}  // namespace skein
