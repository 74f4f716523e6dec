// The batch records' SHA-256 against the FIPS 180-4 example vectors and against sha256sum.
#include "sha256.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "support/run_cli.h"

namespace meshquilt::cli {
namespace {

TEST(Sha256, FipsVectors) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex("abcdefghbcdefghicdefghijdefghijkefghijklfghijklmghijklmnhijklmnoijklmnopjklmnopqklmnopqrlmnopqrsmnopqrstnopqrstu"),
            "cf5b16a778af8380036ce59e7b0492370b249b11e8f07a51afac45037afee9d1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, FilesAsSha256sumSeesThem) {
  // Lengths around the 64-byte block and the 1 MiB read chunk.
  const auto dir = test::scratch_dir("sha256");
  for (size_t length : {size_t{55}, size_t{56}, size_t{64}, size_t{1} << 20, (size_t{1} << 20) + 7}) {
    const auto file = dir / ("f" + std::to_string(length));
    std::string bytes(length, '\0');
    for (size_t i = 0; i < length; ++i) bytes[i] = static_cast<char>((i * 2654435761u) >> 13);
    std::ofstream(file, std::ios::binary) << bytes;
    std::FILE* pipe = popen(("sha256sum '" + file.string() + "'").c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    char digest[65] = {};
    ASSERT_EQ(std::fread(digest, 1, 64, pipe), 64u);
    pclose(pipe);
    EXPECT_EQ(sha256_file(file), std::string(digest)) << length;
    EXPECT_EQ(sha256_hex(bytes), std::string(digest)) << length;
  }
}

}  // namespace
}  // namespace meshquilt::cli
