# probeproxy's Godot importer (Godot 3.2+, GDScript): reads a proxies.json written by
# `probeproxy export` / `build --out` and makes one ReflectionProbe per probe that has a
# `godot_reflection_probe` entry (docs/godot.md, docs/engines.md).
#
#   var root = preload("probeproxy_import.gd").import_probes("res://level/proxies.json")
#
# Each node: name = the probe's name; transform = the entry's origin and rotation (Godot axes,
# metres); extents = size / 2 (Godot 3's extents are half sizes; Godot 4's `size` is the full
# size); origin_offset = the capture point in the node's frame (Godot clamps it 1 cm inside the
# box: `exact` false in proxies.json says where); max_distance (the capture point's distance to
# the box's farthest corner: Godot's default 0 clips each cube face at the box's face, and the
# walls the box was fitted to with it); box_projection on; interior on (probeproxy's
# probes model rooms; pass interior = false for outdoor probes). Godot 3 has no blend distance:
# the entry's blend_distance is kept as the metadata "probeproxy_blend_distance" (Godot 4.3+
# sets ReflectionProbe.blend_distance). Also kept as metadata: "probeproxy_exact" and
# "probeproxy_candidate".
extends Reference

const FORMAT_ID = "probeproxy_runtime"


static func read_json(path):
	var file = File.new()
	if file.open(path, File.READ) != OK:
		push_error("probeproxy: cannot open " + path)
		return null
	var parsed = JSON.parse(file.get_as_text())
	file.close()
	if parsed.error != OK:
		push_error("probeproxy: %s:%d: %s" % [path, parsed.error_line, parsed.error_string])
		return null
	if typeof(parsed.result) != TYPE_DICTIONARY or not parsed.result.has(FORMAT_ID):
		push_error("probeproxy: " + path + " is not a probeproxy runtime export")
		return null
	return parsed.result


static func vec3(a):
	return Vector3(a[0], a[1], a[2])


# One ReflectionProbe from one `godot_reflection_probe` entry.
static func make_probe(name, entry, interior = true):
	var probe = ReflectionProbe.new()
	probe.name = name
	var q = entry["rotation_xyzw"]
	probe.transform = Transform(Basis(Quat(q[0], q[1], q[2], q[3])), vec3(entry["origin"]))
	# extents before origin_offset: set_origin_offset clamps against the current extents.
	probe.extents = vec3(entry["size"]) / 2.0
	probe.origin_offset = vec3(entry["origin_offset"])
	# Exports before max_distance was written leave Godot's default (0: each face sees only to
	# the box's face, and a wall on it is clipped).
	probe.max_distance = entry.get("max_distance", 0.0)
	probe.box_projection = entry["box_projection"]
	probe.interior_enable = interior
	probe.set_meta("probeproxy_blend_distance", entry["blend_distance"])
	probe.set_meta("probeproxy_exact", entry["exact"])
	probe.set_meta("probeproxy_candidate", entry["candidate"])
	return probe


# The reflection atlas's slots for an atlas_subdiv setting, as Godot 3 rounds it
# (RasterizerSceneGLES3::reflection_atlas_set_subdivision: up to a power of 2, then of 4): the
# default 8 gives 16. Godot 3 draws at most that many probes; the others show nothing.
static func atlas_slots(subdiv):
	var slots = 1
	while slots < subdiv:
		slots *= 2
	if slots & 0xaaaaaaaa:
		slots *= 2
	return slots


# "" when the project's reflection atlas has a slot for each of `count` probes, else what to set.
static func atlas_warning(count):
	var subdiv = ProjectSettings.get_setting("rendering/quality/reflections/atlas_subdiv")
	if count <= atlas_slots(subdiv):
		return ""
	var needed = 16
	while needed < count:
		needed *= 4
	return ("probeproxy: %d probes, but Godot 3 draws only %d with rendering/quality/reflections/atlas_subdiv = %d: set it to %d (and atlas_size to %d for the default 512 px a probe)"
		% [count, atlas_slots(subdiv), subdiv, needed, min(8192, 512 * int(sqrt(needed)))])


# A Spatial named "probeproxy_probes" holding one ReflectionProbe per probe with a Godot entry,
# in the file's order, each owned by the root (so PackedScene.pack keeps them). null on error.
# Warns when the project's reflection atlas cannot hold them all (atlas_warning).
static func import_probes(path, interior = true):
	var data = read_json(path)
	if data == null:
		return null
	var root = Spatial.new()
	root.name = "probeproxy_probes"
	for p in data["probes"]:
		var entry = p["engines"]["godot_reflection_probe"]
		if entry == null:
			continue
		var probe = make_probe(p["name"], entry, interior)
		root.add_child(probe)
		probe.owner = root
	var warning = atlas_warning(root.get_child_count())
	if warning != "":
		push_warning(warning)
	return root
