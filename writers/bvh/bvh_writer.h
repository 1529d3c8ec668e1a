// The BVH writer (writers/writer.h, row "bvh"): the subject's skeleton and one
// motion as Biovision Hierarchy text, for retargeting tools (MotionBuilder,
// Blender's BVH importer, research pipelines). Skeleton-only (the row's
// needs_mesh is false): no mesh, skin or morph targets are read.
//
// HIERARCHY: one ROOT (the skeleton's root, `pelvis` for the body models) and
// a JOINT per further joint, nested depth first with children in joint-index
// order, each named with the models' authors' joint names; OFFSET is the rest
// local translation J_k - J_parent(k) of J(beta) (the root: J_0), in the
// file's units; a joint with no children ends in an "End Site" whose OFFSET
// is half the joint's own offset (for display only: the models have no tip
// joints). CHANNELS: the root "Xposition Yposition Zposition Zrotation
// Xrotation Yrotation"; every other joint "Zrotation Xrotation Yrotation",
// with the three position channels first as well for a joint whose clip
// carries a translation track that leaves its rest offset
// (AnimationClip::joint_translations). Position channels hold the joint's
// local translation (the offset is replaced, not added to: the root's is
// J_0 + trans turned Y-up). Rotations: bvh_euler.h (R = Rz Rx Ry, degrees).
//
// MOTION: "Frames: T", "Frame Time: 1/fps" (seconds, 10 decimals), then one
// line per frame with every joint's channels in HIERARCHY order. Without a
// clip the file has one frame, the rest pose (T-pose; Frame Time 1/30 s), for
// characterising the skeleton in a retargeting tool. More than one clip is an
// error (the request allows one --motion for this format: WriterFormat::single_clip).
//
// Axes and units: the asset's (Y up, metres, right-handed); options.bvh_units
// "cm" multiplies every offset and position by 100. Numbers are fixed-point:
// positions with 8 decimals in metres or 6 in centimetres (1e-8 m), angles with
// 6 decimals (degrees); "-0" is written as 0. Same asset, same bytes.
//
//   Result<std::string> text = bvhWriter().serialize(asset, WriterOptions{});
#pragma once

#include "writers/writer.h"

namespace smpl {

const Writer& bvhWriter();

}  // namespace smpl
