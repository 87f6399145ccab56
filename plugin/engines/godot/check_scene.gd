# Headless: load a scene saved by import_to_scene.gd and check every ReflectionProbe against the
# proxies.json it came from. Exit 0 when every probe matches, 1 otherwise.
#   godot3-server --no-window -s check_scene.gd --args PROXIES_JSON SCENE.tscn
# Godot 3 stores Vector3 and Transform in 32-bit floats: values match to 2e-7 relative (+1e-6).
extends SceneTree

const Importer = preload("probeproxy_import.gd")

var failures = 0


func close(a, b):
	return abs(a - b) <= 1e-6 + 2e-7 * max(abs(a), abs(b))


func close3(a, b):
	return close(a.x, b.x) and close(a.y, b.y) and close(a.z, b.z)


func expect(ok, what):
	if not ok:
		failures += 1
		printerr("MISMATCH " + what)


func _init():
	var args = OS.get_cmdline_args()
	var data = Importer.read_json(args[args.size() - 2])
	var packed = load(args[args.size() - 1])
	if data == null or packed == null:
		quit(2)
		return
	var root = packed.instance()
	var checked = 0
	for p in data["probes"]:
		var entry = p["engines"]["godot_reflection_probe"]
		var node = root.get_node_or_null(p["name"])
		if entry == null:
			expect(node == null, p["name"] + ": a node for a probe with no Godot entry")
			continue
		expect(node != null and node is ReflectionProbe, p["name"] + ": no ReflectionProbe")
		if node == null:
			continue
		checked += 1
		var n = p["name"]
		var q = entry["rotation_xyzw"]
		var basis = Basis(Quat(q[0], q[1], q[2], q[3]))
		expect(close3(node.transform.origin, Importer.vec3(entry["origin"])), n + ": origin")
		for axis in range(3):
			expect(close3(node.transform.basis[axis], basis[axis]), n + ": basis")
		var extents = Importer.vec3(entry["size"]) / 2.0
		expect(close3(node.extents, extents), n + ": extents %s, size/2 %s" % [node.extents, extents])
		# Godot's clamp (ReflectionProbe::set_origin_offset): the offset as exported where `exact`,
		# moved to 1 cm inside the box where not.
		var offset = Importer.vec3(entry["origin_offset"])
		var moved = false
		for a in range(3):
			if extents[a] - 0.01 < abs(offset[a]):
				offset[a] = sign(offset[a]) * (extents[a] - 0.01)
				moved = true
		expect(moved != entry["exact"], n + ": exact is %s but Godot's clamp moved=%s" % [entry["exact"], moved])
		expect(close3(node.origin_offset, offset), n + ": origin_offset %s, expected %s" % [node.origin_offset, offset])
		var max_distance = entry.get("max_distance", 0.0)
		expect(close(node.max_distance, max_distance), n + ": max_distance %s, expected %s" % [node.max_distance, max_distance])
		expect(node.box_projection == entry["box_projection"], n + ": box_projection")
		expect(node.interior_enable, n + ": interior")
		expect(close(node.get_meta("probeproxy_blend_distance"), entry["blend_distance"]), n + ": blend distance")
		expect(node.get_meta("probeproxy_exact") == entry["exact"], n + ": exact meta")
	expect(root.get_child_count() == checked, "the scene has %d nodes, %d probes checked" % [root.get_child_count(), checked])
	root.free()
	print("probeproxy godot check: %d probes, %d mismatches" % [checked, failures])
	quit(0 if failures == 0 and checked > 0 else 1)
