// Values as bytes and back, for results handed between machines of one kind (a cluster's
// workers and its client run the same build): plain values byte for byte, vectors with their
// length. Reading checks every length against the bytes left, so bytes from elsewhere fail with
// an Error rather than read out of bounds.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/base/errors.h"

namespace tsk {

class ByteWriter {
 public:
  template <typename T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable<T>::value, "plain values only");
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  template <typename T>
  void put(const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable<T>::value, "vectors of plain values only");
    put(static_cast<std::uint64_t>(values.size()));
    if (!values.empty())
      bytes_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

class ByteReader {
 public:
  ByteReader(std::string_view bytes, const char* what) : bytes_(bytes), what_(what) {}
  template <typename T>
  void get(T& value) {
    static_assert(std::is_trivially_copyable<T>::value, "plain values only");
    need(sizeof value);
    std::memcpy(&value, bytes_.data() + at_, sizeof value);
    at_ += sizeof value;
  }
  template <typename T>
  void get(std::vector<T>& values) {
    std::uint64_t count = 0;
    get(count);
    if (count > (bytes_.size() - at_) / sizeof(T)) fail();
    values.resize(static_cast<std::size_t>(count));
    if (count == 0) return;
    std::memcpy(values.data(), bytes_.data() + at_, values.size() * sizeof(T));
    at_ += values.size() * sizeof(T);
  }
  // Reads a value and throws unless it is `expected`: the mark that begins bytes of one kind.
  template <typename T>
  void expect(const T& expected) {
    T value{};
    get(value);
    if (value != expected) fail();
  }
  // Throws unless every byte was read.
  void finish() const {
    if (at_ != bytes_.size()) fail();
  }

 private:
  void need(std::size_t size) const {
    if (size > bytes_.size() - at_) fail();
  }
  [[noreturn]] void fail() const {
    throw Error(std::string("these bytes are not ") + what_ + " of this build of Terrain Sketch");
  }
  std::string_view bytes_;  // another's, which outlives the reader
  const char* what_;
  std::size_t at_ = 0;
};

}  // namespace tsk
