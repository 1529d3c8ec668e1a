// Meshcapade scene files (.mcs): glTF 2.0 JSON whose scene carries the
// extension MC_scene_description, as PromptHMR writes world4d.mcs
// (yufu-wang/PromptHMR pipeline/mcs_export_cam.py export_scene_with_camera;
// the same layout as Meshcapade/smplcodec smplcodec/mcs.py MCSExporter):
//   scenes[scene].extensions.MC_scene_description
//     num_frames    the scene's frames
//     smpl_bodies   [{frame_presence: [first, end) scene frames, bufferView: i}]
//   bufferViews[i] -> buffers[b].uri "data:application/octet-stream;base64,..."
//                 the body's .smpl file (Meshcapade SMPLCodec npz), whole
//   nodes[k] with "camera" (AnimatedCamera) and animations[*] channels on
//                 its translation / rotation: see motion_mcs_gltf.h readCamera
// Each body is a track, ids 0, 1, ... in smpl_bodies order; its .smpl bytes
// are read as an in-memory npz by the SMPLCodec decoder (motion_smplcodec.h)
// and the track starts at frame_presence[0] of the scene's timeline
// (Motion::first_frame); frame_presence must span the body's frameCount.
// PromptHMR writes each body's smplx_world root + 21 body joints, shape mean,
// trans and the config's fps (pipeline.py): no hands, the world of
// results.pkl (Y up). The rate: the first body's frameRate (--source-fps
// overrides it), else 30 fps; the camera is sampled at that rate. Recognised by content: a JSON
// file named .mcs, .glb (PromptHMR's world4d.mcs copied to world4d.glb is still JSON text) or
// anything else. A binary GLB ("glTF" magic) is not a motion file.
// Bounds: a buffer is decoded from its data URI only (at most 3 bytes per 4
// characters of text already read), then every declared length, offset and
// count is checked against the decoded bytes (a huge declared length is
// refused, nothing allocated for it); truncated or invalid base64, NaN, wrong
// shapes and bad indices are one-line errors.
#pragma once

#include "core/motions/motion_layout.h"

namespace smpl {

const MotionLayout& mcsLayout();

}  // namespace smpl
