// SHA-256 against the test vectors of FIPS 180-2 (appendix B) and NIST's examples, and against the system's
// sha256sum on a file that spans many blocks and an odd tail.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "io/sha256.h"
#include "support/run_process.h"
#include "support/temp_dir.h"

namespace lagoon {
namespace {

std::string sha(const std::string& text) {
  return io::sha256_hex(std::as_bytes(std::span(text.data(), text.size())));
}

TEST(Sha256, MatchesTheFipsVectors) {
  EXPECT_EQ(sha(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  // One million 'a' (FIPS 180-2 B.3), fed in uneven pieces so block boundaries fall inside updates.
  io::Sha256 million;
  const std::string piece(997, 'a');
  size_t left = 1000000;
  while (left > 0) {
    const size_t n = std::min(left, piece.size());
    million.update(std::as_bytes(std::span(piece.data(), n)));
    left -= n;
  }
  EXPECT_EQ(million.hex(), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, AFileHashesAsSha256sumSays) {
  test::TempDir dir;
  const auto path = dir / "data.bin";
  {
    std::ofstream out(path, std::ios::binary);
    for (int i = 0; i < 200003; ++i) out.put(char((i * 7919) >> 3));
  }
  const test::ProcessResult sum = test::run_process("sha256sum " + test::shell_quote(path.string()));
  ASSERT_EQ(sum.exit_code, 0) << sum.output;
  const Result<std::string> ours = io::sha256_file(path);
  ASSERT_TRUE(ours) << ours.error().message;
  EXPECT_EQ(*ours, sum.output.substr(0, 64));
  EXPECT_FALSE(io::sha256_file(dir / "missing.bin"));
}

}  // namespace
}  // namespace lagoon
