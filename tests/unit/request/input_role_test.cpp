// A file given to --model that is another input of the exporter is named
// with the option that takes it (request/input_role.h); a model's own error
// is kept.
#include "request/input_role.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/models/model_loader.h"

namespace smpl {
namespace {

const std::string kFixtures = std::string(SMPL_FIXTURE_DIR) + "/";

std::string roleMessage(const std::string& file) {
  Result<BodyModel> m = loadModel(kFixtures + file);
  EXPECT_FALSE(m.ok()) << file;
  return m.ok() ? std::string() : modelRoleError(kFixtures + file, m.error()).message;
}

TEST(InputRole, MotionsGivenAsModelsAreSentToMotion) {
  const std::pair<const char*, const char*> cases[] = {
      {"motions/amass_smplh.npz", "(the amass layout)"},
      {"layouts/video/wham/wham_output.pkl", "(the wham layout)"},
      {"layouts/video/gvhmr/hmr4d_results.pt", "(the gvhmr layout)"},
      {"layouts/video/prompthmr/world4d.mcs", "(the mcs layout)"}};
  for (const auto& [file, layout] : cases) {
    const std::string message = roleMessage(file);
    EXPECT_NE(message.find(std::string("a motion file ") + layout +
                           ", not a body model: give it as --motion"),
              std::string::npos)
        << message;
    EXPECT_EQ(message.rfind(kFixtures + file + ": ", 0), 0u) << message;
  }
}

TEST(InputRole, ShapeFilesAreSentToBetasFile) {
  const std::string message = roleMessage("formats/subject/shape.npz");
  EXPECT_NE(message.find("a shape file (betas only), not a body model: give it as --betas-file"),
            std::string::npos)
      << message;
}

TEST(InputRole, AnExportedGlbIsNamed) {
  const std::string path = ::testing::TempDir() + "input_role_body.glb";
  {
    std::ofstream out(path, std::ios::binary);
    out.write("glTF\x02\x00\x00\x00\x0c\x00\x00\x00", 12);
  }
  Result<BodyModel> m = loadModel(path);
  ASSERT_FALSE(m.ok());
  const std::string message = modelRoleError(path, m.error()).message;
  EXPECT_NE(message.find(path + ": a binary glTF (GLB), an exported file, not a body model"),
            std::string::npos)
      << message;
}

TEST(InputRole, AModelsOwnErrorIsKept) {
  const Error refused = makeError("m.npz: 'posedirs' has shape (3,3)", ErrorKind::Load);
  const Error kept = modelRoleError(kFixtures + "models/smpl_small.npz", refused);
  EXPECT_EQ(kept.message, refused.message);
  EXPECT_EQ(kept.kind, ErrorKind::Load);
  const Error missing = modelRoleError(kFixtures + "no_such_file.npz", refused);
  EXPECT_EQ(missing.message, refused.message);
}

}  // namespace
}  // namespace smpl
