# Godot 3.2 side of tests/cli/godot_scene.py: plays the imported --scene GLB (res://scene.glb) and
# writes, as JSON, what Godot holds for each body and the camera at the requested times.
# Godot 3.2 skins on the GPU (no CPU-skinned vertices to read), so per body it reports the mesh
# arrays, the blend shape arrays and their weights, the Skeleton's bone global poses, the Skin's
# binds and the MeshInstance's global transform; godot_scene.py skins with these numbers.
#   godot3-server --path PROJECT --script godot_scene.gd   (PROJECT/request.json: {"times": [...]})
extends SceneTree

var done = false
var blob = File.new()
var blob_at = 0


# Numbers go to report.bin as float32 (Godot 3's own precision; its JSON printer keeps 6 digits):
# the JSON holds {"at", "n"} (offset and count in floats).
func emit(values):
	for v in values:
		blob.store_float(v)
	var ref = {"at": blob_at, "n": values.size()}
	blob_at += values.size()
	return ref


func xform(t):
	var b = t.basis
	return emit([b.x.x, b.y.x, b.z.x, t.origin.x, b.x.y, b.y.y, b.z.y, t.origin.y, b.x.z, b.y.z, b.z.z,
			t.origin.z])


func flat3(arr):
	var out = []
	for v in arr:
		out.append(v.x)
		out.append(v.y)
		out.append(v.z)
	return emit(out)


func find_all(node, type_name, out):
	if node.is_class(type_name):
		out.append(node)
	for c in node.get_children():
		find_all(c, type_name, out)
	return out


func static_body(mi):
	var mesh = mi.mesh
	var arrays = mesh.surface_get_arrays(0)
	var shapes = []
	for s in mesh.surface_get_blend_shape_arrays(0):
		shapes.append(flat3(s[Mesh.ARRAY_VERTEX]))
	var names = []
	for i in range(mesh.get_blend_shape_count()):
		names.append(mesh.get_blend_shape_name(i))
	var skin = mi.skin
	var skel = mi.get_node(mi.skeleton)
	var binds = []
	var bind_bones = []
	for i in range(skin.get_bind_count()):
		binds.append(xform(skin.get_bind_pose(i)))
		var bone = skin.get_bind_bone(i)
		if skin.get_bind_name(i) != "":
			bone = skel.find_bone(skin.get_bind_name(i))
		bind_bones.append(bone)
	return {"vertices": flat3(arrays[Mesh.ARRAY_VERTEX]), "bones": Array(arrays[Mesh.ARRAY_BONES]),
			"weights": emit(Array(arrays[Mesh.ARRAY_WEIGHTS])), "shapes": shapes, "shape_names": names,
			"blend_shape_mode": mesh.blend_shape_mode, "binds": binds, "bind_bones": bind_bones,
			"bone_count": skel.get_bone_count(), "skeleton": skel.name,
			"parent": skel.get_parent().name}


# Per frame: the weights the AnimationPlayer set on the MeshInstance ("played") and the imported
# Animation's value tracks at that time ("imported"; -1: no track), which tells an importer error
# from a playback one.
func frame_body(mi, names, anim, scene, t):
	var skel = mi.get_node(mi.skeleton)
	var poses = []
	for b in range(skel.get_bone_count()):
		poses.append(xform(skel.get_bone_global_pose(b)))
	var played = []
	var imported = []
	var path = str(scene.get_path_to(mi)) + ":blend_shapes/"
	for n in names:
		played.append(mi.get("blend_shapes/" + n))
		var track = anim.find_track(NodePath(path + n))
		imported.append(key_value(anim, track, t) if track >= 0 else -1.0)
	return {"mesh_global": xform(mi.global_transform), "bone_poses": poses, "shape_weights": emit(played),
			"imported_weights": emit(imported), "visible": mi.is_visible_in_tree()}


# A LINEAR value track at time t from its keys (Godot 3.2 has no Animation.value_track_interpolate),
# held before the first and after the last key as glTF samplers are.
func key_value(anim, track, t):
	var k = anim.track_find_key(track, t)
	var last = anim.track_get_key_count(track) - 1
	if k < 0:
		return anim.track_get_key_value(track, 0)
	if k >= last:
		return anim.track_get_key_value(track, last)
	var t0 = anim.track_get_key_time(track, k)
	var c = (t - t0) / (anim.track_get_key_time(track, k + 1) - t0)
	return lerp(anim.track_get_key_value(track, k), anim.track_get_key_value(track, k + 1), c)


func _idle(_delta):
	if done:
		return false
	done = true
	var req = parse_json(_read("res://request.json"))
	blob.open("res://report.bin", File.WRITE)
	var out = {"bodies": {}, "frames": [], "errors": []}
	var packed = load("res://scene.glb")
	if packed == null:
		out.errors.append("res://scene.glb did not load (not imported)")
		return _finish(out)
	var scene = packed.instance()
	root.add_child(scene)
	var players = find_all(scene, "AnimationPlayer", [])
	var meshes = find_all(scene, "MeshInstance", [])
	var cameras = find_all(scene, "Camera", [])
	out["animations"] = players[0].get_animation_list() if players.size() == 1 else []
	var names = {}
	for mi in meshes:
		var body = static_body(mi)
		out.bodies[mi.name] = body
		names[mi.name] = body.shape_names
	if players.size() != 1 or out.animations.size() != 1:
		out.errors.append("expected one AnimationPlayer with one animation")
		return _finish(out)
	var ap = players[0]
	var anim = ap.get_animation(out.animations[0])
	var value_tracks = 0
	for i in range(anim.get_track_count()):
		if anim.track_get_type(i) == Animation.TYPE_VALUE:
			value_tracks += 1
	out["value_tracks"] = value_tracks
	ap.play(out.animations[0])
	for t in req.times:
		ap.seek(t, true)
		var f = {"time": t, "bodies": {}}
		for mi in meshes:
			f.bodies[mi.name] = frame_body(mi, names[mi.name], anim, scene, t)
		if cameras.size() > 0:
			f["camera"] = {"global": xform(cameras[0].global_transform), "fov": cameras[0].fov,
					"keep_aspect": cameras[0].keep_aspect, "name": cameras[0].name}
		out.frames.append(f)
	out["length"] = ap.get_animation(out.animations[0]).length
	return _finish(out)


func _read(path):
	var f = File.new()
	f.open(path, File.READ)
	var text = f.get_as_text()
	f.close()
	return text


func _finish(out):
	if blob.is_open():
		blob.close()
	var f = File.new()
	f.open("res://report.json", File.WRITE)
	f.store_string(to_json(out))
	f.close()
	quit()
	return true
