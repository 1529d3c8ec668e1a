// UV sources: the model file's vt/ft, --uv OBJ and --uv numpy pairs split
// seams identically; --uv none turns UVs off; bad indices are one-line errors.
#include "core/models/uv_source.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <set>

#include "core/models/model_loader.h"
#include "core/models/uv_npy.h"
#include "core/models/uv_obj.h"

namespace smpl {
namespace {

const std::string kReleased = std::string(SMPL_FIXTURE_DIR) + "/released/";

BodyModel release() {
  Result<BodyModel> m = loadModel(kReleased + "smplx_release.npz");
  EXPECT_TRUE(m.ok()) << m.message();
  return m.ok() ? *m : BodyModel();
}

void expectSame(const UvLayout& a, const UvLayout& b) {
  EXPECT_EQ(a.source_vertex, b.source_vertex);
  EXPECT_TRUE(a.triangles == b.triangles);
  ASSERT_EQ(a.uvs.rows(), b.uvs.rows());
  EXPECT_LT((a.uvs - b.uvs).cwiseAbs().maxCoeff(), 1e-6f);  // the OBJ prints 9 decimals
}

TEST(UvSource, ModelUvsSplitSeamsLikeTheObj) {
  const BodyModel m = release();
  Result<std::optional<UvLayout>> own = resolveUvLayout("", m);
  ASSERT_TRUE(own.ok()) << own.message();
  ASSERT_TRUE(own->has_value());
  // Independent count: distinct (vertex, uv) corner pairs of the faces.
  std::set<std::pair<int, int>> corners;
  for (Eigen::Index i = 0; i < m.faces.size(); ++i)
    corners.emplace(m.faces(i / 3, i % 3), m.texcoord_faces(i / 3, i % 3));
  EXPECT_EQ((*own)->source_vertex.size(), corners.size());
  EXPECT_GT(corners.size(), static_cast<size_t>(m.numVertices()));  // the fixture has seams
  for (size_t v = 0; v < (*own)->source_vertex.size(); ++v) {
    const int s = (*own)->source_vertex[v];
    EXPECT_TRUE(s >= 0 && s < m.numVertices());
  }
  Result<UvLayout> obj = loadUvLayout(kReleased + "smplx_release_uv.obj", m);
  ASSERT_TRUE(obj.ok()) << obj.message();
  expectSame(**own, *obj);
  for (const char* pair : {"smplx_pair_uv.npy", "smplx_pair_ft.npy"}) {
    Result<std::optional<UvLayout>> npy = resolveUvLayout(kReleased + pair, m);
    ASSERT_TRUE(npy.ok()) << npy.message();
    ASSERT_TRUE(npy->has_value());
    expectSame(**own, **npy);
  }
}

TEST(UvSource, NoneTurnsUvsOffAndModelsWithoutUvsHaveNone) {
  const BodyModel m = release();
  Result<std::optional<UvLayout>> none = resolveUvLayout("none", m);
  ASSERT_TRUE(none.ok());
  EXPECT_FALSE(none->has_value());
  BodyModel plain = m;
  plain.texcoords.resize(0, 2);
  plain.texcoord_faces.resize(0, 3);
  Result<std::optional<UvLayout>> absent = resolveUvLayout("", plain);
  ASSERT_TRUE(absent.ok());
  EXPECT_FALSE(absent->has_value());
}

TEST(UvSource, NumpyPairErrors) {
  const BodyModel m = release();
  Result<UvLayout> lone = loadUvNumpyPair(kReleased + "betas_rows_differ.npy", m);
  ASSERT_FALSE(lone.ok());
  EXPECT_NE(lone.message().find("must be a pair named <stem>_uv.npy"), std::string::npos)
      << lone.message();
  Result<UvLayout> orphan = loadUvNumpyPair(kReleased + "lonely_uv.npy", m);
  ASSERT_FALSE(orphan.ok());
  EXPECT_NE(orphan.message().find("lonely_uv.npy: its partner lonely_ft.npy does not exist"),
            std::string::npos)
      << orphan.message();
  Result<UvLayout> absent = loadUvNumpyPair(kReleased + "nothing_ft.npy", m);
  ASSERT_FALSE(absent.ok());
  EXPECT_NE(absent.message().find("nothing_ft.npy: cannot open"), std::string::npos)
      << absent.message();
  BodyModel fewer = m;  // ft rows must match the model's faces
  fewer.faces = m.faces.topRows(10);
  Result<UvLayout> rows = loadUvNumpyPair(kReleased + "smplx_pair_uv.npy", fewer);
  ASSERT_FALSE(rows.ok());
  EXPECT_NE(rows.message().find("smplx_pair_ft.npy: UV faces (one row per model face) has shape ("),
            std::string::npos)
      << rows.message();
}

// An OBJ texture coordinate beyond float32 (or the plausible range) is named
// with its line, not read as Inf (nor as a "malformed" line).
TEST(UvSource, ObjCoordinatesAreRangeChecked) {
  const BodyModel m = release();
  const std::string path = ::testing::TempDir() + "uv_range_" + std::to_string(::getpid()) + ".obj";
  std::ofstream(path) << "vt 0.5 0.5\nvt 1e39 0\nf 1/1 2/2 1/1\n";
  Result<UvLayout> r = loadUvLayout(path, m);
  std::remove(path.c_str());
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.message().rfind(path + ":2: 'vt' element 0 is 1e+39; expected finite texture", 0), 0u)
      << r.message();
}

}  // namespace
}  // namespace smpl
