# Headless: import a proxies.json and save the probes as a scene.
#   godot3-server --no-window -s import_to_scene.gd --args PROXIES_JSON OUT.tscn
extends SceneTree

const Importer = preload("probeproxy_import.gd")


func _init():
	var args = OS.get_cmdline_args()
	var proxies = args[args.size() - 2]
	var out = args[args.size() - 1]
	var root = Importer.import_probes(proxies)
	if root == null:
		quit(2)
		return
	var scene = PackedScene.new()
	if scene.pack(root) != OK or ResourceSaver.save(out, scene) != OK:
		push_error("probeproxy: cannot save " + out)
		quit(2)
		return
	print("probeproxy: %d ReflectionProbe nodes saved to %s" % [root.get_child_count(), out])
	root.free()
	quit(0)
