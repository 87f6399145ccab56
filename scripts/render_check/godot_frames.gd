# Godot 3's side of the render check (scripts/render_check.py runs it with godot3-runner under
# xvfb-run, GLES3 on Mesa's llvmpipe, one process per set of probes): per pass, the level with
# position-coded walls, a mirror floor, the ReflectionProbes the shipped importer makes from a
# proxies.json, and one frame per camera, saved as raw half floats (RGBA, rows top down) for
# the check to decode.
#
#   godot3-runner --path DIR -s godot_frames.gd --args SPEC.json
#
# SPEC (written by render_check.py; the level and cameras in Godot's axes, metres): level
# {vertices, triangles}, cameras [{name, eye, target, hfov_deg}], width, height, far, lo and
# size (the coded box, world axes), importer (plugin/engines/godot), out, and passes, each
# {name, pass ("position", "normal", "white" or "code"), code {axis, period} for "code" (a
# world axis), proxies (the proxies.json, absent for the passes without probes)}. Colours are in the world's axes (Z up:
# world (x, y, z) = Godot (x, -z, y)), as EEVEE's frames are, so one decoder reads both.
#
# The probes see the walls and a copy of the floor coded like them (layer 2); the camera sees
# the walls (layer 1) and the mirror floor, an object per metre square (MIRROR_LAYER). No
# environment: the sky and ambient are black. An interior probe captures with no environment
# either, so its cubemap keeps the default clear colour past its far planes: project.godot
# (render_check.py) sets it black, as Godot's grey would decode as a level point, and gives the
# reflection atlas a slot for every probe.
extends SceneTree

const MIRROR_NORMAL_Y = 0.7
const MIRROR_LAYER = 8  # the mirror floor's tiles: the camera's frames only
# Godot 3 updates one UPDATE_ONCE probe at a time, one step a frame (VisualServerScene::
# render_probes: six faces, then a filter step per roughness level), so the frames waited for
# grow with the probes: a third probe was not ready after 40 frames and its floor went black.
const FRAMES_PER_PROBE = 24
const SETTLE_FRAMES = 10


func read_json(path):
	var file = File.new()
	file.open(path, File.READ)
	var parsed = JSON.parse(file.get_as_text())
	file.close()
	return parsed.result


func v3(a):
	return Vector3(a[0], a[1], a[2])


func level_meshes(level, tile):
	# [walls, floor, floor tiles]: the triangles facing up are the floor; the tiles are the
	# floor again, an object per `tile` metres square (by the triangles' centres), for the
	# mirror: Godot 3 shows an object at most 8 of the probes paired with it.
	var walls = SurfaceTool.new()
	var floor_ = SurfaceTool.new()
	var tiles = {}
	walls.begin(Mesh.PRIMITIVE_TRIANGLES)
	floor_.begin(Mesh.PRIMITIVE_TRIANGLES)
	var vs = level["vertices"]
	for t in level["triangles"]:
		var a = v3(vs[t[0]])
		var b = v3(vs[t[1]])
		var c = v3(vs[t[2]])
		var n = (b - a).cross(c - a)
		if n.length() == 0.0:
			continue
		var targets = [walls]
		if n.normalized().y > MIRROR_NORMAL_Y:
			var centre = (a + b + c) / 3.0
			var key = Vector2(floor(centre.x / tile), floor(centre.z / tile))
			if not tiles.has(key):
				tiles[key] = SurfaceTool.new()
				tiles[key].begin(Mesh.PRIMITIVE_TRIANGLES)
			targets = [floor_, tiles[key]]
		for st in targets:
			# Godot winds front faces clockwise: the level's counter-clockwise triangles reversed.
			st.add_normal(n.normalized())
			st.add_vertex(a)
			st.add_normal(n.normalized())
			st.add_vertex(c)
			st.add_normal(n.normalized())
			st.add_vertex(b)
	var tile_meshes = []
	for key in tiles.keys():
		tile_meshes.append(tiles[key].commit())
	return [walls.commit(), floor_.commit(), tile_meshes]


func coded_material(spec, step):
	var colour = "vec3(1.0)"
	if step["pass"] == "position":
		colour = "w - LO"
	elif step["pass"] == "normal":
		colour = "0.5 + 0.5 * vec3(wn.x, -wn.z, wn.y)"
	elif step["pass"] == "code":
		var a = step["code"]["axis"]
		var period = step["code"]["period"]
		colour = ("vec3(1.0 + (w[%d] - LO[%d]) / SIZE[%d], 0.5 + 0.5 * cos(6.283185307 * w[%d] / %.9f), 0.5 + 0.5 * sin(6.283185307 * w[%d] / %.9f))"
			% [a, a, a, a, period, a, period])
	var lo = spec["lo"]
	var size = spec["size"]
	var shader = Shader.new()
	shader.code = ("shader_type spatial; render_mode unshaded, cull_disabled; const vec3 LO = vec3(%.9f, %.9f, %.9f); const vec3 SIZE = vec3(%.9f, %.9f, %.9f); varying vec3 wp; varying vec3 wn; void vertex() { wp = (WORLD_MATRIX * vec4(VERTEX, 1.0)).xyz; wn = normalize((WORLD_MATRIX * vec4(NORMAL, 0.0)).xyz); } void fragment() { vec3 w = vec3(wp.x, -wp.z, wp.y); ALBEDO = %s; }"
		% [lo[0], lo[1], lo[2], size[0], size[1], size[2], colour])
	var material = ShaderMaterial.new()
	material.shader = shader
	return material


func mirror_material():
	var material = SpatialMaterial.new()
	material.albedo_color = Color(1, 1, 1)
	material.metallic = 1.0
	material.roughness = 0.0
	return material


func instance(mesh, material, layers):
	var node = MeshInstance.new()
	node.mesh = mesh
	node.material_override = material
	node.layers = layers
	return node


func see_the_whole_level(camera, vertices, width, height):
	# An orthographic camera over the level's bounds, looking down, its frame holding them all.
	var lo = v3(vertices[0])
	var hi = lo
	for v in vertices:
		var p = v3(v)
		lo = Vector3(min(lo.x, p.x), min(lo.y, p.y), min(lo.z, p.z))
		hi = Vector3(max(hi.x, p.x), max(hi.y, p.y), max(hi.z, p.z))
	var middle = 0.5 * (lo + hi)
	var span = max(hi.x - lo.x, (hi.z - lo.z) * float(width) / float(height)) * 1.1 + 1.0
	var above = hi.y - lo.y + 10.0
	camera.set_orthogonal(span, 0.05, above + 10.0)
	camera.look_at_from_position(Vector3(middle.x, hi.y + 10.0, middle.z), middle, Vector3(0, 0, -1))


func probed_scene(spec, step, meshes, importer):
	# The walls coded for this pass; with probes, the mirror floor the camera sees and the coded
	# floor the probes see.
	var root = Spatial.new()
	var coded = coded_material(spec, step)
	root.add_child(instance(meshes[0], coded, 1 | 2))
	if step.has("proxies"):
		var mirror = mirror_material()
		for tile in meshes[2]:
			root.add_child(instance(tile, mirror, MIRROR_LAYER))
		root.add_child(instance(meshes[1], coded, 2))
		var probes = importer.import_probes(step["proxies"])
		for p in probes.get_children():
			p.cull_mask = 2
			p.update_mode = ReflectionProbe.UPDATE_ONCE
		root.add_child(probes)
	else:
		root.add_child(instance(meshes[1], coded, 1))
	return root


func _init():
	var args = OS.get_cmdline_args()
	var spec = read_json(args[args.size() - 1])
	var meshes = level_meshes(spec["level"], spec["floor_tile"])
	var importer = load(spec["importer"] + "/probeproxy_import.gd")
	get_root().hdr = true
	get_root().keep_3d_linear = true  # the codes as written, no sRGB curve
	get_root().size = Vector2(spec["width"], spec["height"])
	var camera = Camera.new()
	camera.cull_mask = 1
	camera.keep_aspect = Camera.KEEP_WIDTH
	camera.near = 0.05
	camera.far = spec["far"]
	get_root().add_child(camera)
	camera.current = true
	# One process for every pass: each gets a scene of its own, and its probes, made anew, are
	# captured anew.
	for step in spec["passes"]:
		var scene = probed_scene(spec, step, meshes, importer)
		get_root().add_child(scene)
		var probe_count = 0
		if step.has("proxies"):
			probe_count = scene.get_node("probeproxy_probes").get_child_count()
		# Godot 3 queues a probe for its update only while the camera's frustum holds it
		# (VisualServerScene::_prepare_scene), so the probes are made looking down on the whole
		# level.
		# The mirror's thousands of tiles are left out of the frames that only wait.
		see_the_whole_level(camera, spec["level"]["vertices"], spec["width"], spec["height"])
		camera.cull_mask = 1
		for i in range(SETTLE_FRAMES + FRAMES_PER_PROBE * probe_count):
			yield(self, "idle_frame")
		camera.cull_mask = 1 | MIRROR_LAYER
		for c in spec["cameras"]:
			camera.set_perspective(c["hfov_deg"], camera.near, spec["far"])
			camera.look_at_from_position(v3(c["eye"]), v3(c["target"]), Vector3.UP)
			for i in range(3):
				yield(self, "idle_frame")
			var image = get_root().get_texture().get_data()
			image.flip_y()
			image.convert(Image.FORMAT_RGBAH)
			var file = File.new()
			file.open("%s/%s_%s.rgbah" % [spec["out"], c["name"], step["name"]], File.WRITE)
			file.store_buffer(image.get_data())
			file.close()
		get_root().remove_child(scene)
		scene.free()
	quit()
