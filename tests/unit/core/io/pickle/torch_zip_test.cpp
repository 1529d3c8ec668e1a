// torch.save archives (core/io/pickle/pickle_torch.cpp, pickle_torch_zip.cpp).
// data_tree_test compares every fixture with torch's own values; here: the
// tensor rebuild rules one by one (views of one storage, strides, byte
// order, dtypes), corrupt and truncated archives, and that persistent ids stay
// refused outside a torch archive.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/io/pickle/pickle_tree.h"
#include "core/io/zip.h"
#include "tests/unit/test_util.h"
#include "tests/unit/tree_expect.h"

namespace smpl {
namespace {

using test::kContainers;
using test::readAll;

Result<DataNode> torchZip(const std::string& bytes, const std::string& context = "x.pt") {
  return parseTorchZip(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), context);
}

const Array& leafOf(const DataNode& tree, const char* key) {
  static const Array kNone;
  const Array* a = tree.leaf(key);
  EXPECT_NE(a, nullptr) << key;
  return a ? *a : kNone;
}

TEST(TorchZip, ViewsOfOneStorageKeepOffsetsAndStrides) {
  // base = arange(24) / 8, saved once; each view is (offset, size, stride) over it.
  Result<DataNode> tree = torchZip(readAll(kContainers + "views.pt"));
  ASSERT_TRUE(tree.ok()) << tree.message();
  auto base = [](int i) { return i / 8.0; };
  const Array& offset = leafOf(*tree, "offset");  // base[2:5]
  EXPECT_EQ(offset.data, (std::vector<double>{base(2), base(3), base(4)}));
  const Array& transposed = leafOf(*tree, "transposed");  // base[:12].view(3,4).t(): (4,3)
  ASSERT_EQ(shapeString(transposed.shape), "(4,3)");
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(transposed.data[r * 3 + c], base(c * 4 + r));
  const Array& columns = leafOf(*tree, "columns");  // base.view(4,6)[:, 1:3]
  ASSERT_EQ(shapeString(columns.shape), "(4,2)");
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 2; ++c) EXPECT_EQ(columns.data[r * 2 + c], base(r * 6 + 1 + c));
  EXPECT_EQ(leafOf(*tree, "strided").data,
            (std::vector<double>{base(0), base(5), base(10), base(15), base(20)}));
}

TEST(TorchZip, DtypesByteOrderAndRebuildForms) {
  Result<DataNode> dtypes = torchZip(readAll(kContainers + "dtypes.pt"));
  ASSERT_TRUE(dtypes.ok()) << dtypes.message();
  EXPECT_EQ(leafOf(*dtypes, "bf16").dtype, "bfloat16");
  EXPECT_EQ(leafOf(*dtypes, "bf16").data[0], 1.5);
  EXPECT_EQ(leafOf(*dtypes, "f16").data[2], 65504.0);
  EXPECT_EQ(leafOf(*dtypes, "i64").data[0], -1099511627776.0);
  EXPECT_EQ(leafOf(*dtypes, "u8").data, (std::vector<double>{0, 255}));
  EXPECT_EQ(shapeString(leafOf(*dtypes, "zero_d").shape), "()");
  EXPECT_EQ(shapeString(leafOf(*dtypes, "empty").shape), "(0,4)");
  EXPECT_EQ(leafOf(*dtypes, "size").data, (std::vector<double>{2, 3}));  // torch.Size
  // byteorder "big": the storages are big-endian.
  Result<DataNode> big = torchZip(readAll(kContainers + "big.pt"));
  ASSERT_TRUE(big.ok()) << big.message();
  EXPECT_EQ(leafOf(*big, "i").data, (std::vector<double>{1, -2, 3}));
  EXPECT_EQ(leafOf(*big, "i").dtype, "<i4");  // torch dtypes have no byte order
  // torch 2.x's _rebuild_tensor_v3 (bytes + dtype), _rebuild_from_type_v2, metadata 'neg'.
  for (const char* file : {"v3.pt", "fromtype.pt", "neg.pt"}) {
    Result<DataNode> tree = torchZip(readAll(kContainers + file));
    ASSERT_TRUE(tree.ok()) << file << ": " << tree.message();
    test::expectTree(*tree, test::expectedTrees().at(file), file);
  }
}

TEST(TorchZip, EveryTruncationAndByteFlipEndsCleanly) {
  const std::string bytes = readAll(kContainers + "views.pt");
  for (size_t n = 0; n < bytes.size(); ++n) {
    Result<DataNode> r = torchZip(bytes.substr(0, n));
    ASSERT_FALSE(r.ok()) << "truncated to " << n;
    ASSERT_EQ(r.message().rfind("x.pt", 0), 0u) << r.message();
  }
  // Flipped bytes: an error (CRC, zip structure, pickle) or, where only
  // unchecked bytes changed, a tree; never a crash or a read out of bounds.
  int failed = 0;
  for (size_t i = 0; i < bytes.size(); ++i) {
    std::string edited = bytes;
    edited[i] = static_cast<char>(edited[i] ^ 0x5a);
    failed += !torchZip(edited).ok();
  }
  EXPECT_GT(failed, static_cast<int>(bytes.size() / 2));
}

TEST(TorchZip, LegacyFilesAreRefusedByEveryPickleReader) {
  // torch < 1.6's format is a sequence of pickles: the first is the magic number.
  const std::string legacy = readAll(kContainers + "legacy.pt");
  ASSERT_TRUE(isLegacyTorchFile(reinterpret_cast<const uint8_t*>(legacy.data()), legacy.size()));
  for (auto* parse : {&parsePickleTree, &parseJoblib}) {
    Result<DataNode> r =
        (*parse)(reinterpret_cast<const uint8_t*>(legacy.data()), legacy.size(), "old.pt", {});
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.message(),
              "old.pt: a legacy torch file: re-save it with torch.save(obj, f) in torch >= 1.6");
  }
  Result<DataNode> zip = torchZip(legacy, "old.pt");
  ASSERT_FALSE(zip.ok());
  EXPECT_EQ(zip.message(), "old.pt: not a zip archive (no end of central directory record)");
}

TEST(TorchZip, PersistentIdsAndTorchGlobalsOnlyInsideAnArchive) {
  const std::string bytes = readAll(kContainers + "gvhmr.pt");
  const uint8_t* data = reinterpret_cast<const uint8_t*>(bytes.data());
  Result<std::vector<ZipMember>> members = listZip(data, bytes.size(), "gvhmr.pt");
  ASSERT_TRUE(members.ok());
  ASSERT_EQ((*members)[0].name, "gvhmr/data.pkl");
  Result<ZipEntry> pkl = extractZipMember(data, bytes.size(), (*members)[0], "gvhmr.pt");
  ASSERT_TRUE(pkl.ok());
  // The same data.pkl as a plain pickle: torch's globals are allowed there (a plain pickle's
  // storages are torch.storage._load_from_bytes), its persistent ids are not.
  Result<DataNode> plain = parsePickleTree(pkl->data.data(), pkl->data.size(), "data.pkl");
  ASSERT_FALSE(plain.ok());
  EXPECT_EQ(plain.message(), "data.pkl: persistent IDs are not supported (not model data)");
  // A persistent id without torch's globals.
  const std::string pid(
      "\x80\x02X\x01\x00\x00\x00"
      "aQ.",
      10);
  Result<DataNode> persid =
      parsePickleTree(reinterpret_cast<const uint8_t*>(pid.data()), pid.size(), "p.pkl");
  ASSERT_FALSE(persid.ok());
  EXPECT_EQ(persid.message(), "p.pkl: persistent IDs are not supported (not model data)");
}

}  // namespace
}  // namespace smpl
