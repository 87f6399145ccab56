# probeproxy's Godot 4 importer (GDScript 2): reads a proxies.json written by `probeproxy export`
# / `build --out` / `layout --out` and makes one ReflectionProbe per probe that has a
# `godot4_reflection_probe` entry (an export without that member: its `godot_reflection_probe`;
# null: a probe `layout --engine godot4` left out). The Godot 3 importer beside it says what
# each number is (probeproxy_import.gd, docs/godot.md); here Godot 4's own names:
#
#   var root = preload("probeproxy_import_godot4.gd").import_probes("res://level/proxies.json")
#
# size is the full size (Godot 3's extents are half sizes); ReflectionProbe.blend_distance
# where the running Godot has it (the versions that fade inside the box), else kept as the
# metadata "probeproxy_blend_distance"; interior on (pass interior = false for outdoor probes).
# Debian 12 packages only Godot 3, so this file is not run by the tests.
extends RefCounted

const FORMAT_ID = "probeproxy_runtime"


static func read_json(path: String):
	if not FileAccess.file_exists(path):
		push_error("probeproxy: cannot open " + path)
		return null
	var json := JSON.new()
	if json.parse(FileAccess.get_file_as_string(path)) != OK:
		push_error("probeproxy: %s:%d: %s" % [path, json.get_error_line(), json.get_error_message()])
		return null
	if typeof(json.data) != TYPE_DICTIONARY or not json.data.has(FORMAT_ID):
		push_error("probeproxy: " + path + " is not a probeproxy runtime export")
		return null
	return json.data


static func vec3(a) -> Vector3:
	return Vector3(a[0], a[1], a[2])


# One ReflectionProbe from one Godot entry.
static func make_probe(probe_name: String, entry: Dictionary, interior := true) -> ReflectionProbe:
	var probe := ReflectionProbe.new()
	probe.name = probe_name
	var q = entry["rotation_xyzw"]
	probe.transform = Transform3D(Basis(Quaternion(q[0], q[1], q[2], q[3])), vec3(entry["origin"]))
	# size before origin_offset: set_origin_offset clamps against the current size.
	probe.size = vec3(entry["size"])
	probe.origin_offset = vec3(entry["origin_offset"])
	probe.max_distance = entry.get("max_distance", 0.0)
	probe.box_projection = entry["box_projection"]
	probe.interior = interior
	if "blend_distance" in probe:
		probe.blend_distance = entry["blend_distance"]
	else:
		probe.set_meta("probeproxy_blend_distance", entry["blend_distance"])
	probe.set_meta("probeproxy_exact", entry["exact"])
	probe.set_meta("probeproxy_candidate", entry["candidate"])
	return probe


# A Node3D named "probeproxy_probes" holding one ReflectionProbe per probe with a Godot 4
# entry, in the file's order, each owned by the root (so PackedScene.pack keeps them). null on
# error.
static func import_probes(path: String, interior := true) -> Node3D:
	var data = read_json(path)
	if data == null:
		return null
	var root := Node3D.new()
	root.name = "probeproxy_probes"
	for p in data["probes"]:
		var engines: Dictionary = p["engines"]
		var key := "godot4_reflection_probe" if engines.has("godot4_reflection_probe") \
				else "godot_reflection_probe"
		var entry = engines[key]
		if entry == null:
			continue
		var probe := make_probe(p["name"], entry, interior)
		root.add_child(probe)
		probe.owner = root
	return root
