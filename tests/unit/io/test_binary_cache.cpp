// The generic cache file parts (shared/io/binary_cache.hpp): what BinaryWriter writes
// BinaryReader reads back bit for bit; another magic (version), a truncated file and a
// wrong fixed shape fail instead of reading garbage; the key follows every input byte.
#include "shared/io/binary_cache.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/unit/io/io_test_support.hpp"

namespace altfem {
namespace {

constexpr char magic[] = "altfem-test-cache-v1";

std::string sample_file(const Eigen::MatrixXd& matrix) {
  BinaryWriter out(magic);
  out.put<std::int32_t>(-7);
  out.matrix(matrix);
  out.put<double>(std::nextafter(1.0, 2.0));
  return out.bytes();
}

TEST(BinaryCache, ReadsBackWhatWasWrittenBitForBit) {
  const Eigen::MatrixXd matrix = Eigen::MatrixXd::Random(4, 3);
  const std::string bytes = sample_file(matrix);
  BinaryReader in(bytes, magic);
  EXPECT_EQ(in.get<std::int32_t>(), -7);
  Eigen::MatrixXd read;
  ASSERT_TRUE(in.matrix(read));
  EXPECT_EQ(read, matrix);
  EXPECT_EQ(in.get<double>(), std::nextafter(1.0, 2.0));
  EXPECT_TRUE(in.at_end());
  EXPECT_FALSE(in.get<std::int32_t>());  // past the end
}

TEST(BinaryCache, OtherVersionsTruncatedFilesAndWrongShapesFail) {
  const Eigen::MatrixXd matrix = Eigen::MatrixXd::Random(4, 3);
  const std::string bytes = sample_file(matrix);
  BinaryReader other(bytes, "altfem-test-cache-v2");
  EXPECT_FALSE(other.get<std::int32_t>());
  for (std::size_t size : {std::size_t{0}, sizeof magic, bytes.size() / 2, bytes.size() - 1}) {
    const std::string truncated = bytes.substr(0, size);
    BinaryReader in(truncated, magic);
    Eigen::MatrixXd read;
    const bool whole = in.get<std::int32_t>() && in.matrix(read) && in.get<double>() && in.at_end();
    EXPECT_FALSE(whole) << "truncated to " << size << " bytes";
  }
  BinaryReader fixed(bytes, magic);
  fixed.get<std::int32_t>();
  Eigen::Matrix<double, 3, 3> wrong_shape;
  EXPECT_FALSE(fixed.matrix(wrong_shape));
}

TEST(BinaryCache, KeyFollowsEveryInputAndFilesRoundTrip) {
  Eigen::MatrixXd matrix = Eigen::MatrixXd::Random(4, 3);
  const auto key = [&] {
    CacheKeyHasher hasher;
    hasher.matrix(matrix);
    return hasher.value();
  };
  const std::uint64_t first = key();
  EXPECT_EQ(key(), first);
  matrix(3, 2) = std::nextafter(matrix(3, 2), 2.0);
  const std::uint64_t last_bit = key();
  EXPECT_NE(last_bit, first);
  // A word's highest bit (a double's sign) and a trailing byte change the key too.
  matrix(0, 0) = -matrix(0, 0);
  EXPECT_NE(key(), last_bit);
  const auto with_byte = [&](unsigned char byte) {
    CacheKeyHasher hasher;
    hasher.matrix(matrix);
    hasher.scalar(byte);
    return hasher.value();
  };
  EXPECT_NE(with_byte(1), with_byte(2));

  const auto folder = test::fresh_output_directory() / "nested";
  const auto path = cache_file_path(folder, 0x1234abcdull, ".test");
  EXPECT_EQ(path.filename().string(), "000000001234abcd.test");
  EXPECT_FALSE(read_cache_file(path));
  write_cache_file(path, sample_file(matrix));  // creates the folder
  EXPECT_EQ(read_cache_file(path), sample_file(matrix));
}

}  // namespace
}  // namespace altfem
