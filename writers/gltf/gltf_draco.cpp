#include "writers/gltf/gltf_draco.h"

#include "writers/writer.h"

#ifdef SMPL_NO_DRACO
// Builds without Draco (the Windows build: Debian ships no Draco for
// mingw-w64): --draco is refused by the request check (dracoAvailable()).
namespace smpl {

const char kNoDraco[] =
    "--draco: this smpl-export was built without Draco (the Windows and WebAssembly builds: "
    "Debian ships no Draco for them); use --meshopt, or a Linux build";

bool dracoAvailable() { return false; }

Result<DracoBlob> encodeDraco(const MeshStreams&) { return makeError(kNoDraco); }

Result<MeshStreams> decodeDraco(const std::string&, const std::map<std::string, int>&, size_t) {
  return makeError(kNoDraco);
}

}  // namespace smpl
#else
#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>

#include <memory>

namespace smpl {

bool dracoAvailable() { return true; }

namespace {

// Adds one attribute with identity point mapping (point i = value i).
int addAttribute(draco::Mesh& mesh, draco::GeometryAttribute::Type type, int components,
                 draco::DataType data_type, size_t element_bytes, const void* data, size_t count) {
  draco::GeometryAttribute ga;
  ga.Init(type, nullptr, uint8_t(components), data_type, false, int64_t(element_bytes), 0);
  const int id = mesh.AddAttribute(ga, true, uint32_t(count));
  draco::PointAttribute* att = mesh.attribute(id);
  const auto* bytes = static_cast<const uint8_t*>(data);
  for (size_t i = 0; i < count; ++i)
    att->SetAttributeValue(draco::AttributeValueIndex(uint32_t(i)), bytes + i * element_bytes);
  return id;
}

void readFloats(const draco::PointAttribute* att, size_t points, int components,
                std::vector<float>* out) {
  out->assign(points * size_t(components), 0.f);
  for (size_t i = 0; i < points; ++i)
    att->ConvertValue<float>(att->mapped_index(draco::PointIndex(uint32_t(i))), int8_t(components),
                             out->data() + i * size_t(components));
}

}  // namespace

Result<DracoBlob> encodeDraco(const MeshStreams& m) {
  draco::Mesh mesh;
  mesh.set_num_points(uint32_t(m.vertices));
  const size_t faces = m.indices.size() / 3;
  mesh.SetNumFaces(faces);
  for (size_t f = 0; f < faces; ++f) {
    draco::Mesh::Face face;
    for (int c = 0; c < 3; ++c) face[c] = draco::PointIndex(m.indices[3 * f + size_t(c)]);
    mesh.SetFace(draco::FaceIndex(uint32_t(f)), face);
  }
  DracoBlob blob;
  auto add = [&](const std::string& semantic, int id) {
    blob.attributes[semantic] = int(mesh.attribute(id)->unique_id());
  };
  using GA = draco::GeometryAttribute;
  add("POSITION",
      addAttribute(mesh, GA::POSITION, 3, draco::DT_FLOAT32, 12, m.positions.data(), m.vertices));
  add("NORMAL",
      addAttribute(mesh, GA::NORMAL, 3, draco::DT_FLOAT32, 12, m.normals.data(), m.vertices));
  if (!m.uvs.empty())
    add("TEXCOORD_0",
        addAttribute(mesh, GA::TEX_COORD, 2, draco::DT_FLOAT32, 8, m.uvs.data(), m.vertices));
  for (size_t s = 0; s < m.joints.size(); ++s) {
    std::vector<uint8_t> narrow(m.joints[s].begin(), m.joints[s].end());
    const int id = m.wide_joints ? addAttribute(mesh, GA::GENERIC, 4, draco::DT_UINT16, 8,
                                                m.joints[s].data(), m.vertices)
                                 : addAttribute(mesh, GA::GENERIC, 4, draco::DT_UINT8, 4,
                                                narrow.data(), m.vertices);
    add("JOINTS_" + std::to_string(s), id);
    add("WEIGHTS_" + std::to_string(s),
        addAttribute(mesh, GA::GENERIC, 4, draco::DT_FLOAT32, 16, m.weights[s].data(), m.vertices));
  }
  draco::Encoder encoder;
  encoder.SetEncodingMethod(draco::MESH_SEQUENTIAL_ENCODING);
  encoder.SetAttributeQuantization(GA::POSITION, kDracoPositionBits);
  encoder.SetAttributeQuantization(GA::NORMAL, 12);
  encoder.SetAttributeQuantization(GA::TEX_COORD, 14);
  draco::EncoderBuffer buffer;
  const draco::Status st = encoder.EncodeMeshToBuffer(mesh, &buffer);
  if (!st.ok()) return makeError("glTF writer: Draco encoding failed: " + st.error_msg_string());
  blob.bytes.assign(buffer.data(), buffer.size());
  return blob;
}

Result<MeshStreams> decodeDraco(const std::string& bytes,
                                const std::map<std::string, int>& attributes,
                                size_t expected_vertices) {
  draco::DecoderBuffer buffer;
  buffer.Init(bytes.data(), bytes.size());
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok())
    return makeError("Draco: cannot decode: " + decoded.status().error_msg_string());
  const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
  if (mesh->num_points() != expected_vertices)
    return makeError("Draco: " + std::to_string(mesh->num_points()) + " points; expected " +
                     std::to_string(expected_vertices));
  MeshStreams out;
  out.vertices = expected_vertices;
  const std::pair<const char*, std::vector<float>*> wanted[] = {
      {"POSITION", &out.positions}, {"NORMAL", &out.normals}, {"TEXCOORD_0", &out.uvs}};
  for (const auto& w : wanted) {
    auto it = attributes.find(w.first);
    if (it == attributes.end()) continue;
    const draco::PointAttribute* att = mesh->GetAttributeByUniqueId(uint32_t(it->second));
    if (!att) return makeError(std::string("Draco: no attribute for ") + w.first);
    readFloats(att, expected_vertices, att->num_components(), w.second);
  }
  for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f)
    for (int c = 0; c < 3; ++c) out.indices.push_back(mesh->face(f)[c].value());
  return out;
}

}  // namespace smpl
#endif  // SMPL_NO_DRACO
