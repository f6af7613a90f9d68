// Binary archives of a model's state, for checkpoints of long runs (`brb cyclic
// --checkpoint`, `brb validate --checkpoint-dir`): a run of hours writes its state after
// converged steps and a later process takes it up from there, bit for bit as if it had
// never stopped.
//
// The two archives share one way to name a state's fields: a type lists its fields once, in
// a function that takes the archive and the object, and the writer passes a const object,
// the reader a mutable one:
//
//   template <class Archive, class Self>
//     requires io::state_of<Self, MortarState>
//   void state_fields(Archive& archive, Self& state) {
//     archive(state.damage_threshold, state.damage, state.dissipated_energy);
//   }
//
// (found by argument-dependent lookup; a class may declare it as a friend to reach its
// private members). Numbers are written as their bytes (doubles round-trip exactly; a
// checkpoint is read back on the machine that wrote it), containers with their sizes. The
// reader does not build a model: it fills one built from the same input, so every size it
// reads must match the one it fills, else it throws CheckpointMismatch naming the field's
// position: a checkpoint of another brace, refinement or program version is refused, never
// half applied to the wrong model.
#pragma once

#include <Eigen/Core>

#include <array>
#include <concepts>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace brb::io {

/// A checkpoint that does not fit the model it is read into (another brace, refinement,
/// protocol or program version), or is truncated.
class CheckpointMismatch : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Self is T or const T: the object a state_fields function archives.
template <class Self, class T>
concept state_of = std::same_as<std::remove_const_t<Self>, T>;

/// A list that grows with the run (the steps of a hysteresis, its cycles): the reader takes
/// whatever length was written. Every other list is part of the model and must keep its size.
template <class Vector> struct Growing { Vector& list; };
template <class Vector> Growing<Vector> growing(Vector& list) {
  return {list};
}

namespace detail {
template <class T> struct is_std_vector : std::false_type {};
template <class T, class A> struct is_std_vector<std::vector<T, A>> : std::true_type {};
template <class T> struct is_std_array : std::false_type {};
template <class T, std::size_t N> struct is_std_array<std::array<T, N>> : std::true_type {};
template <class T> struct is_optional : std::false_type {};
template <class T> struct is_optional<std::optional<T>> : std::true_type {};
template <class T> struct is_variant : std::false_type {};
template <class... T> struct is_variant<std::variant<T...>> : std::true_type {};
template <class T> struct is_pair : std::false_type {};
template <class A, class B> struct is_pair<std::pair<A, B>> : std::true_type {};
template <class T> struct is_growing : std::false_type {};
template <class V> struct is_growing<Growing<V>> : std::true_type {};

/// Numbers, booleans and enumerations: stored as their bytes.
template <class T>
concept plain_value = std::is_arithmetic_v<T> || std::is_enum_v<T>;

/// Eigen's dense matrices and vectors (fixed or dynamic size).
template <class T>
concept eigen_dense = std::derived_from<T, Eigen::PlainObjectBase<T>>;
} // namespace detail

class StateWriter {
public:
  template <class... T> void operator()(const T&... values) { (write(values), ...); }

  /// Everything written so far.
  const std::string& bytes() const { return bytes_; }

private:
  void raw(const void* data, std::size_t size) {
    bytes_.append(static_cast<const char*>(data), size);
  }
  void size(std::size_t count) {
    const auto value = static_cast<std::uint64_t>(count);
    raw(&value, sizeof value);
  }

  template <class T> void write(const T& value) {
    if constexpr (detail::plain_value<T>) {
      raw(&value, sizeof value);
    } else if constexpr (detail::eigen_dense<T>) {
      size(static_cast<std::size_t>(value.rows()));
      size(static_cast<std::size_t>(value.cols()));
      raw(value.data(), sizeof(typename T::Scalar) * static_cast<std::size_t>(value.size()));
    } else if constexpr (std::same_as<T, std::string>) {
      size(value.size());
      raw(value.data(), value.size());
    } else if constexpr (detail::is_growing<T>::value) {
      write(value.list);
    } else if constexpr (detail::is_std_vector<T>::value) {
      size(value.size());
      using Element = typename T::value_type;
      static_assert(!std::same_as<Element, bool>, "std::vector<bool> has no element references");
      if constexpr (detail::plain_value<Element>)
        raw(value.data(), sizeof(Element) * value.size());
      else
        for (const auto& element : value)
          write(element);
    } else if constexpr (detail::is_std_array<T>::value || std::is_array_v<T>) {
      for (const auto& element : value)
        write(element);
    } else if constexpr (detail::is_optional<T>::value) {
      write(value.has_value());
      if (value)
        write(*value);
    } else if constexpr (detail::is_variant<T>::value) {
      size(value.index());
      std::visit([this](const auto& alternative) { write(alternative); }, value);
    } else if constexpr (detail::is_pair<T>::value) {
      write(value.first);
      write(value.second);
    } else if constexpr (std::is_empty_v<T>) {
      // a stateless alternative (e.g. a linear law's State): nothing to store
    } else {
      state_fields(*this, value);
    }
  }

  std::string bytes_;
};

class StateReader {
public:
  /// `source` names the bytes' origin (the checkpoint file) in the messages.
  StateReader(std::string bytes, std::string source)
      : bytes_(std::move(bytes)), source_(std::move(source)) {}

  template <class... T> void operator()(T&&... values) { (read(values), ...); }

  std::size_t position() const { return position_; }
  bool at_end() const { return position_ == bytes_.size(); }
  std::size_t remaining() const { return bytes_.size() - position_; }
  const std::string& source() const { return source_; }

  /// Throws CheckpointMismatch: "<source>: <what> (at byte <position>)".
  [[noreturn]] void mismatch(const std::string& what) const {
    throw CheckpointMismatch(source_ + ": " + what + " (at byte " + std::to_string(position_) +
                             ")");
  }

private:
  void raw(void* data, std::size_t size) {
    if (size > bytes_.size() - position_)
      mismatch("the checkpoint ends early");
    std::memcpy(data, bytes_.data() + position_, size);
    position_ += size;
  }
  std::size_t size() {
    std::uint64_t value = 0;
    raw(&value, sizeof value);
    return static_cast<std::size_t>(value);
  }
  void expect_size(std::size_t expected, const char* what) {
    const std::size_t found = size();
    if (found != expected)
      mismatch(std::string(what) + " of " + std::to_string(found) +
               " entries where the model has " + std::to_string(expected) +
               ": a checkpoint of another model or program version");
  }

  template <class T> void read(T& value) {
    if constexpr (detail::plain_value<T>) {
      raw(&value, sizeof value);
    } else if constexpr (detail::eigen_dense<T>) {
      const std::size_t rows = size();
      const std::size_t cols = size();
      if (rows != static_cast<std::size_t>(value.rows()) ||
          cols != static_cast<std::size_t>(value.cols())) {
        // only an empty dynamic matrix (not set yet) takes the written size
        if (value.size() != 0 || T::RowsAtCompileTime != Eigen::Dynamic || rows > bytes_.size() ||
            cols > bytes_.size())
          mismatch("a " + std::to_string(rows) + " x " + std::to_string(cols) +
                   " matrix where the model has " + std::to_string(value.rows()) + " x " +
                   std::to_string(value.cols()) +
                   ": a checkpoint of another model or program version");
        value.resize(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
      }
      raw(value.data(), sizeof(typename T::Scalar) * static_cast<std::size_t>(value.size()));
    } else if constexpr (std::same_as<T, std::string>) {
      const std::size_t count = size();
      if (count > bytes_.size() - position_)
        mismatch("the checkpoint ends early");
      value.assign(bytes_.data() + position_, count);
      position_ += count;
    } else if constexpr (detail::is_growing<T>::value) {
      // any length the bytes can hold
      const std::size_t count = size();
      if (count > bytes_.size() - position_)
        mismatch("the checkpoint ends early");
      value.list.resize(count);
      read_elements(value.list);
    } else if constexpr (detail::is_std_vector<T>::value) {
      expect_size(value.size(), "a list");
      read_elements(value);
    } else if constexpr (detail::is_std_array<T>::value || std::is_array_v<T>) {
      for (auto& element : value)
        read(element);
    } else if constexpr (detail::is_optional<T>::value) {
      bool present = false;
      read(present);
      if (!present) {
        value.reset();
      } else {
        if (!value)
          value.emplace();
        read(*value);
      }
    } else if constexpr (detail::is_variant<T>::value) {
      expect_size(value.index(), "a law state of alternative");
      std::visit([this](auto& alternative) { read(alternative); }, value);
    } else if constexpr (detail::is_pair<T>::value) {
      read(value.first);
      read(value.second);
    } else if constexpr (std::is_empty_v<T>) {
    } else {
      state_fields(*this, value);
    }
  }

  template <class Vector> void read_elements(Vector& list) {
    using Element = typename Vector::value_type;
    if constexpr (detail::plain_value<Element>)
      raw(list.data(), sizeof(Element) * list.size());
    else
      for (auto& element : list)
        read(element);
  }

  std::string bytes_;
  std::string source_;
  std::size_t position_ = 0;
};

/// A short name of `text` (64-bit FNV-1a, 16 hex digits) for run keys: a checkpoint records
/// the fingerprint of its input files and settings, and is refused by a run whose differ.
inline std::string fingerprint(std::string_view text) {
  std::uint64_t hash = 14695981039346656037ULL;
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ULL;
  }
  static constexpr char kHex[] = "0123456789abcdef";
  std::string hex(16, '0');
  for (int k = 15; k >= 0; --k, hash >>= 4)
    hex[static_cast<std::size_t>(k)] = kHex[hash & 0xF];
  return hex;
}

/// The fingerprint of a file's bytes, for a run key: an edited brace or protocol file makes
/// the run start again instead of taking up a stale checkpoint. Throws io::InputError when
/// the file cannot be read.
std::string file_fingerprint(const std::filesystem::path& file);

} // namespace brb::io
