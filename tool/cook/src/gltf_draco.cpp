// Built as its own module (hullcook_draco.so, see tool/cook/CMakeLists.txt), loaded by
// draco_module.cpp only when a glTF is Draco-compressed: linking Draco into the cooker cost every
// hullcook process 4-5 ms of dynamic loading, about half of its start-up.
#include "gltf_draco.h"

#include "hullcook/core/error.h"

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>

#include <algorithm>

namespace hullcook {

namespace {

DracoMesh encode(const TriangleMesh& mesh, int position_bits, const std::string& name) {
  const int face_count = static_cast<int>(mesh.indices.size() / 3);
  draco::TriangleSoupMeshBuilder builder;
  builder.Start(face_count);
  const int position_attribute =
      builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  for (int face = 0; face < face_count; ++face) {
    const std::uint32_t* corner = &mesh.indices[3 * static_cast<std::size_t>(face)];
    builder.SetAttributeValuesForFace(
        position_attribute, draco::FaceIndex(face), &mesh.positions[3 * corner[0]],
        &mesh.positions[3 * corner[1]], &mesh.positions[3 * corner[2]]);
  }
  std::unique_ptr<draco::Mesh> built = builder.Finalize();
  if (!built) throw OutputError("mesh " + name + ": Draco could not build the mesh");

  draco::Encoder encoder;
  encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, position_bits);
  draco::EncoderBuffer encoded;
  draco::Status status = encoder.EncodeMeshToBuffer(*built, &encoded);
  if (!status.ok()) {
    throw OutputError("mesh " + name + ": Draco encoding failed: " + status.error_msg_string());
  }

  draco::DecoderBuffer input;
  input.Init(encoded.data(), encoded.size());
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&input);
  if (!decoded.ok() || !decoded.value()) {
    throw OutputError("mesh " + name + ": the Draco encoding does not decode");
  }
  const draco::Mesh& result = *decoded.value();
  const draco::PointAttribute* positions =
      result.GetNamedAttribute(draco::GeometryAttribute::POSITION);
  if (!positions || result.num_points() == 0) {
    throw OutputError("mesh " + name + ": the Draco encoding lost its positions");
  }
  DracoMesh out;
  out.bytes.assign(encoded.data(), encoded.size());
  out.decoded_points = result.num_points();
  out.decoded_faces = result.num_faces();
  out.position_id = positions->unique_id();
  for (draco::PointIndex point(0); point < result.num_points(); ++point) {
    std::array<float, 3> value{};
    positions->GetMappedValue(point, value.data());
    for (std::size_t axis = 0; axis < 3; ++axis) {
      out.min[axis] = point.value() == 0 ? value[axis] : std::min(out.min[axis], value[axis]);
      out.max[axis] = point.value() == 0 ? value[axis] : std::max(out.max[axis], value[axis]);
    }
  }
  return out;
}

}  // namespace

}  // namespace hullcook

// The module's one entry point (kDracoEntryPoint in gltf_draco.h): no exception crosses it.
extern "C" __attribute__((visibility("default"))) bool hullcook_draco_encode(
    const hullcook::TriangleMesh* mesh, int position_bits, const std::string* name,
    hullcook::DracoMesh* out, std::string* error) noexcept {
  try {
    *out = hullcook::encode(*mesh, position_bits, *name);
    return true;
  } catch (const std::exception& e) {
    *error = e.what();
  } catch (...) {
    *error = "mesh " + *name + ": Draco failed";
  }
  return false;
}
