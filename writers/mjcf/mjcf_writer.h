// The MJCF writer (writers/writer.h, row "mjcf", `--out body.xml`): the
// subject as a MuJoCo model (MJCF XML, loadable by mj_loadXML 2.2 and later),
// for physics simulation. docs/mujoco.md describes the file; in short:
//
// Axes: MuJoCo's Z up. The asset's Y-up points p = (x, y, z) are turned +90
// degrees about X: (x, y, z) -> (x, -z, y) (positions, capsule ends, inertia
// tensors R I R^T). Metres, kilograms, seconds, radians
// (<compiler angle="radian">); <option gravity="0 0 -9.81" timestep="0.002">.
//
// <worldbody>: a floor plane `floor` at the height of the mesh's lowest
// vertex (the body stands on it at qpos0), then one <body> per skeleton joint
// named exactly as the joint (`pelvis`, `left_hip`, ...), nested by the
// skeleton's parents, children in joint-index order; `pos` is the rest local
// translation J_k - J_parent(k) (the root: its rest position), turned Z up, so
// at qpos0 every body's origin is its rest joint J_k(beta). The root body has
// a <freejoint> named after it; every other body, with options.mjcf_joints
// "hinge" (default), three hinges <name>_x, <name>_y, <name>_z on the axes
// 1 0 0, 0 1 0, 0 0 1 of the body frame (Z-up axes), in that order, range
// [-pi, pi] (limited); with "ball" one ball joint named as the body
// (unlimited). Joint defaults: damping 0.5 N m s/rad, armature 0.01 kg m^2
// (keeps the light finger and face bodies stable at the default timestep).
//
// Per body: <inertial pos mass fullinertia> from mjcf_parts.h (the part's
// centre of mass, volume * options.density kg/m^3, inertia about the centre;
// the masses sum to the closed rest mesh's volume times the density) and a
// collision capsule (or sphere) `<name>` fitted to the vertices the joint
// dominates (mjcf_parts.h), or with options.mjcf_geoms "mesh" the convex
// hull of those vertices: an <asset> <mesh name="<name>" vertex="..."> in
// the body's frame (MuJoCo computes the hull) and <geom type="mesh">; a
// part whose vertices span no solid keeps the capsule. Body geoms collide with the floor only
// (contype 1, conaffinity 0; the floor 1, 1): the rest pose's parts overlap.
// <compiler inertiafromgeom="false">: the geoms carry no mass.
//
// With options.mjcf_motors an <actuator> block has one <motor> per hinge
// (named as the hinge, gear 1, ctrlrange [-100, 100] N m, ctrllimited); with
// ball joints motors are an error (MuJoCo motors drive scalar joints).
//
// Motion (at most one clip; the row is single_clip): the clip as MuJoCo
// qpos rows (mjcf_qpos.h: free root position and quaternion, then per body
// three hinge angles or a ball quaternion, Z up). serializeFiles returns them
// as Files::buffer, the .npz (mjcf_npz.h) the request writes beside the XML
// as <stem>.qpos.npz (the row's motion_file): `qpos` (T, nq) float64, `fps`
// (), `joint_names` (J,) the MuJoCo joint names in qpos order. The XML holds
// the first min(T, 100) rows as <keyframe><key name="frame_<i>" time="t_i"
// qpos="..."/> (a longer clip would make the XML large; the .npz has them all)
// and a comment naming the .npz (options.buffer_uri). serialize() returns
// the XML alone.
//
// Numbers: the shortest text that reads back as the same double ("-0" as
// 0), so a key's qpos equals the .npz row exactly; names XML-escaped. Same
// asset, same bytes. Errors: a mesh without volume (mjcf_parts.h), duplicate
// or empty joint names, density not in (0, 1e5], joints not "hinge" or
// "ball", geoms not "capsule" or "mesh", more than one clip, the clip errors of mjcf_qpos.h.
//
//   Result<std::string> xml = mjcfWriter().serialize(asset, WriterOptions{});
#pragma once

#include "writers/writer.h"

namespace smpl {

const Writer& mjcfWriter();

}  // namespace smpl
