#pragma once
// The generic parts of an on-disk cache of computed data (the FCM's cell rules, the
// harmonic method's bases): a 64-bit key hashed from the bit patterns of the inputs, a
// flat binary format opened by a versioned magic string, whole-file reads, and atomic
// writes (write_file_atomically), so an interrupted run leaves the old file or none. A
// file that does not read back completely (truncated, another version, another size) is
// ignored by its reader and recomputed.
#include <Eigen/Core>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace altfem {

/// A 64-bit hash over raw bytes; matrices hash their shape and then their entries. Eight
/// bytes at a time, each word FNV-1a's xor and multiply followed by a shift and xor (a
/// remainder of fewer bytes byte by byte, as FNV-1a), a multiply per word where FNV-1a
/// takes one per byte: a rebuild keys every embedded tetrahedron of a cut cell several times
/// (a sharpened pencil's tip cell holds thousands). Each step is a bijection of the
/// running value, so inputs of one length that differ in a single word never share a key.
class CacheKeyHasher {
public:
  void bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    std::size_t i = 0;
    for (; i + sizeof(std::uint64_t) <= size; i += sizeof(std::uint64_t)) {
      std::uint64_t word;
      std::memcpy(&word, p + i, sizeof word);
      value_ = (value_ ^ word) * prime;
      value_ ^= value_ >> 29;
    }
    for (; i < size; ++i) value_ = (value_ ^ p[i]) * prime;
  }
  template <typename T>
  void scalar(T x) {
    bytes(&x, sizeof x);
  }
  template <typename Matrix>
  void matrix(const Matrix& m) {
    scalar<std::int64_t>(m.rows());
    scalar<std::int64_t>(m.cols());
    bytes(m.data(), sizeof(typename Matrix::Scalar) * static_cast<std::size_t>(m.size()));
  }
  std::uint64_t value() const { return value_; }

private:
  static constexpr std::uint64_t prime = 1099511628211ull;  // FNV-1a's 64-bit prime and offset basis
  std::uint64_t value_ = 1469598103934665603ull;
};

/// Appends scalars (their bytes) and dense matrices (rows, cols, entries column-major).
class BinaryWriter {
public:
  /// The file starts with `magic` and a terminating NUL: name and format version.
  explicit BinaryWriter(std::string_view magic) : bytes_(magic) { bytes_.push_back('\0'); }
  template <typename T>
  void put(T x) {
    bytes_.append(reinterpret_cast<const char*>(&x), sizeof x);
  }
  template <typename Matrix>
  void matrix(const Matrix& m) {
    put<std::int64_t>(m.rows());
    put<std::int64_t>(m.cols());
    bytes_.append(reinterpret_cast<const char*>(m.data()),
                  sizeof(typename Matrix::Scalar) * static_cast<std::size_t>(m.size()));
  }
  const std::string& bytes() const { return bytes_; }

private:
  std::string bytes_;
};

/// Reads back what BinaryWriter wrote; every read fails (nullopt / false) past the end.
class BinaryReader {
public:
  /// Fails from the start (every read) unless `bytes` opens with `magic` and its NUL.
  BinaryReader(const std::string& bytes, std::string_view magic) : bytes_(bytes) {
    const bool opens =
        bytes.size() > magic.size() && bytes.compare(0, magic.size(), magic) == 0 && bytes[magic.size()] == '\0';
    position_ = opens ? magic.size() + 1 : bytes.size() + 1;
  }
  template <typename T>
  std::optional<T> get() {
    if (!has(sizeof(T))) return std::nullopt;
    T x;
    std::memcpy(&x, bytes_.data() + position_, sizeof x);
    position_ += sizeof x;
    return x;
  }
  /// A matrix of any shape (fixed dimensions must match); false when it does not fit.
  template <typename Matrix>
  bool matrix(Matrix& m) {
    const auto rows = get<std::int64_t>(), cols = get<std::int64_t>();
    if (!rows || !cols || *rows < 0 || *cols < 0) return false;
    const auto entries = static_cast<std::size_t>(*rows) * static_cast<std::size_t>(*cols);
    const std::size_t size = sizeof(typename Matrix::Scalar) * entries;
    if (entries > bytes_.size() || !has(size)) return false;
    if ((Matrix::RowsAtCompileTime != Eigen::Dynamic && Matrix::RowsAtCompileTime != *rows) ||
        (Matrix::ColsAtCompileTime != Eigen::Dynamic && Matrix::ColsAtCompileTime != *cols))
      return false;
    m.resize(*rows, *cols);
    std::memcpy(m.data(), bytes_.data() + position_, size);
    position_ += size;
    return true;
  }
  /// Whether everything was read, no more and no less.
  bool at_end() const { return position_ == bytes_.size(); }

private:
  bool has(std::size_t size) const { return position_ <= bytes_.size() && size <= bytes_.size() - position_; }
  const std::string& bytes_;
  std::size_t position_ = 0;
};

/// `directory`/<key as 16 hex digits><extension>.
std::filesystem::path cache_file_path(const std::filesystem::path& directory, std::uint64_t key,
                                      std::string_view extension);

/// The whole file, or nullopt when it does not exist or cannot be read.
std::optional<std::string> read_cache_file(const std::filesystem::path& path);

/// Creates the file's folder and writes `content` atomically (write_file_atomically).
/// Throws std::runtime_error naming the path when it cannot.
void write_cache_file(const std::filesystem::path& path, std::string_view content);

}  // namespace altfem
