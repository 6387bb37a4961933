// Plain and gzip text files, including the truncated streams SOFA leaves
// behind when a writer is not closed.
#include "regression/gzip_text.h"

#include <gtest/gtest.h>
#include <unistd.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>

namespace sinew::regression {
namespace {

namespace fs = std::filesystem;

// A fresh folder per test, removed afterwards.
class GzipTextTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("sinew_gzip_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  void write_bytes(const std::string& name, const std::string& bytes) const {
    std::ofstream(path(name), std::ios::binary) << bytes;
  }
  fs::path dir_;
};

// Compresses `parts` into one gzip stream, the way SOFA's writer does: a
// sync flush after each part. With `finish` the member is closed (final
// block and trailer), otherwise the stream just stops after the last flush.
std::string sync_flushed_gzip(const std::vector<std::string>& parts, bool finish) {
  z_stream zs{};
  deflateInit2(&zs, Z_DEFAULT_COMPRESSION, Z_DEFLATED, 16 + MAX_WBITS, 8, Z_DEFAULT_STRATEGY);
  std::string out;
  auto pump = [&](const std::string& in, int flush) {
    zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
    zs.avail_in = static_cast<uInt>(in.size());
    char buffer[4096];
    do {
      zs.next_out = reinterpret_cast<Bytef*>(buffer);
      zs.avail_out = sizeof(buffer);
      deflate(&zs, flush);
      out.append(buffer, sizeof(buffer) - zs.avail_out);
    } while (zs.avail_out == 0);
  };
  for (const std::string& part : parts) pump(part, Z_SYNC_FLUSH);
  if (finish) pump("", Z_FINISH);
  deflateEnd(&zs);
  return out;
}

std::string sample_text(int blocks) {
  std::string text;
  for (int b = 0; b < blocks; ++b) {
    text += "T= " + std::to_string(b) + "\n  X=";
    for (int i = 0; i < 300; ++i) text += " " + std::to_string((i * 7919 + b * 31) % 1000);
    text += "\n";
  }
  return text;
}

TEST_F(GzipTextTest, RoundTripsPlainAndGzip) {
  const std::string text = sample_text(3);
  ASSERT_TRUE(write_text_file(path("a.txt"), text, false));
  ASSERT_TRUE(write_text_file(path("a.txt.gz"), text, true));
  EXPECT_EQ(read_text_file(path("a.txt")), text);
  EXPECT_EQ(read_text_file(path("a.txt.gz")), text);
  // Compressed really is compressed (magic bytes 1f 8b).
  std::ifstream in(path("a.txt.gz"), std::ios::binary);
  EXPECT_EQ(in.get(), 0x1f);
  EXPECT_EQ(in.get(), 0x8b);
}

TEST_F(GzipTextTest, DetectsGzipByContentNotExtension) {
  write_bytes("plain.gz", "T= 0\n");
  write_bytes("packed.txt", gzip_text("T= 1\n"));
  EXPECT_EQ(read_text_file(path("plain.gz")), "T= 0\n");
  EXPECT_EQ(read_text_file(path("packed.txt")), "T= 1\n");
}

TEST_F(GzipTextTest, AcceptsMissingTrailer) {
  const std::string text = sample_text(4);
  const std::string packed = gzip_text(text);
  // The trailer is CRC32 + length (8 bytes); without it the data is complete.
  write_bytes("no_trailer.gz", packed.substr(0, packed.size() - 8));
  std::string error;
  EXPECT_EQ(read_text_file(path("no_trailer.gz"), &error), text) << error;
}

TEST_F(GzipTextTest, KeepsEverythingFlushedBeforeACut) {
  const std::vector<std::string> parts = {"T= 0\n  X= 1 2 3\n", "T= 0.01\n  X= 4 5 6\n",
                                          sample_text(2)};
  // Never finished: what an unclosed writer leaves. Everything is readable.
  const std::string unfinished = sync_flushed_gzip(parts, false);
  write_bytes("unfinished.gz", unfinished);
  EXPECT_EQ(read_text_file(path("unfinished.gz")), parts[0] + parts[1] + parts[2]);

  // Cut in the middle of the third part's compressed data: the first two
  // parts come back whole, followed by some prefix of the third.
  const std::string first_two = sync_flushed_gzip({parts[0], parts[1]}, false);
  ASSERT_EQ(unfinished.compare(0, first_two.size(), first_two), 0);
  const std::size_t cut = first_two.size() + (unfinished.size() - first_two.size()) / 2;
  write_bytes("cut.gz", unfinished.substr(0, cut));
  const auto text = read_text_file(path("cut.gz"));
  ASSERT_TRUE(text.has_value());
  const std::string whole = parts[0] + parts[1] + parts[2];
  EXPECT_GE(text->size(), parts[0].size() + parts[1].size());
  EXPECT_LT(text->size(), whole.size());
  EXPECT_EQ(whole.compare(0, text->size(), *text), 0) << "not a prefix";
}

TEST_F(GzipTextTest, JoinsConcatenatedMembersAndIgnoresTrailingJunk) {
  write_bytes("two.gz", gzip_text("first\n") + gzip_text("second\n"));
  EXPECT_EQ(read_text_file(path("two.gz")), "first\nsecond\n");
  write_bytes("junk.gz", gzip_text("only\n") + std::string("\0\0junk", 6));
  EXPECT_EQ(read_text_file(path("junk.gz")), "only\n");
}

TEST_F(GzipTextTest, ReportsCorruptDataAndMissingFiles) {
  // A valid gzip header followed by an invalid deflate block type (11).
  const std::string packed = gzip_text("hello\n");
  write_bytes("corrupt.gz", packed.substr(0, 10) + std::string(8, '\xff'));
  std::string error;
  EXPECT_FALSE(read_text_file(path("corrupt.gz"), &error).has_value());
  EXPECT_NE(error.find("corrupt.gz"), std::string::npos) << error;

  error.clear();
  EXPECT_FALSE(read_text_file(path("missing.txt"), &error).has_value());
  EXPECT_NE(error.find("missing.txt"), std::string::npos) << error;
  EXPECT_FALSE(write_text_file(path("no/such/dir/x.txt"), "x", false, &error));
}

TEST_F(GzipTextTest, EmptyFilesReadAsEmptyText) {
  write_bytes("empty.txt", "");
  EXPECT_EQ(read_text_file(path("empty.txt")), "");
  ASSERT_TRUE(write_text_file(path("empty.gz"), "", true));
  EXPECT_EQ(read_text_file(path("empty.gz")), "");
}

}  // namespace
}  // namespace sinew::regression
